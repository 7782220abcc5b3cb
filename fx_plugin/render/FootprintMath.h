#pragma once
// The per-particle screen-bound arithmetic shared by screenRect (ScreenTiles.cpp) and the tiled
// path's binning (TileBins.cpp): a particle's footprint projected to pixels, and the tile runs
// the full-screen passes draw. Private to those two files (and ScreenTilesTest, which holds the
// four-lane path to the one-lane one).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "ScreenTiles.h"

#include "base/Sse2.h"

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

#if FX_SSE2
    // perspective<Flat> of four particles, a particle a lane: the pixels (tight: the trimmed
    // polygon's where a reach table applies, else the quad's, as `box`) and, as four-bit masks,
    // which lanes are not finite, wholly behind the near plane or reaching it (state(): in that
    // order of precedence).
    struct Lanes {
        __m128 x0, x1, y0, y1;
        __m128 box[4];
        int notFinite, behind, reaching;
        int state(int lane) const {
            const int bit = 1 << lane;
            return notFinite & bit ? Bounds::Unbounded
                   : behind & bit  ? Bounds::Behind
                   : reaching & bit ? Bounds::Unbounded
                                    : Bounds::Bounded;
        }
    };

    // The same operations as perspective<Flat> in the same order, lane by lane (x86-64 has no
    // fused multiply-add without -mfma, so neither side contracts), negation as a sign flip,
    // std::min(a, b) as _mm_min_ps(b, a) and std::max(a, b) as _mm_max_ps(b, a) (the same operand
    // returned for equal values and NaN): the same bits as four calls (ScreenTilesTest's
    // FourAtATime... test). What it saves: the divisions and the products four at a time.
    template <bool Flat>
    FX_LANES_INLINE Lanes perspectiveLanes(const ParticleInstance* p) const {
        __m128 px = _mm_loadu_ps(&p[0].x), py = _mm_loadu_ps(&p[1].x), pz = _mm_loadu_ps(&p[2].x),
               ps = _mm_loadu_ps(&p[3].x);
        _MM_TRANSPOSE4_PS(px, py, pz, ps);  // now x, y, z and size of the four
        const __m128 sign = _mm_set1_ps(-0.0f);
        auto neg = [&](__m128 v) { return _mm_xor_ps(v, sign); };
        auto row = [&](int r) {  // centre(): ((V0r x + V1r y) + V2r z) + V3r
            return _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(V[0][r]), px), _mm_mul_ps(_mm_set1_ps(V[1][r]), py)),
                                         _mm_mul_ps(_mm_set1_ps(V[2][r]), pz)),
                              _mm_set1_ps(V[3][r]));
        };
        const __m128 c[3] = {row(0), row(1), row(2)};
        const __m128 radius = _mm_mul_ps(_mm_set1_ps(reachOfSize), ps);
        const __m128 depthExtent = Flat ? _mm_setzero_ps() : radius;
        const __m128 one = _mm_set1_ps(1.0f);
        const __m128 nearInv = _mm_div_ps(one, neg(_mm_add_ps(c[2], depthExtent)));
        const __m128 farInv = Flat ? nearInv : _mm_div_ps(one, neg(_mm_sub_ps(c[2], depthExtent)));
        const __m128 half = _mm_set1_ps(0.5f), width = _mm_set1_ps(float(w)), height = _mm_set1_ps(float(h));
        auto toPixels = [&](__m128 ndc, __m128 size) { return _mm_mul_ps(_mm_add_ps(_mm_mul_ps(ndc, half), half), size); };
        Lanes out;
        for (int a = 0; a < 2; ++a) {
            const __m128 scale = _mm_set1_ps(P[a][a]), shift = _mm_set1_ps(P[3][a]), offset = _mm_set1_ps(P[2][a]);
            const __m128 lowEdge = _mm_add_ps(_mm_mul_ps(scale, _mm_sub_ps(c[a], radius)), shift);
            const __m128 highEdge = _mm_add_ps(_mm_mul_ps(scale, _mm_add_ps(c[a], radius)), shift);
            __m128 lo, hi;
            if (Flat) {
                lo = _mm_sub_ps(_mm_mul_ps(lowEdge, nearInv), offset);
                hi = _mm_sub_ps(_mm_mul_ps(highEdge, nearInv), offset);
            } else {
                lo = _mm_sub_ps(_mm_min_ps(_mm_mul_ps(lowEdge, farInv), _mm_mul_ps(lowEdge, nearInv)), offset);
                hi = _mm_sub_ps(_mm_max_ps(_mm_mul_ps(highEdge, farInv), _mm_mul_ps(highEdge, nearInv)), offset);
            }
            out.box[a * 2] = toPixels(lo, a == 0 ? width : height);
            out.box[a * 2 + 1] = toPixels(hi, a == 0 ? width : height);
        }
        // state(): not finite (exponent all ones) -> Unbounded; behind; reaching the near plane.
        const __m128i exponent = _mm_set1_epi32(0x7f800000);
        auto infinite = [&](__m128 v) { return _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(v), exponent), exponent); };
        out.notFinite = _mm_movemask_ps(_mm_castsi128_ps(
            _mm_or_si128(_mm_or_si128(infinite(c[0]), infinite(c[1])), _mm_or_si128(infinite(c[2]), infinite(radius)))));
        const __m128 nearZ = neg(_mm_set1_ps(nearPlane));
        out.behind = _mm_movemask_ps(_mm_cmpge_ps(_mm_sub_ps(c[2], depthExtent), nearZ));
        out.reaching = _mm_movemask_ps(_mm_cmpge_ps(_mm_add_ps(c[2], depthExtent), nearZ));
        if (!(Flat && reach)) {
            out.x0 = out.box[0];
            out.x1 = out.box[1];
            out.y0 = out.box[2];
            out.y1 = out.box[3];
            return out;
        }
        // The trimmed polygon's reach: the table lookup a lane at a time, the rest four at once.
        const __m128 depth = _mm_max_ps(_mm_set1_ps(nearPlane), neg(c[2]));
        const __m128 texels = _mm_div_ps(_mm_mul_ps(_mm_set1_ps(reach->lodScale), depth), _mm_max_ps(_mm_set1_ps(1e-6f), ps));
        alignas(16) float t[4];
        _mm_store_ps(t, texels);
        // Into a register lane by lane: four scalar stores read back as one vector would stall the
        // load (no store forwarding; a sixth of the bound's time in perf).
        const __m128 reachOf = _mm_setr_ps(reach->at(p[0].frame, t[0]), reach->at(p[1].frame, t[1]),
                                           reach->at(p[2].frame, t[2]), reach->at(p[3].frame, t[3]));
        const __m128 tightRadius = _mm_mul_ps(reachOf, ps);
        __m128 tight[4];
        for (int a = 0; a < 2; ++a) {
            const __m128 scale = _mm_set1_ps(P[a][a]), shift = _mm_set1_ps(P[3][a]), offset = _mm_set1_ps(P[2][a]);
            const __m128 size = a == 0 ? width : height;
            const __m128 l = _mm_sub_ps(_mm_mul_ps(_mm_add_ps(_mm_mul_ps(scale, _mm_sub_ps(c[a], tightRadius)), shift), nearInv), offset);
            const __m128 u = _mm_sub_ps(_mm_mul_ps(_mm_add_ps(_mm_mul_ps(scale, _mm_add_ps(c[a], tightRadius)), shift), nearInv), offset);
            tight[a * 2] = toPixels(l, size);
            tight[a * 2 + 1] = toPixels(u, size);
        }
        out.x0 = tight[0];
        out.x1 = tight[1];
        out.y0 = tight[2];
        out.y1 = tight[3];
        return out;
    }

