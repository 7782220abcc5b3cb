#include "TileSort.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "FootprintMath.h"
#include "InstanceStream.h"
#include "render/PrivateGl.h"

namespace fx {
namespace {

constexpr int kParticleBinding = 0, kKeysIn = 1, kEntriesIn = 2, kKeysOut = 3, kEntriesOut = 0, kHistogram = 4;
constexpr uint32_t kGroup = TileSort::kGroup;

// CUBEFX_TILE_SORT_ROWS, read once: 1 .. kMaxRows fixes the rows per block (for measuring), else 0.
int rowsFromEnvironment() {
    const char* v = std::getenv("CUBEFX_TILE_SORT_ROWS");
    if (!v || !*v) return 0;
    const int rows = std::atoi(v);
    return rows >= 1 && rows <= TileSort::kMaxRows ? rows : 0;
}
std::atomic<int> gRows{rowsFromEnvironment()};

// CUBEFX_TILED_GPU_ORDER, read once: a whole number of particles (clamped to 2^32 - 1), else -1
// (the defaults), with a problem to report where it was set but not a number.
const char* gOrderLimitProblem = nullptr;
int64_t orderLimitFromEnvironment() {
    const char* v = std::getenv("CUBEFX_TILED_GPU_ORDER");
    if (!v || !*v) return -1;
    uint64_t n = 0;
    for (const char* c = v; *c; ++c) {
        if (*c < '0' || *c > '9') {
            gOrderLimitProblem = "fx: CUBEFX_TILED_GPU_ORDER is not a whole number of particles; the tiled path "
                                 "keeps its default (the GPU sorts views of 16384 particles or more)";
            return -1;
        }
        n = std::min<uint64_t>(n * 10 + uint64_t(*c - '0'), UINT32_MAX);
    }
    return int64_t(n);
}
static_assert(TileSort::kOrderParticles == 16384, "the message above names the default");
const int64_t gOrderLimitFromEnvironment = orderLimitFromEnvironment();
std::atomic<int64_t> gOrderLimit{gOrderLimitFromEnvironment};  // -1: the defaults
std::atomic<uint64_t> gGpuOrderedViews{0};
std::atomic<int64_t> gBlockLimit{0};  // setBlockLimit: 0, the context's

// `groups` work groups in rows of at most 65,535 (the least GL_MAX_COMPUTE_WORK_GROUP_COUNT),
// the row length in the program's uGroupsX.
void dispatch(uint32_t groups, int groupsXUniform) {
    if (groups == 0) return;
    const uint32_t groupsX = std::min<uint32_t>(groups, 65535u);
    glUniform1i(groupsXUniform, int(groupsX));
    glDispatchCompute(groupsX, (groups + groupsX - 1) / groupsX, 1);
}

}  // namespace

uint32_t TileSort::orderLimit(bool softwareRasterizer) {
    const int64_t set = gOrderLimit.load(std::memory_order_relaxed);
    if (set >= 0) return uint32_t(set);
    return softwareRasterizer ? UINT32_MAX : kOrderParticles;
}
void TileSort::setOrderLimit(uint32_t particles) { gOrderLimit.store(int64_t(particles), std::memory_order_relaxed); }
void TileSort::resetOrderLimit() { gOrderLimit.store(gOrderLimitFromEnvironment, std::memory_order_relaxed); }
const char* TileSort::orderLimitProblem() { return gOrderLimitProblem; }
uint64_t TileSort::gpuOrderedViews() { return gGpuOrderedViews.load(std::memory_order_relaxed); }

TileSort::~TileSort() {
    // The renderer deletes its GL objects with the context current (~ParticleRenderer).
    if (!privateGlContextCurrent()) return;
    const uint32_t buffers[12] = {particles_,    keys_[0],      keys_[1],        entries_[0],
                                  entries_[1],   histogram_,    ordered_,        orderKeys_[0],
                                  orderKeys_[1], orderPlaces_[0], orderPlaces_[1], grid_};
    for (uint32_t b : buffers) {
        if (b) glDeleteBuffers(1, &b);
    }
}

void TileSort::bind(const ProgramCache& programs) {
    emit_ = programs.passProgram(ProgramCache::TileEmit);
    count_ = programs.passProgram(ProgramCache::TileSortCount);
    scan_ = programs.passProgram(ProgramCache::TileSortScan);
    scatter_ = programs.passProgram(ProgramCache::TileSortScatter);
    orderKey_ = programs.passProgram(ProgramCache::TileOrderKey);
    orderBatch_ = programs.passProgram(ProgramCache::TileOrderBatch);
    orderPrefix_ = programs.passProgram(ProgramCache::TileOrderPrefix);
    orderAdd_ = programs.passProgram(ProgramCache::TileOrderAdd);
    const uint32_t progs[8] = {emit_, count_, scan_, scatter_, orderKey_, orderBatch_, orderPrefix_, orderAdd_};
    Uniforms* uniforms[8] = {&emitU_, &countU_, &scanU_, &scatterU_, &orderKeyU_, &orderBatchU_, &orderPrefixU_, &orderAddU_};
    for (int p = 0; p < 8; ++p) {
        Uniforms& u = *uniforms[p];
        u = Uniforms{};
        if (!progs[p]) continue;
        u.groupsX = glGetUniformLocation(progs[p], "uGroupsX");
        u.particleCount = glGetUniformLocation(progs[p], "uParticleCount");
        u.tilesX = glGetUniformLocation(progs[p], "uTilesX");
        u.pairCount = glGetUniformLocation(progs[p], "uPairCount");
        u.shift = glGetUniformLocation(progs[p], "uShift");
        u.blocks = glGetUniformLocation(progs[p], "uBlocks");
        u.length = glGetUniformLocation(progs[p], "uLength");
        u.rows = glGetUniformLocation(progs[p], "uRows");
        u.eye = glGetUniformLocation(progs[p], "uEye");
        u.forward = glGetUniformLocation(progs[p], "uForward");
        u.backToFront = glGetUniformLocation(progs[p], "uBackToFront");
        u.batchCount = glGetUniformLocation(progs[p], "uBatchCount");
        u.orderStart = glGetUniformLocation(progs[p], "uOrderStart");
        u.batchLast = glGetUniformLocation(progs[p], "uBatchLast");
    }
    bound_ = programs.passProgram(ProgramCache::TileBound);
    list_ = programs.passProgram(ProgramCache::TileList);
    for (uint32_t program : {bound_, list_}) {
        BinUniforms& u = program == bound_ ? boundU_ : listU_;
        u = BinUniforms{};
        if (!program) continue;
        u.groupsX = glGetUniformLocation(program, "uGroupsX");
        u.particleCount = glGetUniformLocation(program, "uParticleCount");
        u.batchCount = glGetUniformLocation(program, "uBatchCount");
        u.orderStart = glGetUniformLocation(program, "uOrderStart");
        u.batchLast = glGetUniformLocation(program, "uBatchLast");
        u.sphereBatches = glGetUniformLocation(program, "uSphereBatches");
        u.view = glGetUniformLocation(program, "uView");
        u.proj = glGetUniformLocation(program, "uProj");
        u.nearPlane = glGetUniformLocation(program, "uNearPlane");
        u.viewSize = glGetUniformLocation(program, "uViewSize");
        u.tiles = glGetUniformLocation(program, "uTiles");
        u.perspective = glGetUniformLocation(program, "uPerspective");
        u.reachLodScale = glGetUniformLocation(program, "uReachLodScale");
        u.reachBuckets = glGetUniformLocation(program, "uReachBuckets");
        u.reach = glGetUniformLocation(program, "uReach");
        u.phase = glGetUniformLocation(program, "uPhase");
    }
    binnedParticles_ = 0;
    GLint64 bytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
    maxBlockBytes_ = bytes;
}

int TileSort::passes(int tileCount) {
    int bits = 0;
    while (bits < 31 && (int64_t(1) << bits) < int64_t(tileCount)) ++bits;
    return (bits + kDigitBits - 1) / kDigitBits;
}

int TileSort::rowsFor(uint32_t pairs) {
    const int fixed = gRows.load(std::memory_order_relaxed);
    if (fixed > 0) return fixed;
    const uint64_t perBlock = (uint64_t(pairs) + kTargetBlocks - 1) / kTargetBlocks;
    return int(std::min<uint64_t>(std::max<uint64_t>((perBlock + kGroup - 1) / kGroup, 1), kMaxRows));
}

void TileSort::setRows(int rows) { gRows.store(rows >= 1 && rows <= kMaxRows ? rows : 0, std::memory_order_relaxed); }

bool TileSort::fits(const TileBins& bins) const {
    const int64_t limit = gBlockLimit.load(std::memory_order_relaxed);
    const int64_t maxBytes = limit > 0 ? std::min(limit, maxBlockBytes_) : maxBlockBytes_;
    const int64_t pairBytes = int64_t(bins.entryCount) * 4;
    const int64_t particleBytes = (int64_t(bins.particles.size()) + int64_t(bins.gpuParticles) * 2) * 4;
    return pairBytes <= maxBytes && particleBytes <= maxBytes;
}

void TileSort::setBlockLimit(int64_t bytes) { gBlockLimit.store(std::max<int64_t>(bytes, 0), std::memory_order_relaxed); }

void TileSort::ensureBuffer(uint32_t* buffer, size_t* capacity, size_t bytes) {
    if (!*buffer) glGenBuffers(1, buffer);
    if (bytes <= *capacity) return;
    // Grows only, to the next power of two (a growing count reallocates a few times, not each frame).
    size_t grown = 256;
    while (grown < bytes) grown *= 2;
    *capacity = grown;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, *buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(grown), nullptr, GL_DYNAMIC_COPY);
}

