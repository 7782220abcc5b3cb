#include "ScreenTiles.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/PrivateGl.h"

namespace fx {
namespace {

constexpr int kTileSize = ScreenTiles::kTileSize, kTileBorder = ScreenTiles::kTileBorder;

// NDC to pixels.
float toPixel(float ndc, int size) { return (ndc * 0.5f + 0.5f) * float(size); }

// Appends the pixel rectangle [x0, x1) x [y0, y1) as two triangles.
void addRun(ScreenTiles* tiles, int x0, int y0, int x1, int y1) {
    const float a = float(x0), b = float(x1), c = float(y0), d = float(y1);
    const float v[12] = {a, c, b, c, b, d, a, c, b, d, a, d};
    tiles->vertices.insert(tiles->vertices.end(), v, v + 12);
    tiles->pixels += int64_t(x1 - x0) * (y1 - y0);
}

// The projection's shape: a perspective one (glm::perspective, glm::frustum, an infinite or
// reversed-Z far plane: clip.w = -z, x and y not mixed) lets a footprint's screen bound come from
// its centre's two extreme depths instead of projecting eight corners. Any other projection
// (orthographic, skewed) takes the general path.
bool plainPerspective(const glm::mat4& p) {
    return p[0][1] == 0.0f && p[1][0] == 0.0f && p[0][3] == 0.0f && p[1][3] == 0.0f && p[2][3] == -1.0f &&
           p[3][3] == 0.0f && p[0][0] > 0.0f && p[1][1] > 0.0f;
}

// Marks the tiles [tx0, tx1] x [ty0, ty1] in the (tilesX + 1) x (tilesY + 1) difference grid: four
// writes whatever the particle's size; the prefix sum in tileRuns() turns them into coverage.
void markTiles(int32_t* grid, int tilesX, int tx0, int tx1, int ty0, int ty1) {
    const int stride = tilesX + 1;
    grid[size_t(ty0 * stride + tx0)] += 1;
    grid[size_t(ty0 * stride + tx1 + 1)] -= 1;
    grid[size_t((ty1 + 1) * stride + tx0)] -= 1;
    grid[size_t((ty1 + 1) * stride + tx1 + 1)] += 1;
}

// The difference grid summed into coverage, row by row, as horizontal runs of covered tiles.
void tileRuns(ScreenTiles* tiles, int tilesX, int tilesY, int w, int h) {
    const int stride = tilesX + 1;
    std::vector<int32_t>& g = tiles->grid;
    for (int ty = 0; ty < tilesY; ++ty) {
        int32_t* row = g.data() + ty * stride;
        if (ty > 0) {
            const int32_t* above = row - stride;
            for (int tx = 0; tx < stride; ++tx) row[tx] += above[tx];  // column sums so far
        }
        int32_t run = 0;  // the row's running sum: the coverage of tile tx
        for (int tx = 0; tx < tilesX;) {
            run += row[tx];
            if (run <= 0) {
                ++tx;
                continue;
            }
            int end = tx + 1;
            int32_t next = run;
            while (end < tilesX && (next += row[end]) > 0) ++end;
            addRun(tiles, tx * kTileSize, ty * kTileSize, std::min(w, end * kTileSize), std::min(h, (ty + 1) * kTileSize));
            run = next;  // the coverage of tile `end` (0 or less), or past the row's end
            tx = end + 1;
        }
    }
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
constexpr int kChunk = 256;

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

// What one piece of the particles adds to the bound: its rect, its boxes' pixels, its tiles
// (marked in `grid`), or that it has no bound at all.
struct PieceBound {
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};  // in pixels (toPixel is monotone)
    double boxPixels = 0.0;
    bool any = false, unbounded = false;
};

PieceBound boundPiece(const FootprintMath& math, const ViewInfo& view, bool flat, const ParticleInstance* instances,
                      size_t begin, size_t end, int32_t* grid, int tilesX, int tilesY) {
    PieceBound r;
    const int w = view.width, h = view.height;
    const glm::mat4& P = view.proj;
    double boxPixels = 0.0;  // summed in a register
    Bounds b[kChunk];
    for (size_t first = begin; first < end; first += kChunk) {
        const int n = int(std::min<size_t>(kChunk, end - first));
        // The arithmetic first, for a chunk at a time, with no branch on the particle; then what
        // each bound means, in order.
        if (!plainPerspective(P)) {
            for (int j = 0; j < n; ++j) b[j] = math.general(instances[first + j]);
        } else if (flat) {
            for (int j = 0; j < n; ++j) b[j] = math.perspective<true>(instances[first + j]);
        } else {
            for (int j = 0; j < n; ++j) b[j] = math.perspective<false>(instances[first + j]);
        }
        for (int j = 0; j < n; ++j) {
            const Bounds& q = b[j];
            if (q.state == Bounds::Unbounded) {  // no bound to trust, or at the near plane
                r.unbounded = true;
                return r;
            }
            if (q.state == Bounds::Behind) continue;  // wholly behind the near plane: clipped
            r.lo[0] = std::min(r.lo[0], q.x0);
            r.lo[1] = std::min(r.lo[1], q.y0);
            r.hi[0] = std::max(r.hi[0], q.x1);
            r.hi[1] = std::max(r.hi[1], q.y1);
            r.any = true;
            const float cx0 = std::max(0.0f, q.box[0]), cx1 = std::min(float(w), q.box[1]);
            const float cy0 = std::max(0.0f, q.box[2]), cy1 = std::min(float(h), q.box[3]);
            if (cx1 > cx0 && cy1 > cy0) boxPixels += double(cx1 - cx0) * double(cy1 - cy0);
            if (!grid || tilesX <= 0 || tilesY <= 0) continue;
            // The particle's pixels grown by the border, as a tile range clamped to the view (the
            // float clamp first: a bound far off screen must not overflow the int; clamped to 0
            // and up, truncation is the floor).
            auto tileOf = [](float pixel, int border, int tileCount) {
                const float t = (pixel + float(border)) * (1.0f / float(kTileSize));  // exact: a power of two
                return int(std::min(std::max(t, 0.0f), float(tileCount - 1)));
            };
            if (q.x1 < -kTileBorder || q.y1 < -kTileBorder || q.x0 > w + kTileBorder || q.y0 > h + kTileBorder) continue;
            markTiles(grid, tilesX, tileOf(q.x0, -kTileBorder, tilesX), tileOf(q.x1, kTileBorder, tilesX),
                      tileOf(q.y0, -kTileBorder, tilesY), tileOf(q.y1, kTileBorder, tilesY));
        }
    }
    r.boxPixels = boxPixels;
    return r;
}

}  // namespace

BillboardReach BillboardReach::of(const TrimmedShapes& shapes, float lodScale) {
    BillboardReach r;
    if (shapes.empty()) return r;
    r.lodScale = lodScale;
    r.buckets = shapes.buckets();
    const int last = r.buckets - 1;
    for (int b = 0; b < kEntries; ++b) {
        float any = 0.0f;
        for (int f = 0; f < TrimmedShapes::kFrames; ++f) {
            float most = 0.0f;
            for (int k = std::max(b - 1, 0); k <= std::min(b + 1, last); ++k) most = std::max(most, 0.5f * shapes.reach(f, k));
            most = std::min(most, kQuadReach);  // a polygon lies inside its quad
            r.table[size_t(f * kEntries + b)] = most;
            any = std::max(any, most);
        }
        r.table[size_t(TrimmedShapes::kFrames * kEntries + b)] = any;
    }
    return r;
}

ScreenRect screenRect(const ViewInfo& view, const ParticleInstance* instances, int count, ScreenTiles* tiles,
                      Footprint footprint, const Jobs& jobs, const BillboardReach* reach) {
    ScreenRect r;
    const int w = view.width, h = view.height;
    const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
    // Pieces of at least 16k particles (about 0.2 ms each), each with its own difference grid
    // (the first piece's is tiles->grid): at most 16, so the grids stay small beside the work.
    const Pieces pieces = splitWork(size_t(std::max(count, 0)), 16384, 16);
    const size_t gridCells = size_t(std::max(0, (tilesX + 1) * (tilesY + 1)));
    if (tiles) {
        tiles->vertices.clear();
        tiles->pixels = 0;
        tiles->viewWidth = w;
        tiles->viewHeight = h;
        tiles->grid.assign(gridCells, 0);
        if (pieces.count > 1) tiles->pieceGrids.resize(gridCells * (pieces.count - 1));
    }
    auto wholeView = [&]() {
        if (tiles && w > 0 && h > 0) {
            tiles->vertices.clear();
            tiles->pixels = 0;
            addRun(tiles, 0, 0, w, h);
        }
        r.footprintPixels = std::numeric_limits<double>::infinity();  // unbounded: the near plane, or no bound
        return r;  // whole = true
    };
    const FootprintMath math(view, footprint == Footprint::Billboard, reach);
    PieceBound parts[HostAdapter::kMaxTasks];
    jobs.run(pieces, [&](uint32_t piece) {
        int32_t* grid = nullptr;
        if (tiles) {
            grid = piece == 0 ? tiles->grid.data() : tiles->pieceGrids.data() + gridCells * (piece - 1);
            std::fill(grid, grid + gridCells, 0);
        }
        parts[piece] = boundPiece(math, view, footprint == Footprint::Billboard, instances, pieces.begin(piece),
                                  pieces.end(piece), grid, tilesX, tilesY);
    });
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    double boxPixels = 0.0;
    bool any = false;
    for (uint32_t s = 0; s < pieces.count; ++s) {  // in order: the sum does not depend on the threads
        const PieceBound& q = parts[s];
        if (q.unbounded) return wholeView();
        lo[0] = std::min(lo[0], q.lo[0]);
        lo[1] = std::min(lo[1], q.lo[1]);
        hi[0] = std::max(hi[0], q.hi[0]);
        hi[1] = std::max(hi[1], q.hi[1]);
        boxPixels += q.boxPixels;
        any = any || q.any;
    }
    if (tiles) {
        for (uint32_t s = 1; s < pieces.count; ++s) {
            const int32_t* add = tiles->pieceGrids.data() + gridCells * (s - 1);
            for (size_t c = 0; c < gridCells; ++c) tiles->grid[c] += add[c];
        }
    }
    r.footprintPixels = boxPixels;
    if (!any) {
        r.whole = false;  // nothing in front of the camera: an empty rect, no tiles
        return r;
    }
    // One pixel of slack for rasterisation rules, clamped to the view.
    r.x0 = std::max(0, int(std::floor(lo[0])) - 1);
    r.y0 = std::max(0, int(std::floor(lo[1])) - 1);
    r.x1 = std::min(w, int(std::ceil(hi[0])) + 1);
    r.y1 = std::min(h, int(std::ceil(hi[1])) + 1);
    if (r.x1 <= r.x0 || r.y1 <= r.y0) {
        r.x0 = r.x1 = r.y0 = r.y1 = 0;
        r.whole = false;
        return r;  // no tiles either: every bound was off screen
    }
    r.whole = r.x0 == 0 && r.y0 == 0 && r.x1 == w && r.y1 == h;
    if (tiles) tileRuns(tiles, tilesX, tilesY, w, h);
    return r;
}

bool binParticles(const ViewInfo& view, const ParticleInstance* instances, const TileBins::Range* batches,
                  int batchCount, const BillboardReach* reach, TileBins* out, const Jobs& jobs) {
    const int w = view.width, h = view.height;
    const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
    out->entries.clear();
    out->tiles.clear();
    out->cover.vertices.clear();
    out->cover.pixels = 0;
    out->cover.viewWidth = w;
    out->cover.viewHeight = h;
    if (batchCount > (1 << (32 - TileBins::kBatchShift))) return false;
    if (tilesX <= 0 || tilesY <= 0) return true;  // an empty view: no tiles
    int top = 0;
    for (int b = 0; b < batchCount; ++b) top = std::max(top, batches[b].first + batches[b].count);
    if (top >= (1 << TileBins::kBatchShift)) return false;
    // Front-to-back order k: the last batch's last particle first. orderStart[j]: the first k of
    // the j-th batch from the back.
    int orderStart[(1 << (32 - TileBins::kBatchShift)) + 1];
    int n = 0;
    for (int j = 0; j < batchCount; ++j) {
        orderStart[j] = n;
        n += std::max(batches[batchCount - 1 - j].count, 0);
    }
    orderStart[batchCount] = n;
    // Walks k over [k0, k1) with its entry (instance | batch << kBatchShift).
    auto walk = [&](size_t k0, size_t k1, auto&& f) {
        int j = 0;
        while (j < batchCount && size_t(orderStart[j + 1]) <= k0) ++j;
        for (size_t k = k0; k < k1; ++k) {
            while (size_t(orderStart[j + 1]) <= k) ++j;
            const int b = batchCount - 1 - j;
            const int i = batches[b].first + batches[b].count - 1 - (int(k) - orderStart[j]);
            f(k, i, uint32_t(i) | (uint32_t(b) << TileBins::kBatchShift));
        }
    };
    const int tileCount = tilesX * tilesY;
    const FootprintMath flat(view, true, reach), box(view, false, nullptr, 0.5f);
    const bool perspective = plainPerspective(view.proj);
    out->ranges.resize(size_t(n) * 4);
    out->weights.resize(size_t(n));

    // 1. Each particle's tile range (empty where it is clipped or off the view) and its tile count,
    // in pieces of the particles.
    const Pieces boundPieces = splitWork(size_t(n), 8192, 16);
    bool failed[HostAdapter::kMaxTasks] = {};
    jobs.run(boundPieces, [&](uint32_t piece) {
        walk(boundPieces.begin(piece), boundPieces.end(piece), [&](size_t k, int i, uint32_t entry) {
            const bool sphere = batches[entry >> TileBins::kBatchShift].sphere;
            const FootprintMath& math = sphere ? box : flat;
            const ParticleInstance& p = instances[i];
            const Bounds q = !perspective ? math.general(p) : sphere ? math.perspective<false>(p) : math.perspective<true>(p);
            int32_t* r = &out->ranges[k * 4];
            r[0] = 0;
            r[1] = -1;  // empty
            r[2] = 0;
            r[3] = -1;
            out->weights[k] = 0;
            if (q.state == Bounds::Unbounded) {
                if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.size))) {
                    failed[piece] = true;
                    return;
                }
                // A sphere across the near plane (a billboard has one depth: never): every tile.
                r[1] = tilesX - 1;
                r[3] = tilesY - 1;
                out->weights[k] = uint32_t(tileCount);
                return;
            }
            if (q.state == Bounds::Behind || q.x1 < -1.0f || q.y1 < -1.0f || q.x0 > float(w) + 1.0f ||
                q.y0 > float(h) + 1.0f) {
                return;
            }
            auto tileOf = [](float pixel, int tiles) {
                const float t = pixel * (1.0f / float(kTileSize));
                return int(std::min(std::max(t, 0.0f), float(tiles - 1)));
            };
            r[0] = tileOf(q.x0 - 1.0f, tilesX);
            r[1] = tileOf(q.x1 + 1.0f, tilesX);
            r[2] = tileOf(q.y0 - 1.0f, tilesY);
            r[3] = tileOf(q.y1 + 1.0f, tilesY);
            out->weights[k] = uint32_t((r[1] - r[0] + 1) * (r[3] - r[2] + 1));
        });
    });
    for (uint32_t piece = 0; piece < boundPieces.count; ++piece) {
        if (failed[piece]) return false;
    }

    // 2. Bands of tile rows, each counted and filled by one piece: a band owns its tiles' counts
    // and its stretch of the entries (no two threads write one cache line), and reads every
    // particle's range (cheap beside its entries). As many bands as the entries pay for.
    uint64_t entries = 0;
    for (int k = 0; k < n; ++k) entries += out->weights[size_t(k)];
    const Pieces bands = splitWork(size_t(tilesY), 1, uint32_t(std::min<uint64_t>(std::max<uint64_t>(entries / 32768, 1), 16)));
    out->counts.assign(size_t(tileCount), 0);
    int32_t* counts = out->counts.data();
    jobs.run(bands, [&](uint32_t band) {
        const int y0 = int(bands.begin(band)), y1 = int(bands.end(band)) - 1;
        for (int k = 0; k < n; ++k) {
            const int32_t* r = &out->ranges[size_t(k) * 4];
            for (int ty = std::max(r[2], y0); ty <= std::min(r[3], y1); ++ty) {
                for (int tx = r[0]; tx <= r[1]; ++tx) ++counts[ty * tilesX + tx];
            }
        }
    });
    // 3. Each tile's first entry (its cursor from now on), the tiles with particles and their runs
    // for the composite.
    int32_t sum = 0;
    for (int ty = 0; ty < tilesY; ++ty) {
        int runStart = -1;
        for (int tx = 0; tx <= tilesX; ++tx) {
            const int32_t tileEntries = tx < tilesX ? counts[ty * tilesX + tx] : 0;
            if (tileEntries > 0) {
                out->tiles.insert(out->tiles.end(), {uint32_t(tx), uint32_t(ty), uint32_t(sum), uint32_t(tileEntries)});
                counts[ty * tilesX + tx] = sum;
                sum += tileEntries;
                if (runStart < 0) runStart = tx;
            } else if (runStart >= 0) {
                addRun(&out->cover, runStart * kTileSize, ty * kTileSize, std::min(w, tx * kTileSize),
                       std::min(h, (ty + 1) * kTileSize));
                runStart = -1;
            }
        }
    }
    // 4. The entries, front to back (k order), each band into its own tiles.
    out->entries.resize(size_t(sum));
    jobs.run(bands, [&](uint32_t band) {
        const int y0 = int(bands.begin(band)), y1 = int(bands.end(band)) - 1;
        uint32_t* entriesOut = out->entries.data();
        walk(0, size_t(n), [&](size_t k, int, uint32_t entry) {
            const int32_t* r = &out->ranges[k * 4];
            for (int ty = std::max(r[2], y0); ty <= std::min(r[3], y1); ++ty) {
                for (int tx = r[0]; tx <= r[1]; ++tx) entriesOut[counts[ty * tilesX + tx]++] = entry;
            }
        });
    });
    return true;
}

