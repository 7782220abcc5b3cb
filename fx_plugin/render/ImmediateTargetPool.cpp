// Pooled GL targets of the immediate path.
#include "ImmediateTargetPool.h"

#include "PrivateGl.h"

namespace fx {

namespace {

struct Layout {
    GLenum internal, format, type;
};

Layout layoutOf(TargetFormat f) {
    switch (f) {
    case TargetFormat::RGBA8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
    case TargetFormat::RGBA16F: return {GL_RGBA16F, GL_RGBA, GL_FLOAT};
    case TargetFormat::R32F: return {GL_R32F, GL_RED, GL_FLOAT};
    case TargetFormat::RG32F: return {GL_RG32F, GL_RG, GL_FLOAT};
    case TargetFormat::Depth: break;  // not a target's format (sceneZBuffer's texture only)
    }
    return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
}

void freeSlot(PooledTarget& s) {
    if (s.framebuffer) glDeleteFramebuffers(1, &s.framebuffer);
    if (s.texture) glDeleteTextures(1, &s.texture);
    if (s.depth) glDeleteRenderbuffers(1, &s.depth);
    s.framebuffer = s.texture = s.depth = 0;
}

}  // namespace

ImmediateTargetPool::~ImmediateTargetPool() { release(); }

void ImmediateTargetPool::beginFrame() {
    ++frame_;
    for (PooledTarget& s : slots_) s.inUse = false;
}

void ImmediateTargetPool::endFrame() {
    for (size_t i = slots_.size(); i-- > 0;) {
        if (frame_ - slots_[i].lastFrame >= kKeepFrames) {
            freeSlot(slots_[i]);
            slots_.erase(slots_.begin() + std::ptrdiff_t(i));
        }
    }
}

size_t ImmediateTargetPool::acquire(const TargetDesc& desc, int width, int height) {
    for (size_t i = 0; i < slots_.size(); ++i) {
        PooledTarget& s = slots_[i];
        if (!s.inUse && s.width == width && s.height == height && s.desc.format == desc.format &&
            s.desc.linearFilter == desc.linearFilter && s.desc.depth == desc.depth) {
            s.inUse = true;
            s.lastFrame = frame_;
            return i;
        }
    }
    PooledTarget s;
    s.desc = desc;
    s.width = width;
    s.height = height;
    const Layout l = layoutOf(desc.format);
    const GLint filter = desc.linearFilter ? GL_LINEAR : GL_NEAREST;
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);  // a null upload must not read from a host PBO
    glActiveTexture(GL_TEXTURE0);              // a unit the caller's guard restores
    glGenTextures(1, &s.texture);
    glBindTexture(GL_TEXTURE_2D, s.texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(l.internal), width, height, 0, l.format, l.type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    GLint renderbuffer = 0;
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer);
    if (desc.depth) {
        // A z-buffer of its own, float like the hosts' (what a reversed-Z pass needs).
        glGenRenderbuffers(1, &s.depth);
        glBindRenderbuffer(GL_RENDERBUFFER, s.depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, GLuint(renderbuffer));
    }
    glGenFramebuffers(1, &s.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, s.texture, 0);
    if (s.depth) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, s.depth);
    s.inUse = true;
    s.lastFrame = frame_;
    slots_.push_back(s);
    ++allocations_;
    return slots_.size() - 1;
}

void ImmediateTargetPool::release() {
    for (PooledTarget& s : slots_) freeSlot(s);
    slots_.clear();
}

}  // namespace fx
