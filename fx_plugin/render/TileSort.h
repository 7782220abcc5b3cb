#pragma once
// The tiled path's lists written on the GPU (shaders/cs_particles_tile_sort.glsl). binParticles (TileBins.h,
// Fill::Pairs) bounds the particles and counts each tile's entries on the CPU, in time that grows
// with the particles and the tiles; the lists grow with the entries (6 M at 256,000 particles in
// bench_draw's view), so they are written here: a pair (tile, entry) per tile of each particle's
// range in particle order, then a stable radix sort of the pairs by tile, four bits a pass (four
// passes for up to 65,536 tiles: 1080p has 8,160, 4K 32,400). The sorted entries are
// binParticles' Fill::Entries lists bit for bit (TileSortTest).
//
// Why not on the CPU: there every list is written once per frame and uploaded (24 MB at 256,000
// particles); on the H200 that was 37 ms a frame against the tiled pass's 25 ms (docs/results.md,
// session 24).
//
// The particles' front-to-back order too, where the view's list was built without its CPU sort
// (DrawList::orderPending, for views of at least orderLimit() particles): run() with a DepthOrder
// keys each particle by its batch and its depth (worked out as the CPU does, `precise`), sorts the
// keys with the same radix passes (eight for the depth, one or two for the batch where there are
// several) and adds the particles' pair counts up in that order (a scan in blocks of 1,024): the
// pairs and lists are then those of the sorted list, bit for bit (TileSortTest), their entries
// naming the particles where the unsorted list holds them. What the CPU saves: the radix sort and
// the gather of the draw list (bench_draw, 256,000 particles: 10.9 -> 4.4 ms on one thread; on
// the H200 the tiled frame's declare 6.6 -> 3.1 ms, docs/results.md session 29).
//
// The bins themselves, for a view whose particles the GPU orders (binOnGpu, readGpuBins): each
// particle's tile range and each tile's count worked out here too (FX_TILE_BOUND, FX_TILE_LIST),
// the CPU reading back only the entry count and the tiles.
//
// GL state: run() and binOnGpu() bind shader storage buffers 0-4 and a program; the caller puts them back
// (TiledPath's ComputeBindingsScope). Context current.
#include <cstddef>
#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include "ProgramCache.h"
#include "TileBins.h"
#include "base/ParallelFor.h"

namespace fx {

class TileSort {
public:
    static constexpr int kBindings = 5;            ///< shader storage buffers 0 .. 4
    static constexpr int kGroup = 256;             ///< cs_particles_tile_sort.glsl's pairs per row of a block
    static constexpr int kMaxRows = 16;            ///< rows of a block at most
    static constexpr int kDigitBits = 4;           ///< cs_particles_tile_sort.glsl's bits of the tile a pass

    /// What run() needs to put the particles of an unsorted list (DrawList::orderPending) in
    /// front-to-back order: the buffer holding its instances (two vec4 each, InstanceStream's
    /// ParticleInstance), the view's eye and viewForward, the batches drawn back to front (a bit
    /// per batch of TileBins' entries) and the batch count.
    struct DepthOrder {
        uint32_t instances = 0;
        glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};
        uint32_t backToFront = 0;
        int batchCount = 1;
    };
    /// The GPU sorts a view's particles (DrawList::orderPending) from this many particles on.
    /// H200 (docs/results.md, session 29): the GPU's order costs the pass 0.11-0.13 ms up to
    /// 64,000 particles, 0.36 ms at 256,000; the CPU's sort and gather cost the declare
    /// 0.16-0.82 ms at 16,000 particles (two rounds), 1.3 ms at 64,000, 3.5 ms at 256,000 (16
    /// threads). The environment's CUBEFX_TILED_GPU_ORDER (a whole number of particles; 0: every
    /// view) or setOrderLimit()'s where either is set; else kOrderParticles, on a software
    /// rasterizer never (UINT32_MAX).
    static constexpr uint32_t kOrderParticles = 16384;
    static uint32_t orderLimit(bool softwareRasterizer);
    static void setOrderLimit(uint32_t particles);
    static void resetOrderLimit();  ///< back to the environment's, or the defaults
    static const char* orderLimitProblem();  ///< what was wrong with CUBEFX_TILED_GPU_ORDER, or null
    static uint64_t gpuOrderedViews();      ///< views run() ordered, since the process started

