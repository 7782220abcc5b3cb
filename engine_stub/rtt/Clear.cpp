#include "rtt/Clear.h"

#include "gl/Gl.h"
#include "rtt/RenderTargetPool.h"
#include "rtt/ScopedTargetBinding.h"

namespace cube::rtt {

namespace {

// glClearBuffer honours write masks, scissor and rasterizer discard; a pass that left depth
// writes off (opaque with depth test EQUAL) must not stop the next frame's depth clear.
class ScopedClearState {
public:
    explicit ScopedClearState(int colorCount) : colors_(colorCount) {
        for (int i = 0; i < colors_; ++i) glGetBooleani_v(GL_COLOR_WRITEMASK, GLuint(i), colorMask_[i]);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
        glGetIntegerv(GL_STENCIL_WRITEMASK, &stencilFront_);
        glGetIntegerv(GL_STENCIL_BACK_WRITEMASK, &stencilBack_);
        scissor_ = glIsEnabled(GL_SCISSOR_TEST);
        discard_ = glIsEnabled(GL_RASTERIZER_DISCARD);
        for (int i = 0; i < colors_; ++i) glColorMaski(GLuint(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_TRUE);
        glStencilMask(0xFFFFFFFFu);
        if (scissor_) glDisable(GL_SCISSOR_TEST);
        if (discard_) glDisable(GL_RASTERIZER_DISCARD);
    }
    ~ScopedClearState() {
        for (int i = 0; i < colors_; ++i)
            glColorMaski(GLuint(i), colorMask_[i][0], colorMask_[i][1], colorMask_[i][2], colorMask_[i][3]);
        glDepthMask(depthMask_);
        glStencilMaskSeparate(GL_FRONT, GLuint(stencilFront_));
        glStencilMaskSeparate(GL_BACK, GLuint(stencilBack_));
        if (scissor_) glEnable(GL_SCISSOR_TEST);
        if (discard_) glEnable(GL_RASTERIZER_DISCARD);
    }
    ScopedClearState(const ScopedClearState&) = delete;
    ScopedClearState& operator=(const ScopedClearState&) = delete;

private:
    int colors_;
    GLboolean colorMask_[kMaxColorAttachments][4] = {};
    GLboolean depthMask_ = GL_TRUE;
    GLint stencilFront_ = 0, stencilBack_ = 0;
    GLboolean scissor_ = GL_FALSE, discard_ = GL_FALSE;
};

}  // namespace

RttError clear(const RenderTargetPool& pool, RenderTargetHandle target, const ClearValues& values) {
    const RenderTargetDesc* desc = pool.desc(target);
    if (!desc) return RttError::InvalidHandle;
    const int colors = colorAttachmentCount(*desc);
    ScopedTargetBinding binding(pool, target);
    ScopedClearState state(colors);
    // Draw buffer i is COLOR_ATTACHMENTi for every pool framebuffer (see RenderTargetPool::create).
    for (int i = 0; i < colors; ++i)
        if (values.clearColor[size_t(i)]) glClearBufferfv(GL_COLOR, i, values.color[size_t(i)].data());
    const DepthFormat depth = pool.depthFormat(target);
    if (depth == DepthFormat::Depth24Stencil8 && values.clearDepth && values.clearStencil) {
        glClearBufferfi(GL_DEPTH_STENCIL, 0, values.depth, values.stencil);
    } else if (depth == DepthFormat::Depth24Stencil8 && values.clearStencil) {
        glClearBufferiv(GL_STENCIL, 0, &values.stencil);
    } else if (depth != DepthFormat::None && values.clearDepth) {
        glClearBufferfv(GL_DEPTH, 0, &values.depth);
    }
    return RttError::None;
}

}  // namespace cube::rtt
