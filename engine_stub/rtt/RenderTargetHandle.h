#pragma once
// Typed, generation-checked handle to a render target in a RenderTargetPool. The pool bumps a
// slot's generation on release and on destruction, so a handle kept past either is stale and
// every pool query on it fails cleanly (RttError::InvalidHandle, texture 0, size 0).
#include <cstdint>

namespace cube::rtt {

/// Defaults: invalid (generation 0 is never issued).
struct RenderTargetHandle {
    uint32_t index = 0;
    uint32_t generation = 0;

    /// True when the handle was ever issued; whether it is still live is RenderTargetPool::isValid.
    bool valid() const { return generation != 0; }
    friend bool operator==(RenderTargetHandle a, RenderTargetHandle b) {
        return a.index == b.index && a.generation == b.generation;
    }
    friend bool operator!=(RenderTargetHandle a, RenderTargetHandle b) { return !(a == b); }
};

}  // namespace cube::rtt
