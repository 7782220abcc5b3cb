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
    reserve(n);
    for (int i = 0; i < n; ++i) indices_[i] = static_cast<uint32_t>(i);
    order_ = Order{indices_.data(), n};
    if (n < 2) return order_;
    std::fill(histogram_.begin(), histogram_.end(), 0u);
    for (int i = 0; i < n; ++i) addKey(i, descendingKey(depth[i]));
    return radixSort(n);
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
