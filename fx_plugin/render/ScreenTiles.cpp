#include "ScreenTiles.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/PrivateGl.h"

#include "FootprintMath.h"

namespace fx {
namespace {

using namespace footprint;

constexpr int kTileSize = ScreenTiles::kTileSize, kTileBorder = ScreenTiles::kTileBorder;

// The tiles any mark can lie in: every particle's range is inside the range of the union of
// their bounds (TileRangeOf is monotone), so rows above by0 and columns left of bx0 hold no mark
// and the grid's sums start there; the marks reach row by1 + 1 and column bx1 + 1.
struct TileBox {
    int bx0 = 0, bx1 = -1, by0 = 0, by1 = -1;
};

// The difference grid summed into coverage, row by row, as horizontal runs of covered tiles,
// inside `box` (outside it every tile's coverage is 0). The column sums go four cells at a time.
void tileRuns(ScreenTiles* tiles, int tilesX, const TileBox& box, int w, int h) {
    const int stride = tilesX + 1;
    int32_t* g = tiles->grid.data();
    for (int ty = box.by0; ty <= box.by1; ++ty) {
        int32_t* row = g + ty * stride;
        if (ty > box.by0) {
            const int32_t* above = row - stride;
            int tx = box.bx0;
#if FX_SSE2
            for (; tx + 4 <= box.bx1 + 1; tx += 4) {  // column sums so far; integers, any grouping
                const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above + tx));
                const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + tx));
                _mm_storeu_si128(reinterpret_cast<__m128i*>(row + tx), _mm_add_epi32(a, b));
            }
#endif
            for (; tx <= box.bx1; ++tx) row[tx] += above[tx];
        }
        int32_t run = 0;  // the row's running sum: the coverage of tile tx
        for (int tx = box.bx0; tx <= box.bx1;) {
            run += row[tx];
            if (run <= 0) {
                ++tx;
                continue;
            }
            int end = tx + 1;
            int32_t next = run;
            while (end <= box.bx1 && (next += row[end]) > 0) ++end;
            addRun(tiles, tx * kTileSize, ty * kTileSize, std::min(w, end * kTileSize), std::min(h, (ty + 1) * kTileSize));
            run = next;  // the coverage of tile `end` (0 or less), or past the box
            tx = end + 1;
        }
    }
}

// Zeroes what the marks and the sums of `box` wrote, so the grid is all zero again
// (ScreenTiles::gridClean) and the next bound need not clear the whole of it.
void cleanGrid(ScreenTiles* tiles, int tilesX, int tilesY, const TileBox& box) {
    const int stride = tilesX + 1;
    const int x1 = std::min(box.bx1 + 1, tilesX), y1 = std::min(box.by1 + 1, tilesY);
    for (int ty = box.by0; ty <= y1; ++ty) {
        int32_t* row = tiles->grid.data() + ty * stride;
        std::fill(row + box.bx0, row + x1 + 1, 0);
    }
}

constexpr int kChunk = 256;

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
    double boxPixels = 0.0;  // summed in a register, in particle order
    const TileRangeOf rangeOf{w, h, tilesX, tilesY, kTileBorder};
    const bool marking = grid && tilesX > 0 && tilesY > 0;
    size_t first = begin;
