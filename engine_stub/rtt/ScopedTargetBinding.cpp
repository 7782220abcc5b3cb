#include "rtt/ScopedTargetBinding.h"

#include "gl/Gl.h"
#include "rtt/RenderTargetPool.h"

namespace cube::rtt {

ScopedTargetBinding::ScopedTargetBinding() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
}

ScopedTargetBinding::ScopedTargetBinding(const RenderTargetPool& pool, RenderTargetHandle target)
    : ScopedTargetBinding() {
    bind(pool, target);
}

ScopedTargetBinding::~ScopedTargetBinding() { restore(); }

void ScopedTargetBinding::restore() const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
}

bool ScopedTargetBinding::bind(const RenderTargetPool& pool, RenderTargetHandle target) {
    if (!pool.isValid(target)) return false;
    bindFramebuffer(pool.framebuffer(target), pool.width(target), pool.height(target));
    return true;
}

void ScopedTargetBinding::bindFramebuffer(uint32_t framebuffer, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
}

}  // namespace cube::rtt
