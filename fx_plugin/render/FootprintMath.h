#pragma once
// The per-particle screen-bound arithmetic shared by screenRect (ScreenTiles.cpp) and the tiled
// path's binning (TileBins.cpp): a particle's footprint projected to pixels, and the tile runs
// the full-screen passes draw. Private to those two files.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "ScreenTiles.h"

namespace fx {
namespace footprint {

// NDC to pixels.
inline float toPixel(float ndc, int size) { return (ndc * 0.5f + 0.5f) * float(size); }

// Appends the pixel rectangle [x0, x1) x [y0, y1) as two triangles.
inline void addRun(ScreenTiles* tiles, int x0, int y0, int x1, int y1) {
    const float a = float(x0), b = float(x1), c = float(y0), d = float(y1);
    const float v[12] = {a, c, b, c, b, d, a, c, b, d, a, d};
    tiles->vertices.insert(tiles->vertices.end(), v, v + 12);
    tiles->pixels += int64_t(x1 - x0) * (y1 - y0);
}

// The projection's shape: a perspective one (glm::perspective, glm::frustum, an infinite or
// reversed-Z far plane: clip.w = -z, x and y not mixed) lets a footprint's screen bound come from
// its centre's two extreme depths instead of projecting eight corners. Any other projection
// (orthographic, skewed) takes the general path.
inline bool plainPerspective(const glm::mat4& p) {
    return p[0][1] == 0.0f && p[1][0] == 0.0f && p[0][3] == 0.0f && p[1][3] == 0.0f && p[2][3] == -1.0f &&
           p[3][3] == 0.0f && p[0][0] > 0.0f && p[1][1] > 0.0f;
}

// One particle's footprint on screen, in pixels ([x0, x1] x [y0, y1], unclipped), or why there
// is none; box: its quad's (what footprintPixels counts), the same unless a billboard's reach
// bounds it tighter.
struct Bounds {
    enum State : int { Bounded, Behind, Unbounded };
    float x0, x1, y0, y1;
    int state;
    float box[4];  // x0, x1, y0, y1
};


constexpr float kQuadReach = 0.71f;  // a quad's corners from its centre, in sizes (sqrt(2) / 2, up)

// The per-particle arithmetic of screenRect, for one view and footprint kind.
struct FootprintMath {
    glm::mat4 V, P;
    float nearPlane;
    int w, h;
    bool flat;
    const BillboardReach* reach;  // flat footprints under a perspective projection; null: quads
    float reachOfSize;            // the footprint's half-size in sizes: kQuadReach, or 0.5 for a sphere alone
    FootprintMath(const ViewInfo& view, bool flatFootprint, const BillboardReach* billboardReach,
                  float halfSize = kQuadReach)
        : V(view.view), P(view.proj), nearPlane(view.nearPlane), w(view.width), h(view.height), flat(flatFootprint),
          reach(flatFootprint && billboardReach && billboardReach->lodScale > 0.0f ? billboardReach : nullptr),
          reachOfSize(halfSize) {}

    glm::vec3 centre(const ParticleInstance& p) const {
        return glm::vec3(V[0][0] * p.x + V[1][0] * p.y + V[2][0] * p.z + V[3][0],
                         V[0][1] * p.x + V[1][1] * p.y + V[2][1] * p.z + V[3][1],
                         V[0][2] * p.x + V[1][2] * p.y + V[2][2] * p.z + V[3][2]);
    }
    // Non-finite (no bound to trust) or reaching the near plane: Unbounded; wholly behind it:
    // Behind. A billboard lies in the view plane through its centre: no depth extent.
    int state(const glm::vec3& c, float radius, float depthExtent) const {
        const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(radius);
        if (!finite) return Bounds::Unbounded;
        if (c.z - depthExtent >= -nearPlane) return Bounds::Behind;
        return c.z + depthExtent >= -nearPlane ? Bounds::Unbounded : Bounds::Bounded;
    }
    Bounds pixels(const float plo[2], const float phi[2], int state) const {
        const float x0 = toPixel(plo[0], w), x1 = toPixel(phi[0], w), y0 = toPixel(plo[1], h), y1 = toPixel(phi[1], h);
        return Bounds{x0, x1, y0, y1, state, {x0, x1, y0, y1}};
    }

