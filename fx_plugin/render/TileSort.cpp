#include "TileSort.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdlib>

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
    const uint32_t buffers[11] = {particles_,    keys_[0],      keys_[1],       entries_[0],
                                  entries_[1],   histogram_,    ordered_,       orderKeys_[0],
                                  orderKeys_[1], orderPlaces_[0], orderPlaces_[1]};
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
    const int64_t particleBytes = int64_t(bins.particles.size()) * 4;
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

uint32_t TileSort::run(const TileBins& bins, const Jobs& jobs, const DepthOrder* order) {
    const bool sorted = sorted_;
    sorted_ = false;  // taken here (or dropped: a view that is not drawn)
    if (!ok() || !fits(bins) || (order && !orderOk())) return 0;
    const uint32_t pairs = bins.entryCount;
    // The words of the particles: four each, or (Fill::Ranges, only with an order) two.
    if (bins.wordsPerParticle != (order ? 2 : 4) || (order && order->batchCount != bins.batchCount)) return 0;
    const uint32_t particleCount = uint32_t(bins.particles.size() / size_t(bins.wordsPerParticle));
    const size_t keyBytes = size_t(pairs) * 4;
    ensureBuffer(&keys_[0], &keysCapacity_[0], keyBytes);
    ensureBuffer(&entries_[0], &entriesCapacity_[0], keyBytes);
    if (pairs == 0 || particleCount == 0) return entries_[0];
    // Whatever read these buffers before (the last view's tile pass) is done with them.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    // 1. The particles (in front-to-back order: the CPU's, or order's), then the pairs in that order.
    ensureBuffer(&particles_, &particlesCapacity_, bins.particles.size() * 4);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, particles_);
    const size_t particleBytes = bins.particles.size() * 4;
    if (!copyMappedInPieces(GL_SHADER_STORAGE_BUFFER, bins.particles.data(), particleBytes, jobs)) {
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(particleBytes), bins.particles.data());
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

    // 2. The radix passes by tile, from keys_/entries_[0] to [1] and back.
    const int passCount = passes(bins.tilesX * bins.tilesY);
    if (passCount == 0) return entries_[0];
    ensureBuffer(&keys_[1], &keysCapacity_[1], size_t(pairs) * 4);
    ensureBuffer(&entries_[1], &entriesCapacity_[1], size_t(pairs) * 4);
    int from = 0;
    for (int pass = 0; pass < passCount; ++pass, from ^= 1) radixPass(pairs, pass * kDigitBits, keys_, entries_, from);
    return entries_[from];
}

}  // namespace fx
