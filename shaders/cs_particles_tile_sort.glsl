#version 430 core
// The tiled path's lists written on the GPU (fx_plugin/render/TileSort.h): the CPU bounded the
// particles and counted each tile's entries (TileBins.h); what grows with the entries (millions
// at 256,000 particles) is done here, in four programs:
//   FX_TILE_EMIT: one invocation per pair writes it: (tile, entry) of its particle, each particle's
//     tiles row by row from its first pair on: the pairs in particle order, front to back.
//   FX_TILE_COUNT, FX_TILE_SCAN, FX_TILE_SCATTER: one pass of a stable radix sort of the pairs by
//     tile, kDigitBits bits of the tile at a time from the lowest. A block of uRows rows of kGroup
//     pairs (TileSort::rowsFor: few rows, so many blocks, where the pairs are few) counts its digits (COUNT); one group adds the counts up digit by digit, block by block
//     (SCAN: each block's first place for each digit); the block writes each pair to its digit's
//     place plus the pairs of that digit before it in the block (SCATTER). Stable, so after the
//     last pass each tile's pairs are in particle order: front to back, the CPU's lists bit for bit.
// The pairs' keys and entries are separate arrays (std430 uint); the histogram is digit-major.

const uint kDigitBits = 4u;
const uint kDigits = 16u;
const uint kGroup = 256u;
uniform int uRows;  // a block: uRows rows of kGroup pairs (1 .. TileSort::kMaxRows; COUNT, SCATTER)

uniform int uGroupsX;  // groups per row of the dispatch (a row holds at most 65,535)

uint groupIndex() { return gl_WorkGroupID.y * uint(uGroupsX) + gl_WorkGroupID.x; }

#if defined(FX_TILE_EMIT)
layout(local_size_x = 256) in;
// Per particle, front to back (TileBins::particles): tx0 | tx1 << 16, ty0 | ty1 << 16, first pair, entry.
layout(std430, binding = 0) readonly buffer Particles { uvec4 uParticles[]; };
layout(std430, binding = 1) writeonly buffer KeysOut { uint uKeysOut[]; };
layout(std430, binding = 2) writeonly buffer EntriesOut { uint uEntriesOut[]; };
uniform int uParticleCount;
uniform int uPairCount;
uniform int uTilesX;

// One invocation per pair, not per particle: a particle over 2,000 tiles written by one
// invocation kept one group busy for the whole pass while the GPU idled (the fill scene's 250
// large puffs: one group of 256 for 520,000 pairs). The pair's particle is the last whose first
// pair is not past it (a particle with no tiles has the next one's first pair: never chosen for a
// pair, as that one follows it); its tile is the pair's place in the particle's range, row by row.
void main() {
    uint i = groupIndex() * kGroup + gl_LocalInvocationID.x;
    if (i >= uint(uPairCount)) return;
    uint lo = 0u, hi = uint(uParticleCount) - 1u;
    while (lo < hi) {
        uint mid = (lo + hi + 1u) >> 1u;
        if (uParticles[mid].z <= i) lo = mid; else hi = mid - 1u;
    }
    uvec4 p = uParticles[lo];
    uint x0 = p.x & 0xffffu, x1 = p.x >> 16u, y0 = p.y & 0xffffu;
    uint width = x1 - x0 + 1u;
    uint local = i - p.z;
    uKeysOut[i] = (y0 + local / width) * uint(uTilesX) + x0 + local % width;
    uEntriesOut[i] = p.w;
}

#elif defined(FX_TILE_COUNT)
layout(local_size_x = 256) in;
layout(std430, binding = 1) readonly buffer KeysIn { uint uKeysIn[]; };
layout(std430, binding = 4) writeonly buffer Histogram { uint uHistogram[]; };  // [digit * blocks + block]
uniform int uPairCount;
uniform int uShift;
uniform int uBlocks;
shared uint sCounts[kDigits];

