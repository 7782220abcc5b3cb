#include "TileSort.h"

#include <algorithm>
#include <atomic>
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

// `groups` work groups in rows of at most 65,535 (the least GL_MAX_COMPUTE_WORK_GROUP_COUNT),
// the row length in the program's uGroupsX.
void dispatch(uint32_t groups, int groupsXUniform) {
    if (groups == 0) return;
    const uint32_t groupsX = std::min<uint32_t>(groups, 65535u);
    glUniform1i(groupsXUniform, int(groupsX));
    glDispatchCompute(groupsX, (groups + groupsX - 1) / groupsX, 1);
}

}  // namespace

TileSort::~TileSort() {
    // The renderer deletes its GL objects with the context current (~ParticleRenderer).
    if (!privateGlContextCurrent()) return;
    const uint32_t buffers[6] = {particles_, keys_[0], keys_[1], entries_[0], entries_[1], histogram_};
    for (uint32_t b : buffers) {
        if (b) glDeleteBuffers(1, &b);
    }
}

void TileSort::bind(const ProgramCache& programs) {
    emit_ = programs.passProgram(ProgramCache::TileEmit);
    count_ = programs.passProgram(ProgramCache::TileSortCount);
    scan_ = programs.passProgram(ProgramCache::TileSortScan);
    scatter_ = programs.passProgram(ProgramCache::TileSortScatter);
    const uint32_t progs[4] = {emit_, count_, scan_, scatter_};
    Uniforms* uniforms[4] = {&emitU_, &countU_, &scanU_, &scatterU_};
    for (int p = 0; p < 4; ++p) {
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
    const int64_t pairBytes = int64_t(bins.entryCount) * 4;
    const int64_t particleBytes = int64_t(bins.particles.size()) * 4;
    return pairBytes <= maxBlockBytes_ && particleBytes <= maxBlockBytes_;
}

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

uint32_t TileSort::run(const TileBins& bins, const Jobs& jobs) {
    if (!ok() || !fits(bins)) return 0;
    const uint32_t pairs = bins.entryCount;
    const uint32_t particleCount = uint32_t(bins.particles.size() / 4);
    ensureBuffer(&keys_[0], &keysCapacity_[0], size_t(pairs) * 4);
    ensureBuffer(&entries_[0], &entriesCapacity_[0], size_t(pairs) * 4);
    if (pairs == 0 || particleCount == 0) return entries_[0];
    // Whatever read these buffers before (the last view's tile pass) is done with them.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    // 1. The pairs, in particle order.
    ensureBuffer(&particles_, &particlesCapacity_, bins.particles.size() * 4);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, particles_);
    const size_t particleBytes = bins.particles.size() * 4;
    if (!copyMappedInPieces(GL_SHADER_STORAGE_BUFFER, bins.particles.data(), particleBytes, jobs)) {
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(particleBytes), bins.particles.data());
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticleBinding, particles_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, keys_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, entries_[0]);
    glUseProgram(emit_);
    glUniform1i(emitU_.particleCount, int(particleCount));
    glUniform1i(emitU_.pairCount, int(pairs));
    glUniform1i(emitU_.tilesX, bins.tilesX);
    dispatch((pairs + kGroup - 1) / kGroup, emitU_.groupsX);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    // 2. The radix passes, from keys_/entries_[0] to [1] and back.
    const int passCount = passes(bins.tilesX * bins.tilesY);
    if (passCount == 0) return entries_[0];
    ensureBuffer(&keys_[1], &keysCapacity_[1], size_t(pairs) * 4);
    ensureBuffer(&entries_[1], &entriesCapacity_[1], size_t(pairs) * 4);
    const int rows = rowsFor(pairs);
    const uint32_t blockPairs = kGroup * uint32_t(rows);
    const uint32_t blocks = (pairs + blockPairs - 1) / blockPairs;
    const uint32_t histogramLength = blocks * (1u << kDigitBits);
    ensureBuffer(&histogram_, &histogramCapacity_, size_t(histogramLength) * 4);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kHistogram, histogram_);
    // Count and scatter: one group a block, over the pairs' digit at `shift`.
    auto overBlocks = [&](uint32_t program, const Uniforms& u, int shift) {
        glUseProgram(program);
        glUniform1i(u.pairCount, int(pairs));
        glUniform1i(u.shift, shift);
        glUniform1i(u.blocks, int(blocks));
        glUniform1i(u.rows, rows);
        dispatch(blocks, u.groupsX);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    };
    int from = 0;
    for (int pass = 0; pass < passCount; ++pass, from ^= 1) {
        const int shift = pass * kDigitBits;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kKeysIn, keys_[from]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEntriesIn, entries_[from]);
        overBlocks(count_, countU_, shift);
        glUseProgram(scan_);
        glUniform1i(scanU_.length, int(histogramLength));
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kKeysOut, keys_[from ^ 1]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEntriesOut, entries_[from ^ 1]);
        overBlocks(scatter_, scatterU_, shift);
    }
    return entries_[from];
}

}  // namespace fx
