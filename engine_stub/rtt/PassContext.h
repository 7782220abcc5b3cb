#pragma once
// What a pass's execute callback sees while it runs: its targets as GL objects. Valid only
// during that callback. Using a target the pass did not declare asserts (debug builds).
#include <cstdint>

#include "rtt/Clear.h"
#include "rtt/FrameGraphResource.h"
#include "rtt/RenderTargetHandle.h"

namespace cube::rtt {

class FrameGraph;
class RenderTargetPool;

class PassContext {
public:
    /// Binds the target's framebuffer (draw and read) and sets the viewport to its size.
    /// False (nothing bound) when the target could not be allocated.
    bool bindForDraw(FrameGraphResource target);
    /// GL texture of colour attachment `attachment` (0 when absent).
    uint32_t texture(FrameGraphResource target, int attachment = 0) const;
    /// GL texture of the target's depth, shared or own (0 unless a pass declared readDepth on it
    /// or the target was imported with a sampled depth).
    uint32_t depthTexture(FrameGraphResource target) const;
    int width(FrameGraphResource target) const;
    int height(FrameGraphResource target) const;
    /// Clears through rtt::clear (masks and scissor ignored, bindings restored).
    RttError clear(FrameGraphResource target, const ClearValues& values = {});
    /// Pool handle, for the rtt helpers (blit, read-back); valid until the target's last use.
    RenderTargetHandle handle(FrameGraphResource target) const;
    RenderTargetPool& pool() const;
    const char* passName() const;

private:
    friend class FrameGraph;
    PassContext(FrameGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    RenderTargetHandle checked(FrameGraphResource target) const;
    FrameGraph& graph_;
    uint32_t pass_;
};

}  // namespace cube::rtt
