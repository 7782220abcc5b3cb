#include "ParticleSorter.h"

#include <algorithm>
#include <cstring>

namespace fx {
namespace {

constexpr int kDigitBits = 11;
constexpr uint32_t kBuckets = 1u << kDigitBits;
constexpr uint32_t kDigitMask = kBuckets - 1u;
constexpr int kPasses = 3;  // 3 x 11 bits >= 32

// A key whose unsigned order is the float's *descending* order (farthest first).
uint32_t descendingKey(float depth) {
    depth += 0.0f;  // -0 becomes +0: equal depths must get equal keys (stability)
    uint32_t bits;
    std::memcpy(&bits, &depth, sizeof bits);
    // Ascending map: negative floats flip all bits, positive ones set the sign bit.
    const uint32_t ascending = (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
    return ~ascending;
}

}  // namespace

void ParticleSorter::reserve(int capacity) {
    const size_t n = static_cast<size_t>(std::max(capacity, 0));
    if (keys_.size() < n) {
        keys_.resize(n);
        keysTmp_.resize(n);
        indices_.resize(n);
        indicesTmp_.resize(n);
    }
    if (histogram_.size() < kBuckets * kPasses) histogram_.resize(kBuckets * kPasses);
}

ParticleSorter::Order ParticleSorter::update(const ParticlePool& pool, glm::vec3 eye,
                                             glm::vec3 viewDir, bool sort) {
    reserve(pool.capacity());
    const int n = pool.alive();
    for (int i = 0; i < n; ++i) indices_[i] = static_cast<uint32_t>(i);
    order_ = Order{indices_.data(), n};
    if (!sort || n < 2) return order_;

    const float* x = pool.posX();
    const float* y = pool.posY();
    const float* z = pool.posZ();
    std::fill(histogram_.begin(), histogram_.end(), 0u);
    for (int i = 0; i < n; ++i) {
        const float depth =
            (x[i] - eye.x) * viewDir.x + (y[i] - eye.y) * viewDir.y + (z[i] - eye.z) * viewDir.z;
        addKey(i, descendingKey(depth));
    }
    return radixSort(n);
}

ParticleSorter::Order ParticleSorter::sortDescending(const float* depth, int n) {
    return sortDescending(depth, nullptr, n, Jobs());
}

ParticleSorter::Order ParticleSorter::sortDescending(const float* depth, const uint32_t* payload, int n,
                                                     const Jobs& jobs) {
    // Below 2 x 16k keys, or without a job system, the single-pass histogram of radixSort() is
    // the cheaper sort (pieces count each pass's digits anew).
    constexpr size_t kGrain = 16384;
    constexpr uint32_t kMaxPieces = 16;
    const Pieces pieces = splitWork(size_t(std::max(n, 0)), kGrain, jobs.parallel() ? kMaxPieces : 1u);
    if (pieces.count <= 1) {
        reserve(n);
        for (int i = 0; i < n; ++i) indices_[size_t(i)] = payload ? payload[i] : uint32_t(i);
        order_ = Order{indices_.data(), std::max(n, 0)};
        if (n < 2) return order_;
        std::fill(histogram_.begin(), histogram_.end(), 0u);
        for (int i = 0; i < n; ++i) addKey(i, descendingKey(depth[i]));
        return radixSort(n);
    }
    // Digits of 8 bits here, four passes: with 11, a piece holds a few keys per digit, so pieces
    // scattered at once write into the same cache lines (at 225k keys in 14 pieces the scatter
    // cost three times the serial one on two threads); with 8, each piece writes runs of dozens.
    constexpr int kBits = 8;
    constexpr uint32_t kDigits = 1u << kBits, kMask = kDigits - 1u;
    constexpr int kPiecePasses = 4;
    reserve(n);
    pieceCounts_.resize(size_t(pieces.count) * kDigits);
    pieceSlots_.resize(size_t(pieces.count) * kDigits);
    uint32_t* srcKeys = keys_.data();
    uint32_t* srcIdx = indices_.data();
    uint32_t* dstKeys = keysTmp_.data();
    uint32_t* dstIdx = indicesTmp_.data();
    // Each piece's keys and its counts of the first digit.
    jobs.run(pieces, [&](uint32_t piece) {
        uint32_t* counts = &pieceCounts_[size_t(piece) * kDigits];
        std::fill(counts, counts + kDigits, 0u);
        for (size_t i = pieces.begin(piece), e = pieces.end(piece); i < e; ++i) {
            const uint32_t k = descendingKey(depth[i]);
            srcKeys[i] = k;
            srcIdx[i] = payload ? payload[i] : uint32_t(i);
            ++counts[k & kMask];
        }
    });
    for (int p = 0; p < kPiecePasses; ++p) {
        const int shift = p * kBits;
        if (p > 0) {
            jobs.run(pieces, [&](uint32_t piece) {
                uint32_t* counts = &pieceCounts_[size_t(piece) * kDigits];
                std::fill(counts, counts + kDigits, 0u);
                for (size_t i = pieces.begin(piece), e = pieces.end(piece); i < e; ++i) {
                    ++counts[(srcKeys[i] >> shift) & kMask];
                }
            });
        }
        // Digit-major, piece-minor slots: a digit's keys keep piece order, and in a piece their
        // own order, which is what makes each pass (and the sort) stable.
        const uint32_t first = (srcKeys[0] >> shift) & kMask;
        uint32_t sameDigit = 0;
        for (uint32_t s = 0; s < pieces.count; ++s) sameDigit += pieceCounts_[s * kDigits + first];
        if (sameDigit == uint32_t(n)) continue;  // every key has the same digit: the identity
        uint32_t sum = 0;
        for (uint32_t b = 0; b < kDigits; ++b) {
            for (uint32_t s = 0; s < pieces.count; ++s) {
                pieceSlots_[s * kDigits + b] = sum;
                sum += pieceCounts_[s * kDigits + b];
            }
        }
        jobs.run(pieces, [&](uint32_t piece) {
            uint32_t slot[kDigits];  // this piece's next slot per digit
            std::memcpy(slot, &pieceSlots_[size_t(piece) * kDigits], sizeof slot);
            for (size_t i = pieces.begin(piece), e = pieces.end(piece); i < e; ++i) {
                const uint32_t k = srcKeys[i];
                const uint32_t at = slot[(k >> shift) & kMask]++;
                dstKeys[at] = k;
                dstIdx[at] = srcIdx[i];
            }
        });
        std::swap(srcKeys, dstKeys);
        std::swap(srcIdx, dstIdx);
    }
    order_ = Order{srcIdx, n};
    return order_;
}

void ParticleSorter::addKey(int i, uint32_t k) {
    keys_[size_t(i)] = k;
    uint32_t* hist = histogram_.data();
    for (int p = 0; p < kPasses; ++p) ++hist[p * kBuckets + ((k >> (p * kDigitBits)) & kDigitMask)];
}

ParticleSorter::Order ParticleSorter::radixSort(int n) {
    uint32_t* hist = histogram_.data();
    uint32_t* srcKeys = keys_.data();
    uint32_t* srcIdx = indices_.data();
    uint32_t* dstKeys = keysTmp_.data();
    uint32_t* dstIdx = indicesTmp_.data();
    for (int p = 0; p < kPasses; ++p) {
        uint32_t* h = hist + p * kBuckets;
        if (h[(srcKeys[0] >> (p * kDigitBits)) & kDigitMask] == static_cast<uint32_t>(n)) {
            continue;  // every key has the same digit here: the pass would be the identity
        }
        uint32_t sum = 0;
        for (uint32_t b = 0; b < kBuckets; ++b) {
            const uint32_t c = h[b];
            h[b] = sum;
            sum += c;
        }
        for (int i = 0; i < n; ++i) {
            const uint32_t k = srcKeys[i];
            const uint32_t slot = h[(k >> (p * kDigitBits)) & kDigitMask]++;
            dstKeys[slot] = k;
            dstIdx[slot] = srcIdx[i];
        }
        std::swap(srcKeys, dstKeys);
        std::swap(srcIdx, dstIdx);
    }
    order_ = Order{srcIdx, n};
    return order_;
}

}  // namespace fx
