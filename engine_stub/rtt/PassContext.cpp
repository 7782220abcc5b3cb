#include "rtt/PassContext.h"

#include <cassert>

#include "gl/Gl.h"
#include "rtt/FrameGraph.h"
#include "rtt/RenderTargetPool.h"

namespace cube::rtt {

RenderTargetHandle PassContext::checked(FrameGraphResource target) const {
    const int r = graph_.resourceIndex(target);
    assert(r >= 0 && graph_.declared(pass_, r) && "pass uses a target it did not declare");
    return r >= 0 ? graph_.resources_[size_t(r)].handle : RenderTargetHandle{};
}

bool PassContext::isNeeded(FrameGraphResource target) const {
    const int r = graph_.resourceIndex(target);
    assert(r >= 0 && graph_.declared(pass_, r) && "pass asks about a target it did not declare");
    const FrameGraph::Pass& p = graph_.passes_[pass_];
    for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i) {
        const FrameGraph::AccessRecord& a = graph_.accesses_[i];
        if (int(a.resource) == r && (a.access & FrameGraph::kWrite) && !(a.access & FrameGraph::kImplicit)) return true;
    }
    return false;
}

bool PassContext::sharesDepth(FrameGraphResource target) const {
    const int r = graph_.resourceIndex(target);
    return r >= 0 && graph_.resources_[size_t(r)].sharedDepthOf >= 0;
}

bool PassContext::bindForDraw(FrameGraphResource target) {
    const RenderTargetHandle h = checked(target);
    if (!graph_.pool_.isValid(h)) return false;
    glBindFramebuffer(GL_FRAMEBUFFER, graph_.pool_.framebuffer(h));
    glViewport(0, 0, graph_.pool_.width(h), graph_.pool_.height(h));
    return true;
}

void PassContext::setViewport(int x, int y, int w, int h) { glViewport(x, y, w, h); }

bool PassContext::bindForDraw(FrameGraphResource target, FrameGraphResource second) {
    const RenderTargetHandle h = checked(target), h2 = checked(second);
    RenderTargetPool& pool = graph_.pool_;
    if (!pool.isValid(h) || !pool.isValid(h2) || pool.width(h) != pool.width(h2) ||
        pool.height(h) != pool.height(h2) || pool.colorTexture(h2, 0) == 0 || pool.colorTexture(h, 1) != 0) {
        return false;
    }
    const GLuint fbo = pool.framebuffer(h);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, pool.colorTexture(h2, 0), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    extraAttachedFbo_ = fbo;
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        endPass();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return false;
    }
    glViewport(0, 0, pool.width(h), pool.height(h));
    return true;
}

void PassContext::endPass() {
    if (!extraAttachedFbo_) return;
    // Detached again: a later pass that samples `second` while drawing into `target` must not
    // find it attached (a feedback loop even when it is not a draw buffer).
    glBindFramebuffer(GL_FRAMEBUFFER, extraAttachedFbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
    const GLenum buffer = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buffer);
    extraAttachedFbo_ = 0;
}

uint32_t PassContext::texture(FrameGraphResource target, int attachment) const {
    return graph_.pool_.colorTexture(checked(target), attachment);
}

uint32_t PassContext::depthTexture(FrameGraphResource target) const {
    return graph_.pool_.depthTexture(checked(target));
}

int PassContext::width(FrameGraphResource target) const { return graph_.pool_.width(checked(target)); }

int PassContext::height(FrameGraphResource target) const { return graph_.pool_.height(checked(target)); }

RttError PassContext::clear(FrameGraphResource target, const ClearValues& values) {
    return rtt::clear(graph_.pool_, checked(target), values);
}

RenderTargetHandle PassContext::handle(FrameGraphResource target) const { return checked(target); }

RenderTargetPool& PassContext::pool() const { return graph_.pool_; }

const char* PassContext::passName() const { return graph_.passes_[pass_].name.c_str(); }

}  // namespace cube::rtt
