#include "TileBins.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

#include "FootprintMath.h"

namespace fx {

using namespace footprint;

namespace {
constexpr int kTileSize = ScreenTiles::kTileSize;
constexpr int kChunk = 256;  // particles bounded before their tiles are marked
}  // namespace

int placeBatches(const TileBins::Range* batches, int batchCount, TileBins* out) {
    if (batchCount < 0 || batchCount > (1 << (32 - TileBins::kBatchShift))) return -1;
    int top = 0;
    for (int b = 0; b < batchCount; ++b) top = std::max(top, batches[b].first + batches[b].count);
    if (top >= (1 << TileBins::kBatchShift)) return -1;
    // Front-to-back order k: the last batch's last particle first. orderStart[j]: the first k of
    // the j-th batch from the back.
    int n = 0;
    for (int j = 0; j < batchCount; ++j) {
        const TileBins::Range& batch = batches[batchCount - 1 - j];
        out->orderStart[j] = n;
        n += std::max(batch.count, 0);
        out->batchLast[batchCount - 1 - j] = batch.first + batch.count - 1;
    }
    out->orderStart[batchCount] = n;
    out->batchCount = batchCount;
    return n;
}

bool binParticles(const ViewInfo& view, const ParticleInstance* instances, const TileBins::Range* batches,
                  int batchCount, const BillboardReach* reach, TileBins* out, const Jobs& jobs,
                  TileBins::Fill fill) {
    const int w = view.width, h = view.height;
    const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
    out->entries.clear();
    out->particles.clear();
    out->tiles.clear();
    out->entryCount = 0;
    out->gpuParticles = 0;
    out->tilesX = out->tilesY = 0;
    out->cover.vertices.clear();
    out->cover.pixels = 0;
    out->cover.viewWidth = w;
    out->cover.viewHeight = h;
    if (batchCount > (1 << (32 - TileBins::kBatchShift))) return false;
    if (tilesX <= 0 || tilesY <= 0) return true;  // an empty view: no tiles
    if (tilesX > 0xffff || tilesY > 0xffff) return false;  // a range's 16 bit halves
    const int n = placeBatches(batches, batchCount, out);
    if (n < 0) return false;
    const int32_t* orderStart = out->orderStart;
    const int stride = fill == TileBins::Fill::Ranges ? 2 : 4;
    out->wordsPerParticle = stride;
    const int tileCount = tilesX * tilesY;
    const FootprintMath flat(view, true, reach), box(view, false, nullptr, 0.5f);
    const bool perspective = plainPerspective(view.proj);
    out->tilesX = tilesX;
    out->tilesY = tilesY;
    out->particles.resize(size_t(n) * size_t(stride));
    uint32_t* words = out->particles.data();
    const size_t gridWidth = size_t(tilesX) + 1, gridSize = gridWidth * (size_t(tilesY) + 1);

    // 1. Each particle's tile range (empty where it is clipped or off the view), its entry and its
    // entry count (in the first-entry word for now), in pieces of the particles; each piece marks
    // its ranges' corners +-1 in its own grid (summed below into each tile's count: a large
    // particle costs no more than a small one). Pieces of 2,048 or more (20-40 us each): a view of
    // 16,000 particles is seven, which a host's threads share (BM_TileBins/16000/2: 0.71-0.73 x
    // the time of 8,192-particle pieces, which made it one).
    const Pieces pieces = splitWork(size_t(n), 2048, 16);
    // Each piece zeroes its own grid (below, on its thread), but for the first where the last bins
    // left it zero (cleanCells; cleaned after step 2): then nothing is cleared over the whole view
    // for a small view's few tiles. Each piece also keeps the box of the tiles it marked.
    if (out->grids.size() < size_t(pieces.count) * gridSize) out->grids.resize(size_t(pieces.count) * gridSize);
    const bool firstClean = out->cleanCells >= gridSize;
    out->cleanCells = 0;  // until cleaned below: a failed or refused view leaves marks
    bool failed[HostAdapter::kMaxTasks] = {};
    uint64_t pieceEntries[HostAdapter::kMaxTasks] = {};
    int32_t pieceBox[HostAdapter::kMaxTasks][4];  // tx0, tx1, ty0, ty1 of its marks; tx0 > tx1: none
    jobs.run(pieces, [&](uint32_t piece) {
        int32_t* grid = &out->grids[piece * gridSize];
        if (piece > 0 || !firstClean) std::fill(grid, grid + gridSize, 0);
        int32_t marked[4] = {INT32_MAX, -1, INT32_MAX, -1};
        uint64_t sum = 0;
        int32_t ranges[kChunk][4];
        uint8_t what[kChunk];
        const TileRangeOf rangeOf{w, h, tilesX, tilesY, 1};  // grown by a pixel
        [[maybe_unused]] const bool lanes = fourLanes();
        // A stretch of k at a time that lies in one batch and one chunk: its instances are
        // contiguous (k counts them down), so their tile ranges come four at a time
        // (perspectiveLanes) in instance order, read back in k order.
        size_t k = pieces.begin(piece);
        const size_t end = pieces.end(piece);
        int j = 0;
        while (k < end) {
            while (size_t(orderStart[j + 1]) <= k) ++j;
            const size_t stretchEnd = std::min({end, size_t(orderStart[j + 1]), k + size_t(kChunk)});
            const int len = int(stretchEnd - k);
            const int b = batchCount - 1 - j;
            const int iHigh = batches[b].first + batches[b].count - 1 - (int(k) - orderStart[j]);
            const ParticleInstance* stretch = instances + (iHigh - len + 1);  // instance iHigh - t is [len - 1 - t]
            const bool sphere = batches[b].sphere;
            const FootprintMath& math = sphere ? box : flat;
            int t = 0;
            if (!perspective) {
                for (; t < len; ++t) what[t] = rangeOf(math.general(stretch[t]), ranges[t]);
            }
#if FX_SSE2
            for (; lanes && t + 4 <= len; t += 4) {
                rangeOf(sphere ? math.perspectiveLanes<false>(stretch + t) : math.perspectiveLanes<true>(stretch + t),
                        ranges + t, what + t);
            }
#endif
            for (; t < len; ++t) {
                what[t] = rangeOf(sphere ? math.perspective<false>(stretch[t]) : math.perspective<true>(stretch[t]), ranges[t]);
            }
            for (t = 0; t < len; ++t, ++k) {
                const int at = len - 1 - t;
                uint32_t* word = &words[k * size_t(stride)];
                word[0] = word[1] = 1u;  // tx0 1 > tx1 0: none
                if (stride == 4) {
                    word[2] = 0;
                    word[3] = uint32_t(iHigh - t) | (uint32_t(b) << TileBins::kBatchShift);
                }
                if (what[at] == TileRangeOf::None) continue;
                int32_t* r = ranges[at];
                if (what[at] == TileRangeOf::Unbounded) {
                    const ParticleInstance& p = stretch[at];
                    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.size))) {
                        failed[piece] = true;
                        return;
                    }
                    // A sphere across the near plane (a billboard has one depth: never): every tile.
                    r[0] = 0;
                    r[1] = tilesX - 1;
                    r[2] = 0;
                    r[3] = tilesY - 1;
                }
                word[0] = uint32_t(r[0]) | uint32_t(r[1]) << 16;
                word[1] = uint32_t(r[2]) | uint32_t(r[3]) << 16;
                const uint32_t count = uint32_t((r[1] - r[0] + 1) * (r[3] - r[2] + 1));
                if (stride == 4) word[2] = count;  // the first entry once the counts are added up
                sum += count;
                markTiles(grid, tilesX, r[0], r[1], r[2], r[3]);
                marked[0] = std::min(marked[0], r[0]);
                marked[1] = std::max(marked[1], r[1]);
                marked[2] = std::min(marked[2], r[2]);
                marked[3] = std::max(marked[3], r[3]);
            }
        }
        pieceEntries[piece] = sum;
        std::copy(marked, marked + 4, pieceBox[piece]);
    });
    uint64_t total = 0;
    uint32_t pieceFirst[HostAdapter::kMaxTasks] = {};
    for (uint32_t piece = 0; piece < pieces.count; ++piece) {
        if (failed[piece]) return false;
        pieceFirst[piece] = uint32_t(total);
        total += pieceEntries[piece];
        if (total > uint64_t(INT32_MAX)) return false;
    }
    out->entryCount = uint32_t(total);
    // Each particle's first entry: its piece's, then its own count added up in the piece.
    if (fill != TileBins::Fill::Ranges) jobs.run(pieces, [&](uint32_t piece) {
        uint32_t first = pieceFirst[piece];
        for (size_t k = pieces.begin(piece), end = pieces.end(piece); k < end; ++k) {
            const uint32_t count = words[k * 4 + 2];
            words[k * 4 + 2] = first;
            first += count;
        }
    });

    // 2. Each tile's count: the grids added up, then summed along the rows and down the columns,
    // inside the box of every mark (outside it every count is 0, and nothing reads those cells:
    // step 3 and writeEntries visit only tiles of the ranges); then the first grid zeroed there
    // (the marks reach one row and one column past the box).
    int32_t* grid = out->grids.data();
    if (pieces.count > 1) addGrids(grid, grid + gridSize, gridSize, pieces.count - 1, jobs);
    int bx0 = INT32_MAX, bx1 = -1, by0 = INT32_MAX, by1 = -1;
    for (uint32_t piece = 0; piece < pieces.count; ++piece) {
        bx0 = std::min(bx0, pieceBox[piece][0]);
        bx1 = std::max(bx1, pieceBox[piece][1]);
        by0 = std::min(by0, pieceBox[piece][2]);
        by1 = std::max(by1, pieceBox[piece][3]);
    }
    if (out->counts.size() < size_t(tileCount)) out->counts.resize(size_t(tileCount));
    int32_t* counts = out->counts.data();
    for (int ty = by0; ty <= by1; ++ty) {
        int32_t row = 0;
        const int32_t* marks = grid + size_t(ty) * gridWidth;
        int32_t* line = counts + ty * tilesX;
        for (int tx = bx0; tx <= bx1; ++tx) {
            row += marks[tx];
            line[tx] = row + (ty > by0 ? line[tx - tilesX] : 0);
        }
    }
    for (int ty = std::min(by0, tilesY); ty <= std::min(by1 + 1, tilesY); ++ty) {
        std::fill(grid + size_t(ty) * gridWidth + size_t(bx0), grid + size_t(ty) * gridWidth + size_t(std::min(bx1 + 1, tilesX)) + 1, 0);
    }
    out->cleanCells = gridSize;

    // 3. Each tile's first entry (its cursor from now on), the tiles with particles, and their runs
    // for the composite (coverTiles).
    int32_t sum = 0;
    size_t listed = 0;
    if (by1 >= by0) out->tiles.resize(size_t(by1 - by0 + 1) * size_t(bx1 - bx0 + 1) * 4);  // at most; cut below
    uint32_t* tileWords = out->tiles.data();
    for (int ty = by0; ty <= by1; ++ty) {
        int32_t* line = counts + ty * tilesX;
        for (int tx = bx0; tx <= bx1; ++tx) {
            const int32_t tileEntries = line[tx];
            if (tileEntries <= 0) continue;
            uint32_t* t = tileWords + listed;
            t[0] = uint32_t(tx);
            t[1] = uint32_t(ty);
            t[2] = uint32_t(sum);
            t[3] = uint32_t(tileEntries);
            listed += 4;
            line[tx] = sum;
            sum += tileEntries;
        }
    }
    out->tiles.resize(listed);
    coverTiles(out, w, h);
    if (fill == TileBins::Fill::Entries) writeEntries(out, jobs);
    return true;
}