#if FX_SSE2
    if (plainPerspective(P) && fourLanes()) {
        // Four particles a lane each (perspectiveLanes, TileRangeOf): the rect as four running
        // minima and maxima (exact, so their order does not matter: no bounded lane holds a NaN),
        // the boxes' pixels added in particle order as below, the tiles marked lane by lane.
        const __m128 zero = _mm_setzero_ps(), width = _mm_set1_ps(float(w)), height = _mm_set1_ps(float(h));
        __m128 lo[2] = {_mm_set1_ps(1e30f), _mm_set1_ps(1e30f)}, hi[2] = {_mm_set1_ps(-1e30f), _mm_set1_ps(-1e30f)};
        int anyBounded = 0;
        for (; first + 4 <= end; first += 4) {
            const FootprintMath::Lanes q =
                flat ? math.perspectiveLanes<true>(instances + first) : math.perspectiveLanes<false>(instances + first);
            if (q.notFinite | (q.reaching & ~q.behind)) {  // a lane with no bound to trust, or at the near plane
                r.unbounded = true;
                return r;
            }
            const int bounded = ~(q.behind | q.reaching) & 15;  // the rest: wholly behind the near plane, clipped
            if (!bounded) continue;
            anyBounded |= bounded;
            const __m128i bits = _mm_and_si128(_mm_set1_epi32(bounded), _mm_setr_epi32(1, 2, 4, 8));
            const __m128 lane = _mm_castsi128_ps(_mm_cmpeq_epi32(bits, _mm_setr_epi32(1, 2, 4, 8)));
            auto where = [&](__m128 v, __m128 otherwise) { return _mm_or_ps(_mm_and_ps(lane, v), _mm_andnot_ps(lane, otherwise)); };
            lo[0] = _mm_min_ps(lo[0], where(q.x0, lo[0]));
            lo[1] = _mm_min_ps(lo[1], where(q.y0, lo[1]));
            hi[0] = _mm_max_ps(hi[0], where(q.x1, hi[0]));
            hi[1] = _mm_max_ps(hi[1], where(q.y1, hi[1]));
            // std::max(0, b) as _mm_max_ps(b, 0), std::min(w, b) as _mm_min_ps(b, w): the same bits.
            const __m128 cx0 = _mm_max_ps(q.box[0], zero), cx1 = _mm_min_ps(q.box[1], width);
            const __m128 cy0 = _mm_max_ps(q.box[2], zero), cy1 = _mm_min_ps(q.box[3], height);
            const int inside = _mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(cx1, cx0), _mm_cmpgt_ps(cy1, cy0))) & bounded;
            if (inside) {
                alignas(16) float dx[4], dy[4];
                _mm_store_ps(dx, _mm_sub_ps(cx1, cx0));
                _mm_store_ps(dy, _mm_sub_ps(cy1, cy0));
                for (int k = 0; k < 4; ++k) {
                    if (inside >> k & 1) boxPixels += double(dx[k]) * double(dy[k]);
                }
            }
            if (!marking) continue;
            int32_t ranges[4][4];
            uint8_t what[4];
            rangeOf(q, ranges, what);
            for (int k = 0; k < 4; ++k) {
                if (what[k] == TileRangeOf::Range) markTiles(grid, tilesX, ranges[k][0], ranges[k][1], ranges[k][2], ranges[k][3]);
            }
        }
        alignas(16) float l0[4], l1[4], h0[4], h1[4];
        _mm_store_ps(l0, lo[0]);
        _mm_store_ps(l1, lo[1]);
        _mm_store_ps(h0, hi[0]);
        _mm_store_ps(h1, hi[1]);
        for (int k = 0; k < 4; ++k) {
            r.lo[0] = std::min(r.lo[0], l0[k]);
            r.lo[1] = std::min(r.lo[1], l1[k]);
            r.hi[0] = std::max(r.hi[0], h0[k]);
            r.hi[1] = std::max(r.hi[1], h1[k]);
        }
        r.any = anyBounded != 0;
    }
#endif
    // One at a time: the rest of a run of four, a projection that is not a plain perspective one,
    // a target without SSE2. The arithmetic first, a chunk at a time, with no branch on the
    // particle; then what each bound means, in order.
    Bounds b[kChunk];
    for (; first < end; first += kChunk) {
        const int n = int(std::min<size_t>(kChunk, end - first));
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
            if (!marking) continue;
            int32_t range[4];
            if (rangeOf(q, range) == TileRangeOf::Range) markTiles(grid, tilesX, range[0], range[1], range[2], range[3]);
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
    // Pieces of at least 4,096 particles (about 0.1 ms each, four at a time), each with its own
    // difference grid (the first piece's is tiles->grid, 33 KB at 1080p): at most 16, so the grids
    // stay small beside the work. 16,000 particles are three pieces, not one (bench_draw
    // BM_ScreenRectJobs/16000/2: 0.82 x the time of 16,384-particle pieces on two threads).
    const Pieces pieces = splitWork(size_t(std::max(count, 0)), 4096, 16);
    const size_t gridCells = size_t(std::max(0, (tilesX + 1) * (tilesY + 1)));
    bool wasClean = false;
    if (tiles) {
        tiles->vertices.clear();
        tiles->pixels = 0;
        tiles->viewWidth = w;
        tiles->viewHeight = h;
        // All zero where the last bound cleaned up after itself (gridClean, and the same size);
        // else zeroed by its piece below, with the others'.
        if (tiles->grid.size() != gridCells) {
            tiles->gridClean = false;
            tiles->grid.resize(gridCells);
        }
        wasClean = tiles->gridClean;
        if (pieces.count == 0 && !wasClean) std::fill(tiles->grid.begin(), tiles->grid.end(), 0);
        tiles->gridClean = pieces.count == 0;  // else not until cleanGrid below: an early return leaves marks
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
            if (piece > 0 || !wasClean) std::fill(grid, grid + gridCells, 0);
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
    if (tiles && pieces.count > 1) addGrids(tiles->grid.data(), tiles->pieceGrids.data(), gridCells, pieces.count - 1, jobs);
    r.footprintPixels = boxPixels;
    // The tiles the marks lie in (none without a bounded particle): cleaned on every way out.
    TileBox box;
    if (tiles && any && tilesX > 0 && tilesY > 0) {
        const Bounds all{lo[0], hi[0], lo[1], hi[1], Bounds::Bounded, {}};
        int32_t range[4];
        if (TileRangeOf{w, h, tilesX, tilesY, kTileBorder}(all, range) == TileRangeOf::Range) {
            box = TileBox{range[0], range[1], range[2], range[3]};
        }
    }
    auto clean = [&]() {
        if (!tiles) return;
        cleanGrid(tiles, tilesX, tilesY, box);
        tiles->gridClean = true;
    };
    if (!any) {
        clean();
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
        clean();
        return r;  // no tiles either: every bound was off screen
    }
    r.whole = r.x0 == 0 && r.y0 == 0 && r.x1 == w && r.y1 == h;
    if (tiles) tileRuns(tiles, tilesX, box, w, h);
    clean();
    return r;
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
