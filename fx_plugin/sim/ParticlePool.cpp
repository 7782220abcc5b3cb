#include "ParticlePool.h"

#include <cassert>

namespace fx {

ParticlePool::ParticlePool(int capacity)
    : capacity_(capacity > 0 ? capacity : 0),
      data_(static_cast<size_t>(capacity_) * StreamCount, 0.0f),
      frame_(static_cast<size_t>(capacity_), 0) {}

void ParticlePool::kill(int i) {
    assert(i >= 0 && i < alive_);
    const int last = --alive_;
    if (i == last) return;
    float* base = data_.data();
    for (int s = 0; s < StreamCount; ++s) {
        float* a = base + static_cast<size_t>(s) * capacity_;
        a[i] = a[last];
    }
    frame_[i] = frame_[last];
}

}  // namespace fx