void TileSort::radixPass(uint32_t count, int shift, const uint32_t keys[2], const uint32_t entries[2], int from) {
    const int rows = rowsFor(count);
    const uint32_t blockPairs = kGroup * uint32_t(rows);
    const uint32_t blocks = (count + blockPairs - 1) / blockPairs;
    const uint32_t histogramLength = blocks * (1u << kDigitBits);
    ensureBuffer(&histogram_, &histogramCapacity_, size_t(histogramLength) * 4);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kHistogram, histogram_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kKeysIn, keys[from]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEntriesIn, entries[from]);
    // Count and scatter: one group a block, over the digit at `shift`.
    auto overBlocks = [&](uint32_t program, const Uniforms& u) {
        glUseProgram(program);
        glUniform1i(u.pairCount, int(count));
        glUniform1i(u.shift, shift);
        glUniform1i(u.blocks, int(blocks));
        glUniform1i(u.rows, rows);
        dispatch(blocks, u.groupsX);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    };
    overBlocks(count_, countU_);
    glUseProgram(scan_);
    glUniform1i(scanU_.length, int(histogramLength));
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kKeysOut, keys[from ^ 1]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEntriesOut, entries[from ^ 1]);
    overBlocks(scatter_, scatterU_);
}

namespace {
// Each particle's entry from its place (TileBins::orderStart, batchLast), in every program of the
// order that reads one.
void setBatches(const TileBins& places, int batchCountUniform, int orderStartUniform, int batchLastUniform) {
    glUniform1i(batchCountUniform, places.batchCount);
    glUniform1iv(orderStartUniform, places.batchCount + 1, places.orderStart);
    glUniform1iv(batchLastUniform, places.batchCount, places.batchLast);
}
}  // namespace