    TileSort() = default;
    ~TileSort();
    TileSort(const TileSort&) = delete;
    TileSort& operator=(const TileSort&) = delete;

    /// Takes the four programs of `programs` (0 where one failed) and looks their uniforms up, and
    /// the context's largest shader storage block. Context current.
    void bind(const ProgramCache& programs);
    bool ok() const { return emit_ && count_ && scan_ && scatter_; }
    /// ok() and the order's four programs built.
    bool orderOk() const { return ok() && orderKey_ && orderBatch_ && orderPrefix_ && orderAdd_; }
    /// Whether run() can take `bins` (its pairs fit a shader storage block of the context).
    bool fits(const TileBins& bins) const;
    /// Writes and sorts the pairs of `bins` (binParticles with Fill::Pairs); returns the buffer
    /// whose first bins.entryCount words are the entries, tile by tile (0 where !ok() or
    /// !fits()). The buffer is the sort's own, valid until the next run(). Ends with a shader
    /// storage barrier.
    /// With `jobs`, the particles' words are copied into the mapped buffer on the host's threads.
    /// With `order` (orderOk() only, else 0), bins of an unsorted list, binned as it lies with
    /// Fill::Ranges (two words a particle; else 0): the particles are put in front-to-back order
    /// first (above). Without, bins of four words a particle (Pairs).
    /// `afterEmit` (TiledStageTimes): called once the pairs are written, before their radix passes.
    uint32_t run(const TileBins& bins, const Jobs& jobs = Jobs(), const DepthOrder* order = nullptr,
                 const std::function<void()>& afterEmit = nullptr);
    /// The first half of run() with `order`, which needs no bins: each particle's key and the
    /// radix passes over them (orderOk() only). `places`: the bins' orderStart, batchLast and
    /// batchCount (placeBatches). Issued before the bins are worked out, the GPU sorts while the
    /// CPU bins (TiledPath's deferred bins); the next run() with an order of `particleCount`
    /// particles goes on from it instead of sorting again. dropOrder() forgets it (a view that
    /// was not drawn after all).
    void sortParticles(uint32_t particleCount, const DepthOrder& order, const TileBins& places);
    void dropOrder() { sorted_ = false; }
    /// The bins on the GPU as well (FX_TILE_BOUND, FX_TILE_LIST): their two programs built too.
    bool binsOk() const { return orderOk() && bound_ && list_; }
    /// Issues the bins of an unsorted list (what binParticles gives with Fill::Ranges, bit for bit
    /// where the GPU's division rounds as the CPU's): each of `particleCount` particles placed as
    /// `places` (placeBatches) bounded from `instances` (a buffer of ParticleInstance: the list's),
    /// its two words written into the sort's own buffer, where run() takes them, and its tiles
    /// counted; then the tiles that hold particles listed into `*tileBuffer` (grown as
    /// ensureBuffer grows, to the view's tiles). `sphereBatches`: a bit per batch drawn as spheres;
    /// `reach`: the billboards' (lodScale 0: their quads). No CPU work per particle: readGpuBins,
    /// called once the GPU has had other work to do meanwhile, waits for the result. False (nothing
    /// issued) where !binsOk(), the view has no tiles or more than 65,535 a side, or over 32 batches.
    bool binOnGpu(const ViewInfo& view, uint32_t instances, uint32_t particleCount, uint32_t sphereBatches,
                  const BillboardReach& reach, const TileBins& places, uint32_t* tileBuffer, size_t* tileCapacity);
    /// binOnGpu's result, read back (a wait for the GPU): `bins` gets its entryCount, tilesX/Y, tiles
    /// (as binParticles lists them), cover (coverTiles) and gpuParticles, its particles emptied: the
    /// words stay on the GPU. False where nothing was issued, a particle had no bound (not finite:
    /// the view is drawn another way, as binParticles' false) or the entries pass 2^31 - 1.
    bool readGpuBins(TileBins* bins);
    /// Caps the largest shader storage block fits() allows below the context's (bytes; 0: the
    /// context's own): a context with small blocks, for tests.
    static void setBlockLimit(int64_t bytes);

