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
//   FX_TILE_ORDER_KEY, FX_TILE_ORDER_BATCH, FX_TILE_ORDER_PREFIX, FX_TILE_ORDER_ADD: the particles
//     of a list built without its back-to-front sort (TileSort::DepthOrder) put in front-to-back
//     order before the emit: a key per particle (its depth's bits), the radix passes above over
//     those keys, then over its batch (BATCH rekeys), and the pair counts added up in that order
//     (PREFIX: each group's 1,024, SCAN: the groups' sums, ADD: each group's first added on).
// The pairs' keys and entries are separate arrays (std430 uint); the histogram is digit-major.

const uint kDigitBits = 4u;
const uint kDigits = 16u;
const uint kGroup = 256u;
uniform int uRows;  // a block: uRows rows of kGroup pairs (1 .. TileSort::kMaxRows; COUNT, SCATTER)

uniform int uGroupsX;  // groups per row of the dispatch (a row holds at most 65,535)

uint groupIndex() { return gl_WorkGroupID.y * uint(uGroupsX) + gl_WorkGroupID.x; }

#if defined(FX_TILE_ORDER_KEY) || defined(FX_TILE_ORDER_BATCH) || defined(FX_TILE_ORDER_PREFIX)
// The words of an unsorted list's particles (TileBins::particles with Fill::Ranges, binned as the
// list lies, front to back): two a particle, its tile range. Its entry (instance | batch << 26)
// comes from its place k (TileBins::orderStart, batchLast): in the j-th batch from the back, the
// batch's last instance first.
layout(std430, binding = 0) readonly buffer Particles { uvec2 uRanges[]; };
uniform int uBatchCount;
uniform int uOrderStart[65];
uniform int uBatchLast[64];

uint entryOf(uint k) {
    int j = 0;
    while (j + 1 < uBatchCount && uint(uOrderStart[j + 1]) <= k) ++j;
    int b = uBatchCount - 1 - j;
    return uint(uBatchLast[b] - (int(k) - uOrderStart[j])) | (uint(b) << 26u);
}
#endif

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

#elif defined(FX_TILE_ORDER_KEY)
layout(local_size_x = 256) in;
layout(std430, binding = 1) writeonly buffer KeysOut { uint uKeysOut[]; };
layout(std430, binding = 2) writeonly buffer EntriesOut { uint uEntriesOut[]; };
// InstanceStream's ParticleInstance: (x, y, z, size), (life, rotation, fade, frame).
layout(std430, binding = 3) readonly buffer Instances { vec4 uInstances[]; };
uniform int uParticleCount;
uniform vec3 uEye;
uniform vec3 uForward;     // viewForward (DrawList.h)
uniform uint uBackToFront;  // a bit per batch drawn back to front

// The key's ascending order is front to back: the depth as DrawListBuilder works it out, to the
// bit (`precise`: the same products and sums, none fused), -0 as +0, and its bits mapped so that
// their unsigned order is the float's (negative ones flipped, positive ones with the sign set):
// the reverse of the CPU's descendingKey. A batch drawn in pool order keys 0 (the order stays).
// The payload is the particle's place in the words.
void main() {
    uint k = groupIndex() * kGroup + gl_LocalInvocationID.x;
    if (k >= uint(uParticleCount)) return;
    uint entry = entryOf(k);
    uint key = 0u;
    if (((uBackToFront >> (entry >> 26u)) & 1u) != 0u) {
        vec3 p = uInstances[(entry & 0x3ffffffu) * 2u].xyz;
        precise float depth = (p.x - uEye.x) * uForward.x + (p.y - uEye.y) * uForward.y + (p.z - uEye.z) * uForward.z;
        uint bits = floatBitsToUint(depth);
        if (bits == 0x80000000u) bits = 0u;
        key = (bits & 0x80000000u) != 0u ? ~bits : (bits | 0x80000000u);
    }
    uKeysOut[k] = key;
    uEntriesOut[k] = k;
}

#elif defined(FX_TILE_ORDER_BATCH)
layout(local_size_x = 256) in;
layout(std430, binding = 1) writeonly buffer KeysOut { uint uKeysOut[]; };
layout(std430, binding = 2) readonly buffer EntriesIn { uint uEntriesIn[]; };
uniform int uParticleCount;

// Each particle's key becomes its batch, the last first (TileBins' front-to-back order).
void main() {
    uint s = groupIndex() * kGroup + gl_LocalInvocationID.x;
    if (s >= uint(uParticleCount)) return;
    uKeysOut[s] = uint(uBatchCount - 1) - (entryOf(uEntriesIn[s]) >> 26u);
}

#elif defined(FX_TILE_ORDER_PREFIX)
layout(local_size_x = 256) in;
layout(std430, binding = 2) readonly buffer EntriesIn { uint uEntriesIn[]; };  // the sorted places
layout(std430, binding = 3) writeonly buffer Ordered { uvec4 uOrdered[]; };
layout(std430, binding = 4) writeonly buffer Sums { uint uSums[]; };
uniform int uParticleCount;
shared uint sSums[256];

// A particle's pairs: its tile range's tiles (none where tx0 > tx1).
uint pairsOf(uvec2 w) {
    uint x0 = w.x & 0xffffu, x1 = w.x >> 16u, y0 = w.y & 0xffffu, y1 = w.y >> 16u;
    return x0 > x1 ? 0u : (x1 - x0 + 1u) * (y1 - y0 + 1u);
}

// Each group: 1,024 sorted places, four per invocation; their ranges in order, each with its first
// pair within the group and its entry, and the group's sum.
void main() {
    uint lane = gl_LocalInvocationID.x;
    uint first = groupIndex() * 1024u + lane * 4u;
    uint n = uint(uParticleCount);
    uvec2 words[4];
    uint entries[4];
    uint counts[4];
    uint sum = 0u;
    for (int j = 0; j < 4; ++j) {
        uint s = first + uint(j);
        uint k = s < n ? uEntriesIn[s] : 0u;
        words[j] = s < n ? uRanges[k] : uvec2(1u, 1u);
        entries[j] = s < n ? entryOf(k) : 0u;
        counts[j] = s < n ? pairsOf(words[j]) : 0u;
        sum += counts[j];
    }
    sSums[lane] = sum;
    barrier();
    for (uint offset = 1u; offset < 256u; offset <<= 1u) {
        uint before = lane >= offset ? sSums[lane - offset] : 0u;
        barrier();
        sSums[lane] += before;
        barrier();
    }
    uint running = sSums[lane] - sum;
    for (int j = 0; j < 4; ++j) {
        uint s = first + uint(j);
        if (s < n) uOrdered[s] = uvec4(words[j].x, words[j].y, running, entries[j]);
        running += counts[j];
    }
    if (lane == 255u) uSums[groupIndex()] = sSums[255];
}

#elif defined(FX_TILE_ORDER_ADD)
layout(local_size_x = 256) in;
layout(std430, binding = 3) buffer Ordered { uvec4 uOrdered[]; };
layout(std430, binding = 4) readonly buffer Sums { uint uSums[]; };  // scanned: each group's first pair
uniform int uParticleCount;

void main() {
    uint s = groupIndex() * kGroup + gl_LocalInvocationID.x;
    if (s >= uint(uParticleCount)) return;
    uOrdered[s].z += uSums[s >> 10u];
}
#endif
