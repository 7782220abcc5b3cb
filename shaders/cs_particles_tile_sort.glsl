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
//   FX_TILE_BOUND, FX_TILE_LIST: the bins themselves (TileSort::binOnGpu, for a view whose particles
//     the GPU orders): each particle's tile range as binParticles (TileBins.cpp) works it out, the
//     same operations in the same order (FootprintMath.h), and its corners marked in a difference
//     grid (BOUND, one invocation per particle); then the grid is added up into each tile's count
//     (LIST's first two phases: a group per row, then per column) and one group lists the tiles
//     that hold particles, row-major, each with its first entry (its third).
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

#if defined(FX_TILE_ORDER_KEY) || defined(FX_TILE_ORDER_BATCH) || defined(FX_TILE_ORDER_PREFIX) || defined(FX_TILE_BOUND)
// The words of an unsorted list's particles (TileBins::particles with Fill::Ranges, binned as the
// list lies, front to back): two a particle, its tile range. Its entry (instance | batch << 26)
// comes from its place k (TileBins::orderStart, batchLast): in the j-th batch from the back, the
// batch's last instance first. FX_TILE_BOUND writes them (the GPU's bins), the others read them.
#ifdef FX_TILE_BOUND
layout(std430, binding = 0) writeonly buffer Particles { uvec2 uRanges[]; };
#else
layout(std430, binding = 0) readonly buffer Particles { uvec2 uRanges[]; };
#endif
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
#elif defined(FX_TILE_BOUND)
layout(local_size_x = 256) in;
// InstanceStream's ParticleInstance: (x, y, z, size), (life, rotation, fade, frame).
layout(std430, binding = 3) readonly buffer Instances { vec4 uInstances[]; };
// [0]: 1 where a particle has no bound (not finite: the view is drawn another way), [1] [2] [3]:
// LIST's; from kGridStart on the (uTiles.x + 1) x (uTiles.y + 1) difference grid, zero on entry.
layout(std430, binding = 4) buffer Grid { int uGrid[]; };
const int kGridStart = 4;
uniform int uParticleCount;
uniform uint uSphereBatches;    // a bit per batch drawn as spheres (Footprint::Box of half-size 0.5)
uniform mat4 uView;
uniform mat4 uProj;
uniform float uNearPlane;
uniform ivec2 uViewSize;
uniform ivec2 uTiles;
uniform int uPerspective;       // plainPerspective(uProj)
uniform float uReachLodScale;   // BillboardReach::lodScale; 0: no table (the quads' reach)
uniform int uReachBuckets;
uniform float uReach[40];       // BillboardReach::table: (TrimmedShapes::kFrames + 1) rows of 8

// BillboardReach::at.
float reachAt(float frame, float texelsPerPixel) {
    precise float f = frame + 0.5;
    int row = f >= 0.0 && f < 4.0 ? int(f) : 4;
    uint bits = floatBitsToUint(texelsPerPixel);
    int e = int((bits >> 23u) & 0xffu) - 127;
    int bucket = e + 1 + ((bits & 0x7fffffu) > 0x3504f3u ? 1 : 0);
    return uReach[row * 8 + min(max(bucket, 0), uReachBuckets - 1)];
}

bool finite(float v) { return !isinf(v) && !isnan(v); }

// NDC to pixels (footprint::toPixel).
float toPixel(float ndc, int size) {
    precise float p = (ndc * 0.5 + 0.5) * float(size);
    return p;
}

// TileRangeOf::tileOf.
int tileOf(float pixel, int tiles) {
    precise float t = pixel * (1.0 / 16.0);
    return int(min(max(t, 0.0), float(tiles - 1)));
}