#endif

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

// The kTileSize tiles a bound grown by `border` pixels touches, clamped to the view's tilesX x
// tilesY: the tiled path's bins (TileBins.cpp, a pixel) and screenRect's tiles (kTileBorder).
// Range: r = tx0, tx1, ty0, ty1; None: wholly behind the near plane or more than `border` pixels
// off the view; Unbounded: no bound (the caller decides: a sphere across the near plane is in
// every tile, a particle that is not finite fails the view).
struct TileRangeOf {
    enum What : uint8_t { None, Range, Unbounded };
    int w, h, tilesX, tilesY, border;

    static int tileOf(float pixel, int tiles) {
        // The float clamp first: a bound far off screen must not overflow the int; clamped to 0
        // and up, truncation is the floor.
        const float t = pixel * (1.0f / float(ScreenTiles::kTileSize));  // exact: a power of two
        return int(std::min(std::max(t, 0.0f), float(tiles - 1)));
    }
    uint8_t operator()(const Bounds& q, int32_t* r) const {
        if (q.state == Bounds::Unbounded) return Unbounded;
        const float b = float(border);
        if (q.state == Bounds::Behind || q.x1 < -b || q.y1 < -b || q.x0 > float(w + border) || q.y0 > float(h + border)) {
            return None;
        }
        r[0] = tileOf(q.x0 - b, tilesX);
        r[1] = tileOf(q.x1 + b, tilesX);
        r[2] = tileOf(q.y0 - b, tilesY);
        r[3] = tileOf(q.y1 + b, tilesY);
        return Range;
    }
#if FX_SSE2
    // The same for four lanes (FootprintMath::perspectiveLanes), the same bits: std::max(t, 0) as
    // _mm_max_ps(0, t), std::min(t, last) as _mm_min_ps(last, t), truncation as _mm_cvttps_epi32.
    FX_LANES_INLINE void operator()(const FootprintMath::Lanes& q, int32_t (*r)[4], uint8_t* what) const {
        const __m128 grow = _mm_set1_ps(float(border)), zero = _mm_setzero_ps();
        const __m128 inv = _mm_set1_ps(1.0f / float(ScreenTiles::kTileSize));
        const __m128 lastX = _mm_set1_ps(float(tilesX - 1)), lastY = _mm_set1_ps(float(tilesY - 1));
        auto tiles = [&](__m128 pixel, __m128 last) {
            return _mm_castsi128_ps(_mm_cvttps_epi32(_mm_min_ps(last, _mm_max_ps(zero, _mm_mul_ps(pixel, inv)))));
        };
        __m128 r0 = tiles(_mm_sub_ps(q.x0, grow), lastX), r1 = tiles(_mm_add_ps(q.x1, grow), lastX);
        __m128 r2 = tiles(_mm_sub_ps(q.y0, grow), lastY), r3 = tiles(_mm_add_ps(q.y1, grow), lastY);
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);  // a lane's four tiles per register
        const __m128 before = _mm_set1_ps(-float(border));
        const int off = _mm_movemask_ps(_mm_or_ps(
            _mm_or_ps(_mm_cmplt_ps(q.x1, before), _mm_cmplt_ps(q.y1, before)),
            _mm_or_ps(_mm_cmpgt_ps(q.x0, _mm_set1_ps(float(w + border))), _mm_cmpgt_ps(q.y0, _mm_set1_ps(float(h + border))))));
        const __m128 lanes[4] = {r0, r1, r2, r3};
        for (int k = 0; k < 4; ++k) {
            const int state = q.state(k);
            what[k] = state == Bounds::Unbounded ? Unbounded : state == Bounds::Behind || (off >> k & 1) ? None : Range;
            _mm_storeu_ps(reinterpret_cast<float*>(r[k]), lanes[k]);
        }
    }
#endif
};

// Adds `otherCount` grids (each `cells` long, one after another from `others`) into `into`, in
// bands of cells on the host's threads (a band per 2,048 cells, up to 16): with 16 pieces at
// 1080p that is 15 grids of 8,349 cells, which one thread would add up alone. Integers: the
// same sums in any order.
inline void addGrids(int32_t* into, const int32_t* others, size_t cells, uint32_t otherCount, const Jobs& jobs) {
    if (otherCount == 0) return;
    const Pieces bands = splitWork(cells, 2048, 16);
    jobs.run(bands, [&](uint32_t band) {
        const size_t first = bands.begin(band), n = bands.end(band) - first;
        for (uint32_t g = 0; g < otherCount; ++g) {
            const int32_t* from = others + size_t(g) * cells + first;
            for (size_t c = 0; c < n; ++c) into[first + c] += from[c];
        }
    });
}

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