    /// The radix passes a view of `tileCount` tiles takes.
    static int passes(int tileCount);
    /// The rows of kGroup pairs a block of the sort takes for `pairs` pairs: one until there are
    /// about kTargetBlocks blocks, then more, up to kMaxRows. A block is one work group that counts
    /// and scatters its rows one after another, so few blocks leave a large GPU idle (an H200 holds
    /// about 1,000 groups of 256 at once) while many lengthen the one-group scan of their
    /// histogram. setRows (or CUBEFX_TILE_SORT_ROWS, read once) fixes the rows instead, 0 undoes it.
    static int rowsFor(uint32_t pairs);
    static void setRows(int rows);
    static constexpr uint32_t kTargetBlocks = 1024;
    /// Makes `*buffer` if there is none and grows its store to hold `bytes` (to the next power of
    /// two, GL_DYNAMIC_COPY; a growing count reallocates a few times, not each frame); a store
    /// that grows is left bound to GL_SHADER_STORAGE_BUFFER.
    static void ensureBuffer(uint32_t* buffer, size_t* capacity, size_t bytes);

private:
    struct Uniforms {
        int groupsX = -1, particleCount = -1, tilesX = -1, pairCount = -1, shift = -1, blocks = -1, length = -1,
            rows = -1, eye = -1, forward = -1, backToFront = -1, batchCount = -1, orderStart = -1, batchLast = -1;
    };
    // One radix pass over `count` keys[from]/entries[from] into [from ^ 1] by kDigitBits at `shift`.
    void radixPass(uint32_t count, int shift, const uint32_t keys[2], const uint32_t entries[2], int from);
    // Writes the sorted particles (sortParticles), with their first pairs, to ordered_.
    void orderParticles(uint32_t particleCount, const TileBins& bins);

    struct BinUniforms {
        int groupsX = -1, particleCount = -1, batchCount = -1, orderStart = -1, batchLast = -1, sphereBatches = -1,
            view = -1, proj = -1, nearPlane = -1, viewSize = -1, tiles = -1, perspective = -1, reachLodScale = -1,
            reachBuckets = -1, reach = -1, phase = -1;
    };
    uint32_t bound_ = 0, list_ = 0;
    BinUniforms boundU_, listU_;
    uint32_t grid_ = 0;             // BOUND's difference grid after a header of four words (LIST's result)
    size_t gridCapacity_ = 0;
    uint32_t binnedTiles_ = 0;      // binOnGpu's tile buffer, until readGpuBins
    int binnedTilesX_ = 0, binnedTilesY_ = 0, binnedWidth_ = 0, binnedHeight_ = 0;
    uint32_t binnedParticles_ = 0;  // 0: nothing issued
    uint32_t emit_ = 0, count_ = 0, scan_ = 0, scatter_ = 0;
    uint32_t orderKey_ = 0, orderBatch_ = 0, orderPrefix_ = 0, orderAdd_ = 0;
    Uniforms emitU_, countU_, scanU_, scatterU_, orderKeyU_, orderBatchU_, orderPrefixU_, orderAddU_;
    uint32_t particles_ = 0, keys_[2] = {}, entries_[2] = {}, histogram_ = 0, ordered_ = 0;
    size_t particlesCapacity_ = 0, keysCapacity_[2] = {}, entriesCapacity_[2] = {}, histogramCapacity_ = 0,
           orderedCapacity_ = 0;
    // The particles' sort (sortParticles): keys and places of their own, so that the pairs'
    // buffers, sized once the bins are known, can grow after it without losing its result.
    uint32_t orderKeys_[2] = {}, orderPlaces_[2] = {};
    size_t orderKeysCapacity_[2] = {}, orderPlacesCapacity_[2] = {};
    bool sorted_ = false;           // sortParticles ran and no run() has taken it yet
    uint32_t sortedCount_ = 0;      // its particles
    int sortedFrom_ = 0;            // the sorted places: orderPlaces_[sortedFrom_]
    int64_t maxBlockBytes_ = 0;
};

}  // namespace fx
