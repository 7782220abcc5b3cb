#include "CurlNoise.h"

#include <cmath>

#include "Rng.h"  // lowbias32

namespace fx {
namespace {

uint32_t hash3(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    // A 32-bit integer mix (lowbias32-style) of the lattice point: deterministic on every
    // platform, no permutation table to keep in sync with a shader port.
    return lowbias32(seed ^ (static_cast<uint32_t>(x) * 0x8da6b343u) ^
                     (static_cast<uint32_t>(y) * 0xd8163841u) ^ (static_cast<uint32_t>(z) * 0xcb1ab31fu));
}

// The 12 cube-edge directions of improved Perlin noise (no axis is favoured), picked by h's
// low byte.
glm::vec3 latticeGradient(uint32_t h) {
    static const glm::vec3 kDirs[12] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                        {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                        {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
    return kDirs[(h & 0xFFu) % 12u];
}

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
float fadeDeriv(float t) { return 30.0f * t * t * (t * (t - 2.0f) + 1.0f); }

// The lattice cell holding p, shared by the noise and the curl's three potentials: its lowest
// corner, p's position in it and the quintic fade weights (and their derivatives) along each axis.
struct LatticeCell {
    explicit LatticeCell(glm::vec3 p) : i0(glm::floor(p)), f(p - glm::floor(p)) {
        u = glm::vec3(fade(f.x), fade(f.y), fade(f.z));
        du = glm::vec3(fadeDeriv(f.x), fadeDeriv(f.y), fadeDeriv(f.z));
    }
    /// Corner c of 8 as an offset from i0: bit 0 is x, bit 1 y, bit 2 z.
    static glm::ivec3 corner(int c) { return glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); }
    uint32_t cornerHash(int c, uint32_t seed) const {
        const glm::ivec3 o = corner(c);
        return hash3(i0.x + o.x, i0.y + o.y, i0.z + o.z, seed);
    }
    glm::ivec3 i0;
    glm::vec3 f, u, du;
};

constexpr uint32_t kSeeds[1] = {0x68bc21ebu};
// Drift directions per octave (unit, not aligned with the lattice).
const glm::vec3 kDrift[6] = {
    glm::normalize(glm::vec3(0.6f, 0.3f, 0.74f)),  glm::normalize(glm::vec3(-0.7f, 0.2f, 0.5f)),
    glm::normalize(glm::vec3(0.1f, -0.5f, -0.8f)), glm::normalize(glm::vec3(0.8f, 0.45f, -0.3f)),
    glm::normalize(glm::vec3(-0.3f, 0.8f, 0.2f)),  glm::normalize(glm::vec3(0.4f, -0.6f, 0.6f))};

// The gradients of three independent noise potentials at one point, sharing the lattice cell,
// the fade weights and one hash per corner (three gradient picks from its bits): the curl needs
// exactly these, at a third of the cost of three gradientNoise() calls.
void potentialGradients(glm::vec3 p, uint32_t seed, glm::vec3 out[3]) {
    const LatticeCell cell(p);
    const glm::vec3& f = cell.f;
    const glm::vec3& u = cell.u;
    const glm::vec3& du = cell.du;
    // Trilinear weights of the 8 corners and their derivatives along x, y, z.
    float w[8];
    glm::vec3 dw[8];
    for (int c = 0; c < 8; ++c) {
        const float wx = (c & 1) ? u.x : 1.0f - u.x;
        const float wy = (c & 2) ? u.y : 1.0f - u.y;
        const float wz = (c & 4) ? u.z : 1.0f - u.z;
        const float sx = (c & 1) ? du.x : -du.x;
        const float sy = (c & 2) ? du.y : -du.y;
        const float sz = (c & 4) ? du.z : -du.z;
        w[c] = wx * wy * wz;
        dw[c] = glm::vec3(sx * wy * wz, wx * sy * wz, wx * wy * sz);
    }
    out[0] = out[1] = out[2] = glm::vec3(0.0f);
    for (int c = 0; c < 8; ++c) {
        const uint32_t h = cell.cornerHash(c, seed);
        const glm::vec3 r = f - glm::vec3(LatticeCell::corner(c));
        for (int a = 0; a < 3; ++a) {
            const glm::vec3 g = latticeGradient(h >> (8 * a));
            // d/dp [w_c (g . r)] = w_c g + (g . r) dw_c
            out[a] += w[c] * g + glm::dot(g, r) * dw[c];
        }
    }
}

}  // namespace

NoiseSample gradientNoise(glm::vec3 p, uint32_t seed) {
    const LatticeCell cell(p);
    const glm::vec3& u = cell.u;
    const glm::vec3& du = cell.du;

    float n[8];
    glm::vec3 g[8];
    for (int c = 0; c < 8; ++c) {
        g[c] = latticeGradient(cell.cornerHash(c, seed));
        n[c] = glm::dot(g[c], cell.f - glm::vec3(LatticeCell::corner(c)));
    }
    // Trilinear blend with the fade weights, and its derivative (product rule).
    const float k0 = n[0];
    const float k1 = n[1] - n[0];
    const float k2 = n[2] - n[0];
    const float k3 = n[4] - n[0];
    const float k4 = n[0] - n[1] - n[2] + n[3];
    const float k5 = n[0] - n[2] - n[4] + n[6];
    const float k6 = n[0] - n[1] - n[4] + n[5];
    const float k7 = -n[0] + n[1] + n[2] - n[3] + n[4] - n[5] - n[6] + n[7];
    const glm::vec3 g0 = g[0];
    const glm::vec3 g1 = g[1] - g[0];
    const glm::vec3 g2 = g[2] - g[0];
    const glm::vec3 g3 = g[4] - g[0];
    const glm::vec3 g4 = g[0] - g[1] - g[2] + g[3];
    const glm::vec3 g5 = g[0] - g[2] - g[4] + g[6];
    const glm::vec3 g6 = g[0] - g[1] - g[4] + g[5];
    const glm::vec3 g7 = -g[0] + g[1] + g[2] - g[3] + g[4] - g[5] - g[6] + g[7];

    NoiseSample s;
    s.value = k0 + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z +
              k6 * u.z * u.x + k7 * u.x * u.y * u.z;
    s.gradient = g0 + g1 * u.x + g2 * u.y + g3 * u.z + g4 * u.x * u.y + g5 * u.y * u.z +
                 g6 * u.z * u.x + g7 * u.x * u.y * u.z +
                 du * glm::vec3(k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z,
                                k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x,
                                k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y);
    return s;
}

glm::vec3 curlNoise(const TurbulenceDesc& desc, glm::vec3 x, double t) {
    if (!desc.enabled()) return glm::vec3(0.0f);
    const int octaves = glm::clamp(desc.octaves, 1, 6);
    const glm::vec3 p = x / desc.scale;
    // The drift is taken modulo a large lattice period in double, so hours of play keep float
    // precision in the noise argument.
    const double shift = std::fmod(t * static_cast<double>(desc.speed / desc.scale), 4096.0);
    glm::vec3 curl(0.0f);
    float freq = 1.0f, amp = 1.0f, norm = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        const glm::vec3 q = p * freq + static_cast<float>(shift) * kDrift[o];
        glm::vec3 grads[3];
        potentialGradients(q, kSeeds[0] + 101u * o, grads);
        const glm::vec3& gx = grads[0];
        const glm::vec3& gy = grads[1];
        const glm::vec3& gz = grads[2];
        // d/dp of N(freq p) = freq * grad N; amplitude 4^{-o}: velocity falls 2^{-o} per octave.
        const float w = amp * freq;
        curl += w * glm::vec3(gz.y - gy.z, gx.z - gz.x, gy.x - gx.y);
        norm += w;
        freq *= 2.0f;
        amp *= 0.25f;
    }
    return curl * (desc.strength / norm);
}

glm::vec3 vortexVelocity(const VortexDesc& desc, glm::vec3 x, glm::vec3 axis) {
    if (!desc.enabled()) return glm::vec3(0.0f);
    const float dx = x.x - axis.x, dz = x.z - axis.z;
    const float r = std::sqrt(dx * dx + dz * dz);
    if (!(r > 0.0f)) return glm::vec3(0.0f);
    const float R = desc.radius;
    const float speed = r < R ? desc.strength * r / R : desc.strength * R / r;
    // Counter-clockwise seen from above (looking down -Y): +x turns toward -z.
    return glm::vec3(dz, 0.0f, -dx) * (speed / r);
}

}  // namespace fx
