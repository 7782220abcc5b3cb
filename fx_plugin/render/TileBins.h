#pragma once
// The tiled path's bins (TiledPath.h): a view's particles sorted into the 16 px screen tiles their
// bounds touch, each tile's list front to back, on the CPU (no GL).
#include <cstdint>
#include <vector>

#include "ScreenTiles.h"

namespace fx {

/// Each particle of a view in the kTileSize tiles its bound (a billboard's trimmed polygon's with a
/// reach table, else its quad's; a sphere's cube of half-size size / 2; grown by a pixel) touches,
/// every tile's list front to back: the reverse of the draw order, batch by batch.
struct TileBins {
    static constexpr int kBatchShift = 26;  ///< an entry: instance index | batch << kBatchShift
    struct Range {
        int first = 0, count = 0;  ///< a batch's instances
        bool sphere = false;       ///< spheres: bounded as Footprint::Box, the reach table not used
    };
    std::vector<uint32_t> entries;  ///< per tile, front to back
    std::vector<uint32_t> tiles;    ///< per tile holding particles: tile x, tile y, first entry, count
    ScreenTiles cover;              ///< those tiles as runs (the composite's draw)
    std::vector<int32_t> counts;    ///< scratch: entries per tile of the view, then its cursors
    std::vector<int32_t> ranges;    ///< scratch: per particle its tile range (tx0, tx1, ty0, ty1)
    std::vector<uint32_t> weights;  ///< scratch: per particle its tile count
    int tileCount() const { return int(tiles.size() / 4); }
};

/// Bins `instances` (billboards and spheres of a full-resolution view, drawn in `batches`' order)
/// into `out`. A sphere across the near plane is in every tile. False where a particle has no
/// bound (a position or size that is not finite): the caller draws the view another way. At most
/// 2^26 instances and 64 batches (else false too).
/// `jobs`: the host's job system. The bounds go in pieces of the particles, the binning in bands
/// of tile rows (as many as the entries pay for, however few the particles), each band writing
/// only its own tiles' counts and entries: the bins are the same bit for bit however they run.
bool binParticles(const ViewInfo& view, const ParticleInstance* instances, const TileBins::Range* batches,
                  int batchCount, const BillboardReach* reach, TileBins* out, const Jobs& jobs = Jobs());

}  // namespace fx
