// make_assets: the race car. Forward +X, right +Z, wheels on the ground (y = 0); the "car" root
// stays at the origin (the game moves it and spins the wheel nodes about their axles, +Z).
//
// What makes it read as a car from the chase camera and from the side: a hull narrower than the
// wheel track between the wheels (the four wheels stand clear of it), flared arches over them,
// side sills, a tapered nose and tail, a cabin with a raked windscreen and separate glass panels,
// lights and a rear wing; wheels are a tyre and a five-spoke rim (two materials), so their
// rotation shows.

#include "make_assets.h"

#include <cmath>

namespace assets {
namespace {

// Wheel stations (data/README.md): hubs at x = +-1.35, z = +-0.8, radius 0.33, 0.25 wide.
constexpr float kAxleX = 1.35f, kTrackZ = 0.8f, kWheelR = 0.33f, kWheelHalfW = 0.125f;
constexpr float kHullZ = 0.64f;  // hull half width: clear of the wheels' inner faces (0.675)

// A block whose -X end is (yLo0..yHi0, +-z0) and +X end (yLo1..yHi1, +-z1); z taken as the
// half width at the bottom, `tuck` narrower at the top (tumblehome).
void taperedBlock(MeshData* m, float x0, float x1, float yLo0, float yHi0, float yLo1, float yHi1, float z0,
                  float z1, float tuck, bool bottom = true) {
    const vec3 c[8] = {{x0, yLo0, -z0},         {x1, yLo1, -z1},         {x1, yHi1, -(z1 - tuck)},
                       {x0, yHi0, -(z0 - tuck)}, {x0, yLo0, z0},          {x1, yLo1, z1},
                       {x1, yHi1, z1 - tuck},    {x0, yHi0, z0 - tuck}};
    m->hexa(c, bottom);
}

// A point on a quad face by (u, v) in [0,1]^2 (bilinear), pushed `lift` along `n`.
vec3 onFace(const vec3 f[4], float u, float v, vec3 n, float lift) {
    const vec3 bottom = glm::mix(f[0], f[1], u), top = glm::mix(f[3], f[2], u);
    return glm::mix(bottom, top, v) + lift * n;
}

// A window: the part [u0,u1] x [v0,v1] of face f (f[0], f[1] along the bottom; f[3], f[2] the top
// edge above them), 6 mm proud of the face so it never fights the shell for depth.
void window(MeshData* glass, const vec3 f[4], float u0, float u1, float v0, float v1) {
    vec3 n = glm::normalize(glm::cross(f[2] - f[0], f[3] - f[1]));
    vec3 c = 0.25f * (f[0] + f[1] + f[2] + f[3]);
    if (glm::dot(n, c - vec3(-0.45f, 0.85f, 0.0f)) < 0.0f) n = -n;  // away from the cabin's middle
    glass->quad(onFace(f, u0, v0, n, 0.006f), onFace(f, u1, v0, n, 0.006f), onFace(f, u1, v1, n, 0.006f),
                onFace(f, u0, v1, n, 0.006f), n);
}

// The wheel around its hub at the origin, axle along Z: a tyre (tread and sidewalls) on a dark
// dish, and a rim ring, hub and five spokes on both faces (the same wheel serves both sides).
std::pair<MeshData, MeshData> wheelGeometry() {
    MeshData tyre, rim;
    tyre.tubeArc(vec3(0), 0.235f, kWheelR, -kWheelHalfW, kWheelHalfW, 0.0f, 2.0f * kPi, 24);
    tyre.cylinder(vec3(0), {0, 0, 1}, 0.236f, 0.14f, 24);  // the dish behind the spokes
    rim.tubeArc(vec3(0), 0.205f, 0.237f, -0.11f, 0.11f, 0.0f, 2.0f * kPi, 24);
    rim.cylinder(vec3(0), {0, 0, 1}, 0.06f, 0.22f, 10);
    for (float side : {-1.0f, 1.0f}) {
        for (int k = 0; k < 5; ++k) {
            const float a = 2.0f * kPi * float(k) / 5.0f;
            const vec3 d(std::cos(a), std::sin(a), 0.0f), s(-d.y, d.x, 0.0f);
            const float z0 = side * 0.07f, z1 = side * 0.10f, w0 = 0.03f, w1 = 0.02f;
            const vec3 c[8] = {0.05f * d - w0 * s + vec3(0, 0, std::min(z0, z1)),
                               0.21f * d - w1 * s + vec3(0, 0, std::min(z0, z1)),
                               0.21f * d + w1 * s + vec3(0, 0, std::min(z0, z1)),
                               0.05f * d + w0 * s + vec3(0, 0, std::min(z0, z1)),
                               0.05f * d - w0 * s + vec3(0, 0, std::max(z0, z1)),
                               0.21f * d - w1 * s + vec3(0, 0, std::max(z0, z1)),
                               0.21f * d + w1 * s + vec3(0, 0, std::max(z0, z1)),
                               0.05f * d + w0 * s + vec3(0, 0, std::max(z0, z1))};
            rim.hexa(c);
        }
    }
    return {tyre, rim};
}

}  // namespace

int buildCar(GltfBuilder& b) {

    // ---- body: hull, nose, tail, sills, arches (paint); splitter, diffuser, wing (trim) ----
    MeshData paint, trim, head, tail;
    taperedBlock(&paint, -1.75f, 1.75f, 0.16f, 0.66f, 0.16f, 0.66f, kHullZ, kHullZ, 0.04f);      // hull
    taperedBlock(&paint, 1.75f, 2.30f, 0.16f, 0.66f, 0.18f, 0.40f, kHullZ, 0.52f, 0.04f);        // nose
    taperedBlock(&paint, -2.20f, -1.75f, 0.20f, 0.70f, 0.16f, 0.66f, 0.60f, kHullZ, 0.04f);      // tail
    for (float s : {-1.0f, 1.0f}) {
        // Sills between the wheels, out to the full 1.8 m width.
        const float zi = s * 0.55f, zo = s * 0.90f, zt = s * 0.86f;
        const vec3 sill[8] = {{-0.95f, 0.20f, std::min(zi, zo)}, {0.95f, 0.20f, std::min(zi, zo)},
                              {0.85f, 0.56f, std::min(zi, zt)},  {-0.85f, 0.56f, std::min(zi, zt)},
                              {-0.95f, 0.20f, std::max(zi, zo)}, {0.95f, 0.20f, std::max(zi, zo)},
                              {0.85f, 0.56f, std::max(zi, zt)},  {-0.85f, 0.56f, std::max(zi, zt)}};
        paint.hexa(sill);
        // Flared arches: the upper half of a ring 4 to 11 cm outside the tyre.
        for (float x : {-kAxleX, kAxleX}) {
            const float z0 = s > 0 ? 0.58f : -0.93f, z1 = s > 0 ? 0.93f : -0.58f;
            paint.tubeArc({x, kWheelR, 0.0f}, kWheelR + 0.04f, kWheelR + 0.11f, z0, z1, 0.0f, kPi, 9);
        }
        head.box({2.22f, 0.28f, s > 0 ? 0.26f : -0.48f}, {2.315f, 0.36f, s > 0 ? 0.48f : -0.26f});
        tail.box({-2.215f, 0.52f, s > 0 ? 0.32f : -0.54f}, {-2.15f, 0.62f, s > 0 ? 0.54f : -0.32f});
        trim.box({-2.12f, 0.66f, s * 0.45f - 0.03f}, {-2.02f, 0.93f, s * 0.45f + 0.03f});  // wing post
    }
    trim.box({2.02f, 0.12f, -0.58f}, {2.40f, 0.18f, 0.58f}, true);    // front splitter
    trim.box({-2.26f, 0.12f, -0.50f}, {-1.95f, 0.24f, 0.50f}, true);  // rear diffuser
    const vec3 wing[8] = {{-2.30f, 0.93f, -0.80f}, {-1.98f, 0.95f, -0.80f}, {-1.98f, 0.98f, -0.80f},
                          {-2.30f, 1.00f, -0.80f}, {-2.30f, 0.93f, 0.80f},  {-1.98f, 0.95f, 0.80f},
                          {-1.98f, 0.98f, 0.80f},  {-2.30f, 1.00f, 0.80f}};
    trim.hexa(wing);
    const int car = b.node("car", -1, vec3(0));
    b.child(car, b.node("car_body",
                        b.mesh("car_body", {{paint, kCarPaint}, {trim, kCarTrim}, {head, kCarHeadlight},
                                            {tail, kCarTaillight}}),
                        vec3(0)));

    // ---- cabin: a shell with a raked screen and tumblehome (paint), glass panels on it ----
    // Corners: bottom at y = 0.66 from x = -1.30 to 0.70, 1.20 wide; roof at 1.12 from -0.95 to
    // 0.05, 0.96 wide.
    const vec3 cab[8] = {{-1.30f, 0.66f, -0.60f}, {0.70f, 0.66f, -0.60f}, {0.05f, 1.12f, -0.48f},
                         {-0.95f, 1.12f, -0.48f}, {-1.30f, 0.66f, 0.60f}, {0.70f, 0.66f, 0.60f},
                         {0.05f, 1.12f, 0.48f},   {-0.95f, 1.12f, 0.48f}};
    MeshData shell, glass;
    shell.hexa(cab, false);
    const vec3 screen[4] = {cab[1], cab[5], cab[6], cab[2]}, rear[4] = {cab[4], cab[0], cab[3], cab[7]};
    const vec3 left[4] = {cab[0], cab[1], cab[2], cab[3]}, right[4] = {cab[5], cab[4], cab[7], cab[6]};
    window(&glass, screen, 0.07f, 0.93f, 0.08f, 0.90f);
    window(&glass, rear, 0.10f, 0.90f, 0.14f, 0.86f);
    // Side windows: a front and a rear pane each side, split by the B pillar.
    for (const vec3* side : {left, right}) {
        const bool mirrored = side == right;  // u runs rear to front on the left, front to rear on the right
        window(&glass, side, mirrored ? 0.14f : 0.50f, mirrored ? 0.50f : 0.86f, 0.14f, 0.86f);
        window(&glass, side, mirrored ? 0.54f : 0.14f, mirrored ? 0.86f : 0.46f, 0.14f, 0.86f);
    }
    b.child(car, b.node("car_cabin", b.mesh("car_cabin", {{shell, kCarPaint}, {glass, kCarGlass}}), vec3(0)));

    // ---- wheels: one mesh, a node per corner with its hub at the node's origin ----
    const auto [tyre, rim] = wheelGeometry();
    const int wheel = b.mesh("wheel", {{tyre, kWheelRubber}, {rim, kWheelRim}});
    const std::pair<const char*, vec3> wheels[] = {{"wheel_FL", {kAxleX, kWheelR, -kTrackZ}},
                                                   {"wheel_FR", {kAxleX, kWheelR, kTrackZ}},
                                                   {"wheel_RL", {-kAxleX, kWheelR, -kTrackZ}},
                                                   {"wheel_RR", {-kAxleX, kWheelR, kTrackZ}}};
    for (const auto& [name, at] : wheels) b.child(car, b.node(name, wheel, at));
    return car;
}

}  // namespace assets