bool quarterResPays(const ScreenRect& rect, const ScreenTiles& tiles) {
    if (tiles.pixels <= 0) return false;  // nothing on screen: no pass either way
    return rect.footprintPixels >= kQuarterResMinOverdraw * double(tiles.pixels);
}

HostClip HostClip::current() {
    HostClip c;
    c.on = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
    if (c.on) glGetIntegerv(GL_SCISSOR_BOX, c.box);
    return c;
}

void HostClip::apply() const {
    if (!on) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(box[0], box[1], box[2], box[3]);
}

void scissorToView(const ScreenRect& rect, int border, const ViewInfo& view, const HostClip& clip) {
    if (rect.whole && !clip.on) {
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    int x0 = view.x, y0 = view.y, x1 = view.x + view.width, y1 = view.y + view.height;
    if (!rect.whole) {
        x0 = std::max(x0, view.x + rect.x0 - border);
        y0 = std::max(y0, view.y + rect.y0 - border);
        x1 = std::min(x1, view.x + rect.x1 + border);
        y1 = std::min(y1, view.y + rect.y1 + border);
    }
    if (clip.on) {
        x0 = std::max(x0, clip.box[0]);
        y0 = std::max(y0, clip.box[1]);
        x1 = std::min(x1, clip.box[0] + clip.box[2]);
        y1 = std::min(y1, clip.box[1] + clip.box[3]);
    }
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

void scissorTo(const ScreenRect& rect, float scale, int border, int w, int h) {
    if (rect.whole) {
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    const int x0 = std::max(0, int(std::floor(float(rect.x0) * scale)) - border);
    const int y0 = std::max(0, int(std::floor(float(rect.y0) * scale)) - border);
    const int x1 = std::min(w, int(std::ceil(float(rect.x1) * scale)) + border);
    const int y1 = std::min(h, int(std::ceil(float(rect.y1) * scale)) + border);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

}  // namespace fx
