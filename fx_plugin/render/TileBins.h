#pragma once
// The tiled path's bins (TiledPath.h): a view's particles sorted into the 16 px screen tiles their
// bounds touch, each tile's list front to back. The CPU bounds the particles and counts each
// tile's entries (O(particles + tiles)); the lists themselves, O(entries), are written by the GPU
// (TileSort.h) from `particles`, or here where a caller asks for them (Fill::Entries: the
// reference the GPU's are tested against, and bench_draw's). A view whose particles the GPU orders
// is bounded and counted there too (TileSort::binOnGpu: Fill::Ranges' words and tiles, bit for
// bit where the GPU's division rounds as the CPU's).
#include <cstdint>
#include <vector>

#include "ScreenTiles.h"
#include "base/NoInitVector.h"

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
    /// What binParticles writes besides the counts: the lists (Entries), or only what the GPU
    /// writes them from (Pairs: `particles`); Ranges: `particles` with only each one's tile range
    /// (two words), for the GPU that orders the particles itself, works each one's entry out from
    /// its place (orderStart, batchLast) and adds the counts up in its order (TileSort::DepthOrder):
    /// half the bytes written here and uploaded.
    enum class Fill : uint8_t { Entries, Pairs, Ranges };
    /// Per particle, front to back, wordsPerParticle words: its tile range (tx0 | tx1 << 16,
    /// ty0 | ty1 << 16; tx0 > tx1 where it touches none), then (Entries, Pairs) its first entry in
    /// pair order (the entries of the particles before it added up) and its entry. The GPU writes
    /// a pair (tile, entry) for every tile of a range, row by row, and sorts them by tile keeping
    /// that order (TileSort.h): the sorted entries are `entries`.
    /// (Every word is written by binParticles: not zeroed first, 1-2 MB at 256,000 particles that
    /// the one thread would otherwise clear before the pieces start.)
    NoInitVector<uint32_t> particles;
    int wordsPerParticle = 4;  ///< 4, or 2 for Fill::Ranges
    /// The entry of particle k (front to back): in the j-th batch from the back, the first k at or
    /// past orderStart[j]; its batch b = batchCount - 1 - j; its instance batchLast[b] - (k -
    /// orderStart[j]) (the batch's last instance first).
    int batchCount = 0;
    int32_t orderStart[(1 << (32 - kBatchShift)) + 1] = {};
    int32_t batchLast[1 << (32 - kBatchShift)] = {};
    std::vector<uint32_t> entries;  ///< per tile, front to back (Fill::Entries only)
    NoInitVector<uint32_t> tiles;   ///< per tile holding particles: tile x, tile y, first entry, count
    ScreenTiles cover;              ///< those tiles as runs (the composite's draw)
    uint32_t entryCount = 0;        ///< the entries of every tile (and the pairs)
    /// Binned on the GPU (TileSort::binOnGpu, readGpuBins): this many particles' words (two each,
    /// Fill::Ranges) lie in the sort's own buffer, not in `particles` (empty); 0 otherwise.
    uint32_t gpuParticles = 0;
    int tilesX = 0, tilesY = 0;     ///< the view's tiles
    /// Scratch: per tile of the view its entries, then its first (only the tiles inside the box
    /// of every particle's range are written; no other is read).
    NoInitVector<int32_t> counts;
    std::vector<int32_t> grids;     ///< scratch: per piece of the particles, +-1 at its ranges' corners
    size_t cleanCells = 0;          ///< the first cells of `grids` known to be 0 (binParticles cleans them)
    int tileCount() const { return int(tiles.size() / 4); }
};

/// Bins `instances` (billboards and spheres of a full-resolution view, drawn in `batches`' order)
/// into `out`. A sphere across the near plane is in every tile. False where a particle has no
/// bound (a position or size that is not finite): the caller draws the view another way. At most
/// 2^26 instances, 64 batches and 2^31 entries (else false too).
/// `jobs`: the host's job system. The bounds go in pieces of the particles; with Fill::Entries the
/// lists in bands of tile rows (as many as the entries pay for), each band writing only its own
/// tiles' entries: the bins are the same bit for bit however they run.
bool binParticles(const ViewInfo& view, const ParticleInstance* instances, const TileBins::Range* batches,
                  int batchCount, const BillboardReach* reach, TileBins* out, const Jobs& jobs = Jobs(),
                  TileBins::Fill fill = TileBins::Fill::Entries);

/// The composite's runs (`cover`) of `bins->tiles` (row-major, as binParticles lists them): each
/// row's neighbouring tiles as one run, on a view of width x height. binParticles ends with it, and
/// TileSort::readGpuBins for the tiles the GPU listed.
void coverTiles(TileBins* bins, int width, int height);

/// The front-to-back places of `batches` in `out` (orderStart, batchLast, batchCount), the first
/// thing binParticles writes: the GPU's order of the particles (TileSort::sortParticles) needs no
/// more, so it can start before the bins (TiledPath's deferred bins). Returns the particles, or -1
/// past binParticles' limits (more than 64 batches, an instance at 2^26 or beyond).
int placeBatches(const TileBins::Range* batches, int batchCount, TileBins* out);

/// The lists of a Fill::Pairs (or Entries) result written here after all (`entries`, what Fill::Entries gives
/// and TileSort writes on the GPU): where they are few, writing them costs the CPU less than the
/// GPU's sort costs its fixed passes (TiledPath::kCpuListEntries). Once per binParticles: its
/// `counts` are the cursors. In bands of tile rows through `jobs`.
void writeEntries(TileBins* bins, const Jobs& jobs = Jobs());

}  // namespace fx
