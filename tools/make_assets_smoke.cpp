// The smoke atlas: 2x2 cells of soft smoke puffs in one RGBA8 PNG.
//
// Each 256x256 cell is a different puff: fBm value noise (own integer hash, fixed seeds, so the
// bytes never change) warps a radial falloff. RGB is a white-grey smoke colour everywhere (also
// where alpha is 0, so bilinear filtering never pulls in black); alpha is the density, straight
// (not premultiplied): the particle shader multiplies colour by alpha itself. Alpha is exactly 0
// on every cell border, so neighbouring puffs never bleed into each other.
// Beside it, smoke_normals.png: the same puffs' normals for lit smoke (writeSmokeNormals).

#include <stb_image_write.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "../fx_plugin/sim/Rng.h"  // fx::lowbias32

namespace {

constexpr int kCell = 256;
constexpr int kCells = 2;  // per side
constexpr int kSize = kCell * kCells;

uint32_t hash(int32_t x, int32_t y, uint32_t seed) {
    // lowbias32 (Wellons) over a mix of the lattice point and the seed.
    return fx::lowbias32(seed ^ (uint32_t(x) * 0x8da6b343u) ^ (uint32_t(y) * 0xd8163841u));
}

float lattice(int32_t x, int32_t y, uint32_t seed) {
    return float(hash(x, y, seed) >> 8) / 16777216.0f;
}

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// Value noise in [0, 1).
float valueNoise(glm::vec2 p, uint32_t seed) {
    const glm::vec2 i = glm::floor(p);
    const glm::vec2 f = p - i;
    const int32_t x = int32_t(i.x), y = int32_t(i.y);
    const float u = fade(f.x), v = fade(f.y);
    const float a = lattice(x, y, seed), b = lattice(x + 1, y, seed);
    const float c = lattice(x, y + 1, seed), d = lattice(x + 1, y + 1, seed);
    return glm::mix(glm::mix(a, b, u), glm::mix(c, d, u), v);
}

// Five octaves, gain 0.5, normalised back to [0, 1).
float fbm(glm::vec2 p, uint32_t seed) {
    float sum = 0.0f, amp = 0.5f, norm = 0.0f;
    for (int o = 0; o < 5; ++o) {
        sum += amp * valueNoise(p, seed + uint32_t(o) * 1013u);
        norm += amp;
        p = p * 2.0f + glm::vec2(17.3f, 5.9f);
        amp *= 0.5f;
    }
    return sum / norm;
}

struct PuffParams {
    uint32_t seed;
    float frequency;  // lumps across the cell
    float warp;       // how far noise pushes the outline in and out
    float core;       // radius where density starts to fall off
};

const PuffParams kPuffs[kCells * kCells] = {
    {0xC0BE5EEDu, 3.0f, 0.50f, 0.20f},
    {0x5A0CE001u, 4.0f, 0.60f, 0.15f},
    {0x0DDBA11u, 2.5f, 0.45f, 0.25f},
    {0xFEEDF00Du, 5.0f, 0.70f, 0.10f},
};

uint8_t toByte(float v) { return uint8_t(std::lround(glm::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// A signed component in [-1, 1] as 128 + round(127 v): 0 is exactly 128, so a zero normal
// (where the puff is empty) decodes to exactly zero ((byte - 128) / 127).
uint8_t toSignedByte(float v) { return uint8_t(128 + std::lround(glm::clamp(v, -1.0f, 1.0f) * 127.0f)); }

// The normal atlas from the density field (the alpha bytes). Each puff is lit as a lumpy dome:
// height = a dome over the cell (the puff's bulk) plus the smoothed density (its lumps); the
// normal is the height field's, in particle space (x right, y up, z toward the viewer). Zero
// where alpha is 0, unit length elsewhere. RGB = the signed normal, A = the height (0 outside).
bool writeSmokeNormals(const std::string& path, const std::vector<uint8_t>& rgba) {
    std::vector<float> height(size_t(kSize) * kSize, 0.0f);
    auto alphaAt = [&](int x, int y) {
        x = glm::clamp(x, 0, kSize - 1);
        y = glm::clamp(y, 0, kSize - 1);
        return float(rgba[(size_t(y) * kSize + size_t(x)) * 4 + 3]) / 255.0f;
    };
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            // 5x5 box of density (softens the 8-bit steps before differentiating).
            float sum = 0.0f;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) sum += alphaAt(x + dx, y + dy);
            const glm::vec2 q = (glm::vec2(float(x % kCell), float(y % kCell)) + 0.5f) / float(kCell) * 2.0f - 1.0f;
            // The dome spans the puff (radius 0.85 of the half cell), not the whole cell.
            const float dome = std::sqrt(glm::max(0.0f, 1.0f - glm::dot(q, q) / (0.85f * 0.85f)));
            height[size_t(y) * kSize + size_t(x)] = 0.8f * dome + 0.35f * sum / 25.0f;
        }
    }
    std::vector<uint8_t> out(size_t(kSize) * kSize * 4);
    const float slope = float(kCell) / 2.0f;  // d(height)/d(texel) -> d(height)/d(q), q in [-1, 1]
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            uint8_t* px = &out[(size_t(y) * kSize + size_t(x)) * 4];
            if (rgba[(size_t(y) * kSize + size_t(x)) * 4 + 3] == 0) {
                px[0] = px[1] = px[2] = 128;
                px[3] = 0;
                continue;
            }
            // Central differences inside the cell (image y grows downward: flip to +y up).
            const int cx = x / kCell * kCell, cy = y / kCell * kCell;
            const int x0 = glm::max(x - 1, cx), x1 = glm::min(x + 1, cx + kCell - 1);
            const int y0 = glm::max(y - 1, cy), y1 = glm::min(y + 1, cy + kCell - 1);
            const float dhdx = (height[size_t(y) * kSize + size_t(x1)] - height[size_t(y) * kSize + size_t(x0)]) /
                               float(x1 - x0);
            const float dhdy = -(height[size_t(y1) * kSize + size_t(x)] - height[size_t(y0) * kSize + size_t(x)]) /
                               float(y1 - y0);
            const glm::vec3 n = glm::normalize(glm::vec3(-dhdx * slope, -dhdy * slope, 1.0f));
            px[0] = toSignedByte(n.x);
            px[1] = toSignedByte(n.y);
            px[2] = toSignedByte(n.z);
            px[3] = toByte(height[size_t(y) * kSize + size_t(x)]);
        }
    }
    if (!stbi_write_png(path.c_str(), kSize, kSize, 4, out.data(), kSize * 4)) {
        std::fprintf(stderr, "make_assets: cannot write %s\n", path.c_str());
        return false;
    }
    return true;
}

}  // namespace

