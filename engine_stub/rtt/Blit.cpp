#include "rtt/Blit.h"

#include "gl/Gl.h"
#include "rtt/RenderTargetPool.h"
#include "rtt/ScopedTargetBinding.h"

namespace cube::rtt {

namespace {

bool colorAttachmentOk(const RenderTargetPool& pool, RenderTargetHandle h, int attachment) {
    const RenderTargetDesc* d = pool.desc(h);
    return d && attachment >= 0 && attachment < colorAttachmentCount(*d);
}

// Blits obey the scissor test; nothing else of the caller's state matters to them.
class ScopedNoScissor {
public:
    ScopedNoScissor() : scissor_(glIsEnabled(GL_SCISSOR_TEST)) {
        if (scissor_) glDisable(GL_SCISSOR_TEST);
    }
    ~ScopedNoScissor() {
        if (scissor_) glEnable(GL_SCISSOR_TEST);
    }
    ScopedNoScissor(const ScopedNoScissor&) = delete;
    ScopedNoScissor& operator=(const ScopedNoScissor&) = delete;

private:
    GLboolean scissor_;
};

// Puts a pool framebuffer's draw buffers back to the canonical COLOR_ATTACHMENT0..n-1.
void restoreDrawBuffers(const RenderTargetPool& pool, RenderTargetHandle h) {
    const int n = colorAttachmentCount(*pool.desc(h));
    GLenum buffers[kMaxColorAttachments];
    for (int i = 0; i < n; ++i) buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pool.framebuffer(h));
    if (n > 0) glDrawBuffers(n, buffers);
}

}  // namespace

RttError blitColor(const RenderTargetPool& pool, RenderTargetHandle src, int srcAttachment,
                   RenderTargetHandle dst, int dstAttachment, Filter filter) {
    if (!pool.isValid(src) || !pool.isValid(dst)) return RttError::InvalidHandle;
    if (!colorAttachmentOk(pool, src, srcAttachment) || !colorAttachmentOk(pool, dst, dstAttachment))
        return RttError::InvalidAttachment;
    ScopedTargetBinding saved;
    ScopedNoScissor noScissor;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, pool.framebuffer(src));
    glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + srcAttachment));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pool.framebuffer(dst));
    const GLenum drawBuffer = GLenum(GL_COLOR_ATTACHMENT0 + dstAttachment);
    glDrawBuffers(1, &drawBuffer);
    glBlitFramebuffer(0, 0, pool.width(src), pool.height(src), 0, 0, pool.width(dst), pool.height(dst),
                      GL_COLOR_BUFFER_BIT, filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    restoreDrawBuffers(pool, dst);
    return RttError::None;
}

RttError blitDepth(const RenderTargetPool& pool, RenderTargetHandle src, RenderTargetHandle dst) {
    if (!pool.isValid(src) || !pool.isValid(dst)) return RttError::InvalidHandle;
    const DepthFormat a = pool.depthFormat(src), b = pool.depthFormat(dst);
    if (a == DepthFormat::None || b == DepthFormat::None) return RttError::InvalidAttachment;
    if (a != b) return RttError::FormatMismatch;
    ScopedTargetBinding saved;
    ScopedNoScissor noScissor;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, pool.framebuffer(src));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pool.framebuffer(dst));
    const GLbitfield mask = GL_DEPTH_BUFFER_BIT | (a == DepthFormat::Depth24Stencil8 ? GL_STENCIL_BUFFER_BIT : 0);
    glBlitFramebuffer(0, 0, pool.width(src), pool.height(src), 0, 0, pool.width(dst), pool.height(dst), mask,
                      GL_NEAREST);
    return RttError::None;
}

RttError present(const RenderTargetPool& pool, RenderTargetHandle src, int attachment, int x, int y,
                 int width, int height, Filter filter) {
    if (!pool.isValid(src)) return RttError::InvalidHandle;
    if (!colorAttachmentOk(pool, src, attachment)) return RttError::InvalidAttachment;
    if (width <= 0 || height <= 0) return RttError::None;  // minimised window: nothing to show
    ScopedTargetBinding saved;
    ScopedNoScissor noScissor;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, pool.framebuffer(src));
    glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + attachment));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, pool.width(src), pool.height(src), x, y, x + width, y + height,
                      GL_COLOR_BUFFER_BIT, filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    return RttError::None;
}

}  // namespace cube::rtt