void TileSort::sortParticles(uint32_t n, const DepthOrder& order, const TileBins& places) {
    sorted_ = false;
    if (!orderOk() || n == 0) return;
    constexpr int kInstances = 3;
    for (int i = 0; i < 2; ++i) {
        ensureBuffer(&orderKeys_[i], &orderKeysCapacity_[i], size_t(n) * 4);
        ensureBuffer(&orderPlaces_[i], &orderPlacesCapacity_[i], size_t(n) * 4);
    }
    // Whatever read these buffers before (the last view's order) is done with them.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    // 1. Each particle's key (its depth's bits, ascending: front to back; 0 in a batch drawn in
    // pool order) and its place in the words (the sort's payload), in orderKeys_/orderPlaces_[0].
    // (The programs declare the words' block, which these two do not read: a store bound anyway.)
    ensureBuffer(&particles_, &particlesCapacity_, 16);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticleBinding, particles_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, orderKeys_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, orderPlaces_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstances, order.instances);
    glUseProgram(orderKey_);
    glUniform1i(orderKeyU_.particleCount, int(n));
    glUniform3f(orderKeyU_.eye, order.eye.x, order.eye.y, order.eye.z);
    glUniform3f(orderKeyU_.forward, order.forward.x, order.forward.y, order.forward.z);
    glUniform1ui(orderKeyU_.backToFront, order.backToFront);
    setBatches(places, orderKeyU_.batchCount, orderKeyU_.orderStart, orderKeyU_.batchLast);
    dispatch((n + kGroup - 1) / kGroup, orderKeyU_.groupsX);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    // 2. Sorted by depth (the radix passes are stable: equal depths keep the words' order, the
    // reverse of the pool's, as the CPU's list has them), then by batch, the last batch first.
    int from = 0;
    if (order.backToFront != 0) {
        for (int shift = 0; shift < 32; shift += kDigitBits, from ^= 1) radixPass(n, shift, orderKeys_, orderPlaces_, from);
    }
    if (order.batchCount > 1) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, orderKeys_[from]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, orderPlaces_[from]);
        glUseProgram(orderBatch_);
        glUniform1i(orderBatchU_.particleCount, int(n));
        setBatches(places, orderBatchU_.batchCount, orderBatchU_.orderStart, orderBatchU_.batchLast);
        dispatch((n + kGroup - 1) / kGroup, orderBatchU_.groupsX);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        for (int shift = 0; (order.batchCount - 1) >> shift; shift += kDigitBits, from ^= 1) {
            radixPass(n, shift, orderKeys_, orderPlaces_, from);
        }
    }
    sorted_ = true;
    sortedCount_ = n;
    sortedFrom_ = from;
}