void coverTiles(TileBins* bins, int width, int height) {
    ScreenTiles& cover = bins->cover;
    cover.vertices.clear();
    cover.pixels = 0;
    cover.viewWidth = width;
    cover.viewHeight = height;
    const uint32_t* t = bins->tiles.data();
    const size_t n = bins->tiles.size() / 4;
    for (size_t i = 0; i < n;) {
        // A run: the tiles of one row whose x follow on.
        const uint32_t ty = t[i * 4 + 1], x0 = t[i * 4];
        size_t j = i + 1;
        while (j < n && t[j * 4 + 1] == ty && t[j * 4] == t[(j - 1) * 4] + 1) ++j;
        const int endX = int(t[(j - 1) * 4]) + 1;
        addRun(&cover, int(x0) * kTileSize, int(ty) * kTileSize, std::min(width, endX * kTileSize),
               std::min(height, (int(ty) + 1) * kTileSize));
        i = j;
    }
}

void writeEntries(TileBins* bins, const Jobs& jobs) {
    // 4. The entries, front to back (k order), in bands of tile rows, each band into its own tiles
    // (it reads every particle's range: cheap beside its entries). A band per 8,192 entries, up to
    // 16: the writes go to scattered tiles, about 4-6 ns an entry on one thread (bench_draw).
    if (bins->wordsPerParticle != 4) return;  // Fill::Ranges: no entries to write them from
    const int tilesX = bins->tilesX, n = int(bins->particles.size() / 4);
    const uint32_t* words = bins->particles.data();
    int32_t* counts = bins->counts.data();
    const Pieces bands = splitWork(size_t(bins->tilesY), 1,
                                   uint32_t(std::min<uint64_t>(std::max<uint64_t>(bins->entryCount / 8192, 1), 16)));
    bins->entries.resize(bins->entryCount);
    uint32_t* entriesOut = bins->entries.data();
    jobs.run(bands, [&](uint32_t band) {
        const int y0 = int(bands.begin(band)), y1 = int(bands.end(band)) - 1;
        for (int k = 0; k < n; ++k) {
            const uint32_t* r = &words[size_t(k) * 4];
            const int tx0 = int(r[0] & 0xffffu), tx1 = int(r[0] >> 16);
            for (int ty = std::max(int(r[1] & 0xffffu), y0); ty <= std::min(int(r[1] >> 16), y1); ++ty) {
                for (int tx = tx0; tx <= tx1; ++tx) entriesOut[counts[ty * tilesX + tx]++] = r[3];
            }
        }
    });
}

}  // namespace fx