    // Under a perspective projection (plainPerspective): ndc.x = (P00 x + P30) / -z - P20, monotone
    // in x and in 1/-z, so the extremes lie at the corners (x +- r, z +- e) and two reciprocals
    // bound all eight (y likewise); a billboard has one depth, one reciprocal.
    template <bool Flat>
    Bounds perspective(const ParticleInstance& p) const {
        const glm::vec3 c = centre(p);
        const float radius = reachOfSize * p.size;
        const float depthExtent = Flat ? 0.0f : radius;
        const float nearInv = 1.0f / -(c.z + depthExtent), farInv = Flat ? nearInv : 1.0f / -(c.z - depthExtent);
        float plo[2], phi[2];
        for (int a = 0; a < 2; ++a) {
            const float lowEdge = P[a][a] * (c[a] - radius) + P[3][a];
            const float highEdge = P[a][a] * (c[a] + radius) + P[3][a];
            if (Flat) {
                plo[a] = lowEdge * nearInv - P[2][a];
                phi[a] = highEdge * nearInv - P[2][a];
            } else {
                plo[a] = std::min(lowEdge * nearInv, lowEdge * farInv) - P[2][a];
                phi[a] = std::max(highEdge * nearInv, highEdge * farInv) - P[2][a];
            }
        }
        Bounds b = pixels(plo, phi, state(c, radius, depthExtent));
        if (Flat && reach) {
            // The trimmed polygon of the LOD bucket the vertex shader picks (BillboardReach), of
            // radius `tight`: the same projection, about the same centre.
            const float depth = std::max(-c.z, nearPlane);
            const float tight = reach->at(p.frame, reach->lodScale * depth / std::max(p.size, 1e-6f)) * p.size;
            for (int a = 0; a < 2; ++a) {
                plo[a] = (P[a][a] * (c[a] - tight) + P[3][a]) * nearInv - P[2][a];
                phi[a] = (P[a][a] * (c[a] + tight) + P[3][a]) * nearInv - P[2][a];
            }
            b.x0 = toPixel(plo[0], w);
            b.x1 = toPixel(phi[0], w);
            b.y0 = toPixel(plo[1], h);
            b.y1 = toPixel(phi[1], h);
        }
        return b;
    }

    // Any other projection: the footprint's corners (8, or 4 for a flat square) projected.
    Bounds general(const ParticleInstance& p) const {
        const glm::vec3 c = centre(p);
        const float radius = reachOfSize * p.size;
        const float depthExtent = flat ? 0.0f : radius;
        const int st = state(c, radius, depthExtent);
        float plo[2] = {1e30f, 1e30f}, phi[2] = {-1e30f, -1e30f};
        if (st == Bounds::Bounded) {
            const int corners = depthExtent > 0.0f ? 8 : 4;
            for (int corner = 0; corner < corners; ++corner) {
                const glm::vec3 q = c + glm::vec3(corner & 1 ? radius : -radius, corner & 2 ? radius : -radius,
                                                  corner & 4 ? depthExtent : -depthExtent);
                const glm::vec4 clip = P * glm::vec4(q, 1.0f);
                for (int a = 0; a < 2; ++a) {
                    const float ndc = clip[a] / clip.w;
                    plo[a] = std::min(plo[a], ndc);
                    phi[a] = std::max(phi[a], ndc);
                }
            }
        }
        return pixels(plo, phi, st);
    }
};

// Marks the tiles [tx0, tx1] x [ty0, ty1] in the (tilesX + 1) x (tilesY + 1) difference grid: four
// writes whatever the particle's size; a prefix sum over the grid turns them into each tile's count
// (ScreenTiles' runs, TileBins' counts).
inline void markTiles(int32_t* grid, int tilesX, int tx0, int tx1, int ty0, int ty1) {
    const size_t stride = size_t(tilesX) + 1;
    grid[size_t(ty0) * stride + size_t(tx0)] += 1;
    grid[size_t(ty0) * stride + size_t(tx1) + 1] -= 1;
    grid[(size_t(ty1) + 1) * stride + size_t(tx0)] -= 1;
    grid[(size_t(ty1) + 1) * stride + size_t(tx1) + 1] += 1;
}

}  // namespace footprint
}  // namespace fx