void TileSort::orderParticles(uint32_t n, const TileBins& bins) {
    constexpr int kOrdered = 3, kSums = 4;
    constexpr uint32_t kPrefixBlock = 1024;  // cs_particles_tile_sort.glsl's particles a prefix group adds up
    // 3. The words in the sorted order, each with its first pair: the counts added up in blocks,
    // the blocks' sums scanned, each block's first added on.
    ensureBuffer(&ordered_, &orderedCapacity_, size_t(n) * 16);
    const uint32_t prefixGroups = (n + kPrefixBlock - 1) / kPrefixBlock;
    ensureBuffer(&histogram_, &histogramCapacity_, size_t(prefixGroups) * 4);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticleBinding, particles_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, orderPlaces_[sortedFrom_]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOrdered, ordered_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSums, histogram_);
    glUseProgram(orderPrefix_);
    glUniform1i(orderPrefixU_.particleCount, int(n));
    setBatches(bins, orderPrefixU_.batchCount, orderPrefixU_.orderStart, orderPrefixU_.batchLast);
    dispatch(prefixGroups, orderPrefixU_.groupsX);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(scan_);
    glUniform1i(scanU_.length, int(prefixGroups));
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(orderAdd_);
    glUniform1i(orderAddU_.particleCount, int(n));
    dispatch((n + kGroup - 1) / kGroup, orderAddU_.groupsX);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gGpuOrderedViews.fetch_add(1, std::memory_order_relaxed);
}

