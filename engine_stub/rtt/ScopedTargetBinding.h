#pragma once
// RAII framebuffer binding: remembers the draw and read framebuffers and the viewport bound
// when it was made, and puts them back when it goes out of scope.
#include <cstdint>

#include "rtt/RenderTargetHandle.h"

namespace cube::rtt {

class RenderTargetPool;

class ScopedTargetBinding {
public:
    /// Saves the current bindings and binds nothing.
    ScopedTargetBinding();
    /// Saves, then bind(pool, target).
    ScopedTargetBinding(const RenderTargetPool& pool, RenderTargetHandle target);
    ~ScopedTargetBinding();
    ScopedTargetBinding(const ScopedTargetBinding&) = delete;
    ScopedTargetBinding& operator=(const ScopedTargetBinding&) = delete;

    /// Binds the target's framebuffer for drawing and reading and sets the viewport to its
    /// size. A stale handle binds nothing and returns false.
    bool bind(const RenderTargetPool& pool, RenderTargetHandle target);
    /// Binds a GL framebuffer name (0 = the default framebuffer) and sets the viewport.
    void bindFramebuffer(uint32_t framebuffer, int width, int height);
    /// Puts the saved bindings back now (the destructor does it again).
    void restore() const;

private:
    int draw_ = 0, read_ = 0;
    int viewport_[4] = {};
};

}  // namespace cube::rtt