bool writeSmokeAtlas(const std::string& path) {
    std::vector<uint8_t> rgba(size_t(kSize) * kSize * 4);
    for (int cy = 0; cy < kCells; ++cy) {
        for (int cx = 0; cx < kCells; ++cx) {
            const PuffParams& puff = kPuffs[cy * kCells + cx];
            for (int y = 0; y < kCell; ++y) {
                for (int x = 0; x < kCell; ++x) {
                    const glm::vec2 p((float(x) + 0.5f) / kCell,
                                      (float(y) + 0.5f) / kCell);  // [0,1]^2
                    const glm::vec2 q = p * 2.0f - 1.0f;           // [-1,1]^2
                    const float shapeNoise = fbm(p * puff.frequency, puff.seed);
                    const float detail = fbm(p * puff.frequency * 2.3f, puff.seed ^ 0x5bd1e995u);
                    const float r = glm::length(q) + (shapeNoise - 0.5f) * puff.warp;
                    const float body = 1.0f - glm::smoothstep(puff.core, 0.85f, r);
                    // Window that forces alpha to exactly 0 before the cell border, whatever the
                    // warp did.
                    const float border =
                        1.0f -
                        glm::smoothstep(0.80f, 0.97f, glm::max(std::fabs(q.x), std::fabs(q.y)));
                    const float density =
                        glm::clamp(body * border * (0.45f + 0.75f * detail), 0.0f, 1.0f);
                    // White-grey: a little darker where dense, a little lighter towards the top.
                    const float grey =
                        0.93f + 0.08f * (detail - 0.5f) - 0.12f * density - 0.03f * q.y;
                    uint8_t* px =
                        &rgba[(size_t(cy * kCell + y) * kSize + size_t(cx * kCell + x)) * 4];
                    px[0] = px[1] = px[2] = toByte(grey);
                    px[3] = toByte(density);
                }
            }
        }
    }
    stbi_write_png_compression_level = 9;
    if (!stbi_write_png(path.c_str(), kSize, kSize, 4, rgba.data(), kSize * 4)) {
        std::fprintf(stderr, "make_assets: cannot write %s\n", path.c_str());
        return false;
    }
    // smoke_normals.png next to it (lit smoke).
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
    return writeSmokeNormals(dir + "smoke_normals.png", rgba);
}