void main() {
    uint block = groupIndex();
    if (block >= uint(uBlocks)) return;  // the whole group: no barrier is skipped by some only
    uint lane = gl_LocalInvocationID.x;
    if (lane < kDigits) sCounts[lane] = 0u;
    barrier();
    uint rows = uint(uRows);
    for (uint row = 0u; row < rows; ++row) {
        uint i = (block * rows + row) * kGroup + lane;
        if (i < uint(uPairCount)) atomicAdd(sCounts[(uKeysIn[i] >> uint(uShift)) & (kDigits - 1u)], 1u);
    }
    barrier();
    if (lane < kDigits) uHistogram[lane * uint(uBlocks) + block] = sCounts[lane];
}

#elif defined(FX_TILE_SCAN)
layout(local_size_x = 1024) in;
layout(std430, binding = 4) buffer Histogram { uint uHistogram[]; };
uniform int uLength;
shared uint sSums[1024];

// Exclusive sums of uHistogram in place, by one group: each invocation adds up its stretch, the
// group scans the 1,024 sums, each invocation writes its stretch's running sums.
void main() {
    uint lane = gl_LocalInvocationID.x;
    uint n = uint(uLength);
    uint stretch = (n + 1023u) / 1024u;
    uint begin = min(lane * stretch, n), end = min(begin + stretch, n);
    uint sum = 0u;
    for (uint i = begin; i < end; ++i) sum += uHistogram[i];
    sSums[lane] = sum;
    barrier();
    for (uint offset = 1u; offset < 1024u; offset <<= 1u) {
        uint before = lane >= offset ? sSums[lane - offset] : 0u;
        barrier();
        sSums[lane] += before;
        barrier();
    }
    uint running = sSums[lane] - sum;
    for (uint i = begin; i < end; ++i) {
        uint v = uHistogram[i];
        uHistogram[i] = running;
        running += v;
    }
}

#elif defined(FX_TILE_SCATTER)
layout(local_size_x = 256) in;
layout(std430, binding = 1) readonly buffer KeysIn { uint uKeysIn[]; };
layout(std430, binding = 2) readonly buffer EntriesIn { uint uEntriesIn[]; };
layout(std430, binding = 3) writeonly buffer KeysOut { uint uKeysOut[]; };
layout(std430, binding = 0) writeonly buffer EntriesOut { uint uEntriesOut[]; };
layout(std430, binding = 4) readonly buffer Histogram { uint uHistogram[]; };
uniform int uPairCount;
uniform int uShift;
uniform int uBlocks;
shared uint sPlace[kDigits];            // the next place of each digit
shared uint sMask[kDigits * kGroup / 32u];  // per digit, a bit per lane of the row holding it

void main() {
    uint block = groupIndex();
    if (block >= uint(uBlocks)) return;
    uint lane = gl_LocalInvocationID.x;
    if (lane < kDigits) sPlace[lane] = uHistogram[lane * uint(uBlocks) + block];
    uint word = lane >> 5u, bit = 1u << (lane & 31u);
    uint rows = uint(uRows);
    for (uint row = 0u; row < rows; ++row) {
        if (lane < kDigits * kGroup / 32u) sMask[lane] = 0u;
        barrier();
        uint i = (block * rows + row) * kGroup + lane;
        bool live = i < uint(uPairCount);
        uint key = 0u, entry = 0u, digit = 0u;
        if (live) {
            key = uKeysIn[i];
            entry = uEntriesIn[i];
            digit = (key >> uint(uShift)) & (kDigits - 1u);
            atomicOr(sMask[digit * 8u + word], bit);
        }
        barrier();
        if (live) {
            // The lanes before this one with the same digit: the bits below it.
            uint rank = uint(bitCount(sMask[digit * 8u + word] & (bit - 1u)));
            for (uint w = 0u; w < word; ++w) rank += uint(bitCount(sMask[digit * 8u + w]));
            uint place = sPlace[digit] + rank;
            uKeysOut[place] = key;
            uEntriesOut[place] = entry;
        }
        barrier();
        if (lane < kDigits) {
            uint total = 0u;
            for (uint w = 0u; w < 8u; ++w) total += uint(bitCount(sMask[lane * 8u + w]));
            sPlace[lane] += total;
        }
        barrier();
    }
}
#endif
