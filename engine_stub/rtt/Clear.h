#pragma once
// Clearing a render target's attachments regardless of the caller's write masks and scissor.
#include <array>

#include "rtt/RenderTargetDesc.h"
#include "rtt/RenderTargetHandle.h"
#include "rtt/RttError.h"

namespace cube::rtt {

class RenderTargetPool;

/// Defaults: every colour attachment to (0,0,0,0), depth to 1, stencil (when the depth
/// format has one) to 0. Values are written as given: float formats keep them exactly, RGBA8
/// clamps to [0,1] and rounds to the nearest 1/255.
struct ClearValues {
    std::array<std::array<float, 4>, kMaxColorAttachments> color{};
    std::array<bool, kMaxColorAttachments> clearColor = {true, true, true, true};
    bool clearDepth = true;
    float depth = 1.0f;
    bool clearStencil = true;
    int stencil = 0;
};

/// Clears the target's attachments (unused colour indices are skipped; a shared depth is the
/// owner's depth, so clearing it clears the owner's). Colour/depth/stencil write masks,
/// scissor and rasterizer discard are forced off for the clear and restored; framebuffer
/// bindings are restored. InvalidHandle for a stale handle.
RttError clear(const RenderTargetPool& pool, RenderTargetHandle target, const ClearValues& values = {});

}  // namespace cube::rtt
