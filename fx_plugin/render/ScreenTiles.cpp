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
    double boxPixels = 0.0;  // summed in a register
    Bounds b[kChunk];
    for (size_t first = begin; first < end; first += kChunk) {
        const int n = int(std::min<size_t>(kChunk, end - first));
        // The arithmetic first, for a chunk at a time, with no branch on the particle; then what
        // each bound means, in order.
        if (!plainPerspective(P)) {
            for (int j = 0; j < n; ++j) b[j] = math.general(instances[first + j]);
        } else if (flat) {
            math.perspectiveRun<true>(instances + first, n, b);
        } else {
            math.perspectiveRun<false>(instances + first, n, b);
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
        // Zeroed by its piece below, with the others' (cleared twice, it was a tenth of a 1,000
        // particle bound: bench_draw BM_ScreenRect/1000).
        if (pieces.count > 0) {
            tiles->grid.resize(gridCells);
        } else {
            tiles->grid.assign(gridCells, 0);
        }
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
