#pragma once
// Copies between render targets and to the default framebuffer (presenting), through
// glBlitFramebuffer. Framebuffer bindings, scissor and the pool framebuffers' draw/read
// buffers are restored.
#include <cstdint>

#include "rtt/RenderTargetDesc.h"
#include "rtt/RenderTargetHandle.h"
#include "rtt/RttError.h"

namespace cube::rtt {

class RenderTargetPool;

/// Whole colour attachment `srcAttachment` of `src` onto the whole `dstAttachment` of `dst`,
/// scaled with `filter` when the sizes differ. InvalidHandle / InvalidAttachment on bad input.
RttError blitColor(const RenderTargetPool& pool, RenderTargetHandle src, int srcAttachment,
                   RenderTargetHandle dst, int dstAttachment, Filter filter = Filter::Linear);
/// Whole depth (and stencil) of `src` onto `dst`, nearest. Both need a depth attachment of the
/// same format (FormatMismatch otherwise); InvalidAttachment when one has no depth.
RttError blitDepth(const RenderTargetPool& pool, RenderTargetHandle src, RenderTargetHandle dst);
/// Colour attachment of `src` onto the default framebuffer's current draw buffer at
/// (x, y, width, height), bottom-left origin, e.g. (0, 0, platform.width(), platform.height()).
RttError present(const RenderTargetPool& pool, RenderTargetHandle src, int attachment, int x, int y,
                 int width, int height, Filter filter = Filter::Linear);

}  // namespace cube::rtt
