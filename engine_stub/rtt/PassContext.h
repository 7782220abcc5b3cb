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
    /// Multiple render targets: binds `target`'s framebuffer (its colour as draw buffer 0, its
    /// depth) with `second`'s colour attachment 0 as draw buffer 1, for this pass only (detached
    /// when the pass returns). Both must have the same size and `second` a colour attachment;
    /// false (and nothing bound) otherwise. Fragment output location 1 lands in `second`.
    bool bindForDraw(FrameGraphResource target, FrameGraphResource second);
    /// After bindForDraw: draw into the rectangle (x, y, w, h) of the bound target only (a view
    /// that is part of a larger target, e.g. one half of a split screen). Sets the viewport; the
    /// graph restores it after the pass.
    void setViewport(int x, int y, int w, int h);
    /// GL texture of colour attachment `attachment` (0 when absent).
    uint32_t texture(FrameGraphResource target, int attachment = 0) const;
    /// GL texture of the target's depth, shared or own (0 unless a pass declared readDepth on it
    /// or the target was imported with a sampled depth).
    uint32_t depthTexture(FrameGraphResource target) const;
    int width(FrameGraphResource target) const;
    int height(FrameGraphResource target) const;
    /// True when this pass must write the target: declared with write(), or with writeIfRead()
    /// and compile() found a later reader and no earlier writer.
    bool isNeeded(FrameGraphResource target) const;
    /// True when the target draws on another target's z-buffer this frame (sharedDepthOf, or
    /// sharedDepthIfWritten that compile() took): that z-buffer already holds the scene.
    bool sharesDepth(FrameGraphResource target) const;
    /// Clears through rtt::clear (masks and scissor ignored, bindings restored).
    RttError clear(FrameGraphResource target, const ClearValues& values = {});
    /// Pool handle, for the rtt helpers (blit, read-back); valid until the target's last use.
    RenderTargetHandle handle(FrameGraphResource target) const;
    RenderTargetPool& pool() const;
    const char* passName() const;

private:
    friend class FrameGraph;
    PassContext(FrameGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    /// Undoes a two-target bind (called by the graph after the pass body).
    void endPass();
    RenderTargetHandle checked(FrameGraphResource target) const;
    FrameGraph& graph_;
    uint32_t pass_;
    uint32_t extraAttachedFbo_ = 0;  ///< framebuffer that has a second target attached this pass
};

}  // namespace cube::rtt