void main() {
    uint k = groupIndex() * kGroup + gl_LocalInvocationID.x;
    if (k >= uint(uParticleCount)) return;
    uint entry = entryOf(k);
    uint instance = entry & 0x3ffffffu;
    vec4 p = uInstances[instance * 2u];
    float frame = uInstances[instance * 2u + 1u].w;
    bool billboard = ((uSphereBatches >> (entry >> 26u)) & 1u) == 0u;
    // FootprintMath::centre, then perspective<Flat> or general, then state().
    precise vec3 c;
    c.x = uView[0][0] * p.x + uView[1][0] * p.y + uView[2][0] * p.z + uView[3][0];
    c.y = uView[0][1] * p.x + uView[1][1] * p.y + uView[2][1] * p.z + uView[3][1];
    c.z = uView[0][2] * p.x + uView[1][2] * p.y + uView[2][2] * p.z + uView[3][2];
    precise float radius = (billboard ? 0.71 : 0.5) * p.w;
    precise float depthExtent = billboard ? 0.0 : radius;
    // 0 bounded, 1 behind, 2 unbounded.
    int state;
    if (!(finite(c.x) && finite(c.y) && finite(c.z) && finite(radius))) {
        state = 2;
    } else {
        precise float back = c.z - depthExtent, front = c.z + depthExtent;
        state = back >= -uNearPlane ? 1 : front >= -uNearPlane ? 2 : 0;
    }
    precise float plo[2], phi[2];
    if (uPerspective != 0) {
        precise float nearInv = 1.0 / -(c.z + depthExtent);
        precise float farInv = billboard ? nearInv : 1.0 / -(c.z - depthExtent);
        for (int a = 0; a < 2; ++a) {
            precise float lowEdge = uProj[a][a] * (c[a] - radius) + uProj[3][a];
            precise float highEdge = uProj[a][a] * (c[a] + radius) + uProj[3][a];
            if (billboard) {
                plo[a] = lowEdge * nearInv - uProj[2][a];
                phi[a] = highEdge * nearInv - uProj[2][a];
            } else {
                plo[a] = min(lowEdge * nearInv, lowEdge * farInv) - uProj[2][a];
                phi[a] = max(highEdge * nearInv, highEdge * farInv) - uProj[2][a];
            }
        }
        if (billboard && uReachLodScale > 0.0) {
            // The trimmed polygon's reach (BillboardReach), about the same centre.
            precise float depth = max(-c.z, uNearPlane);
            precise float texels = uReachLodScale * depth / max(p.w, 1e-6);
            precise float tight = reachAt(frame, texels) * p.w;
            for (int a = 0; a < 2; ++a) {
                plo[a] = (uProj[a][a] * (c[a] - tight) + uProj[3][a]) * nearInv - uProj[2][a];
                phi[a] = (uProj[a][a] * (c[a] + tight) + uProj[3][a]) * nearInv - uProj[2][a];
            }
        }
    } else {
        plo[0] = plo[1] = 1e30;
        phi[0] = phi[1] = -1e30;
        if (state == 0) {
            int corners = depthExtent > 0.0 ? 8 : 4;
            for (int corner = 0; corner < corners; ++corner) {
                precise vec3 q = c + vec3((corner & 1) != 0 ? radius : -radius, (corner & 2) != 0 ? radius : -radius,
                                          (corner & 4) != 0 ? depthExtent : -depthExtent);
                // glm's mat4 * vec4: (m0 x + m1 y) + (m2 z + m3 w), w = 1.
                precise vec4 clip = (uProj[0] * q.x + uProj[1] * q.y) + (uProj[2] * q.z + uProj[3]);
                for (int a = 0; a < 2; ++a) {
                    precise float ndc = clip[a] / clip.w;
                    plo[a] = min(plo[a], ndc);
                    phi[a] = max(phi[a], ndc);
                }
            }
        }
    }
    precise float x0 = toPixel(plo[0], uViewSize.x), x1 = toPixel(phi[0], uViewSize.x);
    precise float y0 = toPixel(plo[1], uViewSize.y), y1 = toPixel(phi[1], uViewSize.y);
    // TileRangeOf, grown by a pixel.
    ivec4 r;
    if (state == 2) {
        if (!(finite(p.x) && finite(p.y) && finite(p.z) && finite(p.w))) {
            uGrid[0] = 1;
            uRanges[k] = uvec2(1u, 1u);
            return;
        }
        r = ivec4(0, uTiles.x - 1, 0, uTiles.y - 1);  // a sphere across the near plane: every tile
    } else if (state == 1 || x1 < -1.0 || y1 < -1.0 || x0 > float(uViewSize.x + 1) || y0 > float(uViewSize.y + 1)) {
        uRanges[k] = uvec2(1u, 1u);  // tx0 1 > tx1 0: none
        return;
    } else {
        r = ivec4(tileOf(x0 - 1.0, uTiles.x), tileOf(x1 + 1.0, uTiles.x), tileOf(y0 - 1.0, uTiles.y),
                  tileOf(y1 + 1.0, uTiles.y));
    }
    uRanges[k] = uvec2(uint(r.x) | (uint(r.y) << 16u), uint(r.z) | (uint(r.w) << 16u));
    int stride = uTiles.x + 1;
    atomicAdd(uGrid[kGridStart + r.z * stride + r.x], 1);
    atomicAdd(uGrid[kGridStart + r.z * stride + r.y + 1], -1);
    atomicAdd(uGrid[kGridStart + (r.w + 1) * stride + r.x], -1);
    atomicAdd(uGrid[kGridStart + (r.w + 1) * stride + r.y + 1], 1);
}

