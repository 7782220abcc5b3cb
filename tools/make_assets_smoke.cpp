// The smoke atlas: 2x2 cells of soft smoke puffs in one RGBA8 PNG.
//
// Each 256x256 cell is a different puff: fBm value noise (own integer hash, fixed seeds, so the
// bytes never change) warps a radial falloff. RGB is a white-grey smoke colour everywhere (also
// where alpha is 0, so bilinear filtering never pulls in black); alpha is the density, straight
// (not premultiplied): the particle shader multiplies colour by alpha itself. Alpha is exactly 0
// on every cell border, so neighbouring puffs never bleed into each other.

#include <stb_image_write.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr int kCell = 256;
constexpr int kCells = 2;  // per side
constexpr int kSize = kCell * kCells;

uint32_t hash(int32_t x, int32_t y, uint32_t seed) {
    // lowbias32 (Wellons) over a mix of the lattice point and the seed.
    uint32_t h = seed ^ (uint32_t(x) * 0x8da6b343u) ^ (uint32_t(y) * 0xd8163841u);
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
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
    return true;
}
