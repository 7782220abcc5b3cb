#include "TileBins.h"

#include <algorithm>
#include <cmath>

#include "FootprintMath.h"

namespace fx {

using namespace footprint;

namespace {
constexpr int kTileSize = ScreenTiles::kTileSize;
}  // namespace

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

}  // namespace fx
