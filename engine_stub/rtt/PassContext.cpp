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

bool PassContext::bindForDraw(FrameGraphResource target) {
    const RenderTargetHandle h = checked(target);
    if (!graph_.pool_.isValid(h)) return false;
    glBindFramebuffer(GL_FRAMEBUFFER, graph_.pool_.framebuffer(h));
    glViewport(0, 0, graph_.pool_.width(h), graph_.pool_.height(h));
    return true;
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