#elif defined(FX_TILE_LIST)
layout(local_size_x = 1024) in;
// BOUND's grid, read back by the CPU: [1] the entries (0x7fffffff where they pass 2^31 - 1), [2]
// the tiles listed, [3] 1 where the entries passed 2^31 - 1, | 2 where a particle had no bound
// (BOUND's [0], zeroed here with the grid for the next view).
layout(std430, binding = 4) coherent buffer Grid { int uGrid[]; };
// The tiles that hold particles, row-major: (tile x, tile y, first entry, entry count).
layout(std430, binding = 1) writeonly buffer Listed { uvec4 uListed[]; };
uniform ivec2 uTiles;
uniform int uPhase;  // 0: the rows (a group each), 1: the columns (a group each), 2: the list (one group)
const int kGridStart = 4;
shared uint sTiles[1024];
shared uint sEntries[1024];
shared int sLine[1024];

// Inclusive sums in place along one line of the grid (`length` cells from `first`, `step` apart),
// a stretch a lane: each lane's sum, the lanes' sums scanned, each stretch's running sums written.
void sumLine(int first, int step, int length) {
    uint lane = gl_LocalInvocationID.x;
    int stretch = (length + 1023) / 1024;
    int begin = min(int(lane) * stretch, length), end = min(begin + stretch, length);
    int sum = 0;
    for (int i = begin; i < end; ++i) sum += uGrid[kGridStart + first + i * step];
    sLine[lane] = sum;
    barrier();
    for (uint offset = 1u; offset < 1024u; offset <<= 1u) {
        int before = lane >= offset ? sLine[lane - offset] : 0;
        barrier();
        sLine[lane] += before;
        barrier();
    }
    int running = sLine[lane] - sum;
    for (int i = begin; i < end; ++i) {
        running += uGrid[kGridStart + first + i * step];
        uGrid[kGridStart + first + i * step] = running;
    }
}

// Inclusive sums over the group's lanes, saturating at 2^31 (entries past 2^31 - 1 fail the view).
uint scan(uint value, bool entries) {
    uint lane = gl_LocalInvocationID.x;
    if (entries) sEntries[lane] = value; else sTiles[lane] = value;
    barrier();
    for (uint offset = 1u; offset < 1024u; offset <<= 1u) {
        uint before = lane >= offset ? (entries ? sEntries[lane - offset] : sTiles[lane - offset]) : 0u;
        barrier();
        if (entries) sEntries[lane] = min(sEntries[lane] + before, 0x80000000u);
        else sTiles[lane] += before;
        barrier();
    }
    return entries ? sEntries[lane] : sTiles[lane];
}

void main() {
    uint lane = gl_LocalInvocationID.x;
    int tx = uTiles.x, ty = uTiles.y, stride = tx + 1;
    // 1. Each row summed along (a group a row), then each column down (a group a column): each
    // tile's count (binParticles' step 2), every line at once instead of one lane's loop each.
    if (uPhase == 0) {
        sumLine(int(gl_WorkGroupID.x) * stride, 1, tx);
        return;
    }
    if (uPhase == 1) {
        sumLine(int(gl_WorkGroupID.x), stride, ty);
        return;
    }
    // 2. (One group.) The tiles with entries in row-major order, a stretch a lane: its tiles and entries, the
    // lanes' sums scanned, then each stretch listed from its first place.
    uint count = uint(tx * ty);
    uint stretch = (count + 1023u) / 1024u;
    uint begin = min(lane * stretch, count), end = min(begin + stretch, count);
    uint tiles = 0u, entries = 0u;
    for (uint t = begin; t < end; ++t) {
        int c = uGrid[kGridStart + int(t / uint(tx)) * stride + int(t % uint(tx))];
        if (c > 0) {
            ++tiles;
            entries = min(entries + uint(c), 0x80000000u);
        }
    }
    uint tileEnd = scan(tiles, false);
    uint entryEnd = scan(entries, true);
    uint place = tileEnd - tiles, first = entryEnd - entries;
    for (uint t = begin; t < end; ++t) {
        int c = uGrid[kGridStart + int(t / uint(tx)) * stride + int(t % uint(tx))];
        if (c > 0) {
            uListed[place++] = uvec4(t % uint(tx), t / uint(tx), first, uint(c));
            first = min(first + uint(c), 0x80000000u);
        }
    }
    if (lane == 1023u) {
        uGrid[1] = int(min(entryEnd, 0x7fffffffu));
        uGrid[2] = int(tileEnd);
        uGrid[3] = (entryEnd >= 0x80000000u ? 1 : 0) | (uGrid[0] != 0 ? 2 : 0);
        uGrid[0] = 0;
    }
    memoryBarrierBuffer();
    barrier();
    // 3. The grid back to zero (every cell BOUND may have marked: one row and one column past).
    uint cells = uint(stride * (ty + 1));
    for (uint i = lane; i < cells; i += 1024u) uGrid[kGridStart + int(i)] = 0;
}
#endif