uint32_t TileSort::run(const TileBins& bins, const Jobs& jobs, const DepthOrder* order,
                       const std::function<void()>& afterEmit) {
    const bool sorted = sorted_;
    sorted_ = false;  // taken here (or dropped: a view that is not drawn)
    if (!ok() || !fits(bins) || (order && !orderOk())) return 0;
    const uint32_t pairs = bins.entryCount;
    // The words of the particles: four each, or (Fill::Ranges, only with an order) two; binned on
    // the GPU (with an order only), already in particles_.
    if (bins.wordsPerParticle != (order ? 2 : 4) || (order && order->batchCount != bins.batchCount)) return 0;
    if (bins.gpuParticles > 0 && !order) return 0;
    const uint32_t particleCount = bins.gpuParticles > 0 ? bins.gpuParticles
                                                         : uint32_t(bins.particles.size() / size_t(bins.wordsPerParticle));
    const size_t keyBytes = size_t(pairs) * 4;
    ensureBuffer(&keys_[0], &keysCapacity_[0], keyBytes);
    ensureBuffer(&entries_[0], &entriesCapacity_[0], keyBytes);
    if (pairs == 0 || particleCount == 0) return entries_[0];
    // Whatever read these buffers before (the last view's tile pass) is done with them.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    // 1. The particles (in front-to-back order: the CPU's, or order's), then the pairs in that order.
    if (bins.gpuParticles == 0) {
        ensureBuffer(&particles_, &particlesCapacity_, bins.particles.size() * 4);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, particles_);
        const size_t particleBytes = bins.particles.size() * 4;
        if (!copyMappedInPieces(GL_SHADER_STORAGE_BUFFER, bins.particles.data(), particleBytes, jobs)) {
            glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(particleBytes), bins.particles.data());
        }
    }
    if (order) {
        if (!sorted || sortedCount_ != particleCount) sortParticles(particleCount, *order, bins);
        sorted_ = false;
        orderParticles(particleCount, bins);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticleBinding, order ? ordered_ : particles_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, keys_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, entries_[0]);
    glUseProgram(emit_);
    glUniform1i(emitU_.particleCount, int(particleCount));
    glUniform1i(emitU_.pairCount, int(pairs));
    glUniform1i(emitU_.tilesX, bins.tilesX);
    dispatch((pairs + kGroup - 1) / kGroup, emitU_.groupsX);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    if (afterEmit) afterEmit();

    // 2. The radix passes by tile, from keys_/entries_[0] to [1] and back.
    const int passCount = passes(bins.tilesX * bins.tilesY);
    if (passCount == 0) return entries_[0];
    ensureBuffer(&keys_[1], &keysCapacity_[1], size_t(pairs) * 4);
    ensureBuffer(&entries_[1], &entriesCapacity_[1], size_t(pairs) * 4);
    int from = 0;
    for (int pass = 0; pass < passCount; ++pass, from ^= 1) radixPass(pairs, pass * kDigitBits, keys_, entries_, from);
    return entries_[from];
}

