// make_assets: trackside furniture around the race track (data/README.md). All small, flat
// shaded boxes, cones and cylinders. Only the guard rails are solid (extras.solid): the rest
// stands where the scripted drive never goes and takes part in no collision query.

#include "make_assets.h"

#include <cmath>
#include <string>

namespace assets {
namespace {

// A left-side guard rail (armco) from x0 to x1 at z: posts every 4 m and a 0.3 m band.
MeshData guardRail(float x0, float x1, float z) {
    MeshData m;
    for (float x = x0; x <= x1 + 1e-3f; x += 4.0f) m.box({x - 0.05f, 0.0f, z - 0.05f}, {x + 0.05f, 0.72f, z + 0.05f});
    m.box({x0, 0.42f, z + 0.05f}, {x1, 0.72f, z + 0.10f}, true);
    return m;
}

// A board of w x h metres with its lower edge `lift` above the ground, on two legs, facing +Z
// (or -X when `facesMinusX`); the panel and the legs go into separate meshes.
void board(MeshData* panel, MeshData* legs, vec3 at, float w, float h, float lift, bool facesMinusX) {
    const vec3 across = facesMinusX ? vec3(0, 0, 1) : vec3(1, 0, 0);
    const vec3 depth = facesMinusX ? vec3(1, 0, 0) : vec3(0, 0, 1);
    const vec3 lo = at - 0.5f * w * across - 0.04f * depth + vec3(0, lift, 0);
    const vec3 hi = at + 0.5f * w * across + 0.04f * depth + vec3(0, lift + h, 0);
    panel->box(glm::min(lo, hi), glm::max(lo, hi), true);
    for (float s : {-0.4f, 0.4f}) {
        const vec3 c = at + s * w * across + 0.1f * depth;
        legs->box(c - vec3(0.04f, 0.0f, 0.04f), c + vec3(0.04f, lift + 0.3f * h, 0.04f));
    }
}

}  // namespace

void buildTrackside(GltfBuilder& b, std::vector<int>* roots) {

    // Debris fence on the right wall (barrier_right, x in [-150,150], z in [8.5,9], 1 m tall):
    // posts every 5 m and two rails, up to 2.3 m. Not solid: the wall below is.
    MeshData fence;
    for (float x = -150.0f; x <= 150.0f; x += 5.0f) fence.box({x - 0.04f, 1.0f, 8.71f}, {x + 0.04f, 2.3f, 8.79f});
    for (float y : {1.6f, 2.25f}) fence.box({-150.0f, y, 8.72f}, {150.0f, y + 0.05f, 8.78f}, true);
    roots->push_back(b.node("fence_right", b.mesh("fence_right", {{fence, kSteel}}), vec3(0)));

    // Guard rails on the left, behind the tyre walls, leaving the run-off and the gravel trap.
    const float rails[][2] = {{-150.0f, -26.0f}, {26.0f, 56.0f}, {122.0f, 150.0f}};
    for (size_t i = 0; i < std::size(rails); ++i) {
        roots->push_back(b.node("barrier_left_" + std::to_string(i),
                                b.mesh("barrier_left_" + std::to_string(i),
                                       {{guardRail(rails[i][0], rails[i][1], -9.5f), kSteel}}),
                                vec3(0), solidTag()));
    }

    // Marshal posts behind the right wall: a white hut with an orange band and a flag pole.
    MeshData hut, band, pole;
    hut.box({-0.8f, 0.0f, -0.7f}, {0.8f, 2.2f, 0.7f});
    band.box({-0.85f, 2.2f, -0.75f}, {0.85f, 2.45f, 0.75f}, true);
    pole.box({0.6f, 2.45f, -0.5f}, {0.66f, 4.0f, -0.44f});
    MeshData flag;
    flag.box({0.66f, 3.4f, -0.49f}, {1.3f, 3.95f, -0.45f}, true);
    const int post = b.mesh("marshal_post", {{hut, kPaintWhite}, {band, kPaintOrange}, {pole, kSteel}, {flag, kPaintYellow}});
    const float postsX[] = {-80.0f, -35.0f, 55.0f, 100.0f};
    for (size_t i = 0; i < std::size(postsX); ++i)
        roots->push_back(b.node("marshal_post_" + std::to_string(i), post, {postsX[i], 0.0f, 11.5f}));

    // Advertising boards along the left, facing the track, in three colours.
    MeshData boardPanels[3], boardLegs;
    const float boardsX[] = {-130.0f, -110.0f, -90.0f, -70.0f, 34.0f, 130.0f};
    for (size_t i = 0; i < std::size(boardsX); ++i)
        board(&boardPanels[i % 3], &boardLegs, {boardsX[i], 0.0f, -11.0f}, 6.0f, 1.3f, 0.5f, false);
    roots->push_back(b.node("boards", b.mesh("boards", {{boardPanels[0], kPaintYellow}, {boardPanels[1], kPaintRed},
                                                        {boardPanels[2], kPaintWhite}, {boardLegs, kSteel}}),
                            vec3(0)));

    // Braking boards before the burnout zone: 3, 2, 1 dark bars on white, facing the cars (-X).
    MeshData markers, bars, markerLegs;
    for (int n = 3; n >= 1; --n) {
        const float x = -20.0f - 10.0f * float(n);
        board(&markers, &markerLegs, {x, 0.0f, -8.2f}, 0.9f, 0.9f, 0.5f, true);
        for (int k = 0; k < n; ++k) {
            const float y = 0.5f + 0.9f * float(k + 1) / float(n + 1);
            bars.box({x - 0.06f, y - 0.06f, -8.55f}, {x - 0.04f, y + 0.06f, -7.85f}, true);
        }
    }
    roots->push_back(b.node("braking_boards",
                            b.mesh("braking_boards", {{markers, kPaintWhite}, {bars, kPanelDark}, {markerLegs, kSteel}}),
                            vec3(0)));

    // A small grandstand behind the right wall: five tiers, rows of seats, a roof on six posts.
    MeshData tiers, seats, roof;
    for (int k = 0; k < 5; ++k) {
        const float z0 = 13.0f + 1.4f * float(k), y1 = 0.6f + 0.5f * float(k);
        tiers.box({-12.0f, 0.0f, z0}, {28.0f, y1, 21.0f});
        seats.box({-11.5f, y1, z0 + 0.5f}, {27.5f, y1 + 0.35f, z0 + 0.95f});
    }
    tiers.box({-12.0f, 0.0f, 21.0f}, {28.0f, 5.0f, 21.4f});  // back wall
    for (float x : {-11.6f, 8.0f, 27.6f})
        for (float z : {13.2f, 21.0f})  // front posts 5.6 m, back posts 6.0 m: under the sloping roof
            tiers.box({x - 0.15f, 0.0f, z - 0.15f}, {x + 0.15f, z < 20.0f ? 5.6f : 6.0f, z + 0.15f});
    // The roof slopes up toward the back (z = 12.4 -> 21.8), 0.2 m thick.
    const vec3 slab[8] = {{-12.5f, 5.6f, 12.4f}, {28.5f, 5.6f, 12.4f}, {28.5f, 5.8f, 12.4f}, {-12.5f, 5.8f, 12.4f},
                          {-12.5f, 6.0f, 21.8f}, {28.5f, 6.0f, 21.8f}, {28.5f, 6.2f, 21.8f}, {-12.5f, 6.2f, 21.8f}};
    roof.hexa(slab);
    roots->push_back(b.node(
        "grandstand", b.mesh("grandstand", {{tiers, kStandConcrete}, {seats, kStandSeats}, {roof, kPaintWhite}}), vec3(0)));

    // A start gantry across the track at x = 45: two posts, a beam, a dark panel with red lights.
    MeshData frame, panel, lights;
    for (float z : {-8.6f, 9.6f}) frame.box({44.75f, 0.0f, z - 0.25f}, {45.25f, 6.2f, z + 0.25f});
    frame.box({44.7f, 5.3f, -8.6f}, {45.3f, 6.2f, 9.6f}, true);
    panel.box({44.6f, 4.3f, -3.0f}, {44.7f, 5.3f, 3.0f}, true);
    for (int k = 0; k < 5; ++k) {
        const float z = -2.2f + 1.1f * float(k);
        lights.box({44.55f, 4.6f, z - 0.2f}, {44.6f, 5.0f, z + 0.2f}, true);
    }
    roots->push_back(
        b.node("gantry", b.mesh("gantry", {{frame, kSteel}, {panel, kPanelDark}, {lights, kPaintRed}}), vec3(0)));

    // Cones along the left kerb at the exit of the run-off: orange with a white band.
    MeshData cone, coneBand;
    cone.frustum({0, 0, 0}, 0.16f, 0.09f, 0.30f, 12);
    coneBand.frustum({0, 0.30f, 0}, 0.09f, 0.075f, 0.08f, 12);
    cone.frustum({0, 0.38f, 0}, 0.075f, 0.0f, 0.14f, 12);
    const int coneMesh = b.mesh("cone", {{cone, kPaintOrange}, {coneBand, kPaintWhite}});
    for (int k = 0; k < 6; ++k)
        roots->push_back(b.node("cone_" + std::to_string(k), coneMesh, {24.0f + 2.5f * float(k), 0.0f, -7.5f}));
}

}  // namespace assets