bool TileSort::binOnGpu(const ViewInfo& view, uint32_t instances, uint32_t particleCount, uint32_t sphereBatches,
                        const BillboardReach& reach, const TileBins& places, uint32_t* tileBuffer, size_t* tileCapacity) {
    binnedParticles_ = 0;
    constexpr int kTile = ScreenTiles::kTileSize;
    const int tilesX = (view.width + kTile - 1) / kTile, tilesY = (view.height + kTile - 1) / kTile;
    if (!binsOk() || particleCount == 0 || tilesX <= 0 || tilesY <= 0 || tilesX > 0xffff || tilesY > 0xffff ||
        places.batchCount > 32) {
        return false;
    }
    constexpr int kParticles = 0, kTiles = 1, kInstances = 3, kGrid = 4;
    // The grid: four words of header, then (tilesX + 1) x (tilesY + 1) cells, zero (LIST leaves
    // them so; a new store is made zero).
    const size_t gridBytes = (4 + size_t(tilesX + 1) * size_t(tilesY + 1)) * 4;
    if (!grid_) glGenBuffers(1, &grid_);
    if (gridBytes > gridCapacity_) {
        gridCapacity_ = gridBytes;
        const std::vector<int32_t> zeros(gridBytes / 4, 0);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, grid_);
        glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(gridBytes), zeros.data(), GL_DYNAMIC_COPY);
    }
    ensureBuffer(&particles_, &particlesCapacity_, size_t(particleCount) * 8);
    ensureBuffer(tileBuffer, tileCapacity, size_t(tilesX) * size_t(tilesY) * 16);
    // Whatever read these buffers before (the last view's lists and tiles) is done with them.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticles, particles_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstances, instances);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGrid, grid_);
    glUseProgram(bound_);
    const BinUniforms& u = boundU_;
    glUniform1i(u.particleCount, int(particleCount));
    setBatches(places, u.batchCount, u.orderStart, u.batchLast);
    glUniform1ui(u.sphereBatches, sphereBatches);
    glUniformMatrix4fv(u.view, 1, GL_FALSE, &view.view[0][0]);
    glUniformMatrix4fv(u.proj, 1, GL_FALSE, &view.proj[0][0]);
    glUniform1f(u.nearPlane, view.nearPlane);
    glUniform2i(u.viewSize, view.width, view.height);
    glUniform2i(u.tiles, tilesX, tilesY);
    const bool perspective = footprint::plainPerspective(view.proj);
    glUniform1i(u.perspective, perspective ? 1 : 0);
    static_assert(BillboardReach::kRows * BillboardReach::kEntries == 40, "cs_particles_tile_sort.glsl's uReach[40]");
    static_assert(BillboardReach::kEntries == 8, "its rows of 8");
    glUniform1f(u.reachLodScale, reach.lodScale > 0.0f && reach.buckets > 0 ? reach.lodScale : 0.0f);
    glUniform1i(u.reachBuckets, std::max(reach.buckets, 1));
    glUniform1fv(u.reach, BillboardReach::kRows * BillboardReach::kEntries, reach.table.data());
    dispatch((particleCount + kGroup - 1) / kGroup, u.groupsX);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTiles, *tileBuffer);
    glUseProgram(list_);
    glUniform2i(listU_.tiles, tilesX, tilesY);
    // The grid summed along every row at once (a group each), then down every column, then the
    // tiles listed by one group: a single group's lanes walking whole rows and columns one cell
    // after another would put the grid's every cell in one chain of memory round trips.
    glUniform1i(listU_.phase, 0);
    glDispatchCompute(GLuint(tilesY), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUniform1i(listU_.phase, 1);
    glDispatchCompute(GLuint(tilesX), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUniform1i(listU_.phase, 2);
    glDispatchCompute(1, 1, 1);
    // The tiles for the shade, the header for the CPU's read.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    binnedParticles_ = particleCount;
    binnedTiles_ = *tileBuffer;
    binnedTilesX_ = tilesX;
    binnedTilesY_ = tilesY;
    binnedWidth_ = view.width;
    binnedHeight_ = view.height;
    return true;
}

bool TileSort::readGpuBins(TileBins* bins) {
    const uint32_t n = binnedParticles_;
    binnedParticles_ = 0;
    if (n == 0 || !grid_) return false;
    // The header: LIST's entries, tiles and what failed.
    int32_t header[4] = {};
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, grid_);
    const void* mapped = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, sizeof header, GL_MAP_READ_BIT);
    if (!mapped) return false;
    std::memcpy(header, mapped, sizeof header);
    glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
    if (header[3] != 0 || header[1] < 0 || header[2] < 0 || int64_t(header[2]) > int64_t(binnedTilesX_) * binnedTilesY_) {
        return false;
    }
    bins->particles.clear();
    bins->entries.clear();
    bins->wordsPerParticle = 2;
    bins->gpuParticles = n;
    bins->entryCount = uint32_t(header[1]);
    bins->tilesX = binnedTilesX_;
    bins->tilesY = binnedTilesY_;
    // The tiles, for the composite's runs (the shade reads them where they are).
    bins->tiles.resize(size_t(header[2]) * 4);
    if (header[2] > 0) {
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, binnedTiles_);
        const size_t bytes = bins->tiles.size() * 4;
        mapped = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(bytes), GL_MAP_READ_BIT);
        if (!mapped) return false;
        std::memcpy(bins->tiles.data(), mapped, bytes);
        glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
    }
    coverTiles(bins, binnedWidth_, binnedHeight_);
    return true;
}

}  // namespace fx
