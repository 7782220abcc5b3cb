#include "rtt/Readback.h"

#include <algorithm>
#include <cstring>

#include "gl/Gl.h"
#include "rtt/RenderTargetPool.h"
#include "rtt/ScopedTargetBinding.h"

namespace cube::rtt {

namespace {

// Everything glReadPixels into client memory depends on, set to "tight, no conversion".
class ScopedPackState {
public:
    ScopedPackState() {
        for (size_t i = 0; i < kCount; ++i) glGetIntegerv(kParams[i], &saved_[i]);
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer_);
        glGetIntegerv(GL_CLAMP_READ_COLOR, &clampRead_);
        for (size_t i = 0; i < kCount; ++i) glPixelStorei(kParams[i], kParams[i] == GL_PACK_ALIGNMENT ? 1 : 0);
        if (packBuffer_) glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        if (clampRead_ != GL_FIXED_ONLY) glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY);
    }
    ~ScopedPackState() {
        for (size_t i = 0; i < kCount; ++i) glPixelStorei(kParams[i], saved_[i]);
        if (packBuffer_) glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer_));
        if (clampRead_ != GL_FIXED_ONLY) glClampColor(GL_CLAMP_READ_COLOR, GLenum(clampRead_));
    }
    ScopedPackState(const ScopedPackState&) = delete;
    ScopedPackState& operator=(const ScopedPackState&) = delete;

private:
    static constexpr size_t kCount = 8;
    static constexpr GLenum kParams[kCount] = {GL_PACK_ALIGNMENT,   GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS,
                                               GL_PACK_SKIP_PIXELS, GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST,
                                               GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES};
    GLint saved_[kCount] = {};
    GLint packBuffer_ = 0, clampRead_ = GL_FIXED_ONLY;
};

// GL rows are bottom-up; callers get top-down.
void flipRows(uint8_t* data, size_t rowBytes, int rows) {
    std::vector<uint8_t> tmp(rowBytes);
    for (int top = 0, bottom = rows - 1; top < bottom; ++top, --bottom) {
        uint8_t* a = data + size_t(top) * rowBytes;
        uint8_t* b = data + size_t(bottom) * rowBytes;
        std::memcpy(tmp.data(), a, rowBytes);
        std::memcpy(a, b, rowBytes);
        std::memcpy(b, tmp.data(), rowBytes);
    }
}

RttError checkColor(const RenderTargetPool& pool, RenderTargetHandle target, int attachment,
                    const RenderTargetDesc** desc) {
    *desc = pool.desc(target);
    if (!*desc) return RttError::InvalidHandle;
    if (attachment < 0 || attachment >= colorAttachmentCount(**desc)) return RttError::InvalidAttachment;
    return RttError::None;
}

// Reads the whole target into `dst` (rows bottom-up), then flips.
void readPixels(const RenderTargetPool& pool, RenderTargetHandle target, GLenum readBuffer, GLenum format,
                GLenum type, void* dst, size_t rowBytes) {
    ScopedTargetBinding saved;
    ScopedPackState pack;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, pool.framebuffer(target));
    if (readBuffer != GL_NONE) glReadBuffer(readBuffer);
    glReadPixels(0, 0, pool.width(target), pool.height(target), format, type, dst);
    if (readBuffer != GL_NONE) glReadBuffer(GL_COLOR_ATTACHMENT0);  // the pool's canonical state
    flipRows(static_cast<uint8_t*>(dst), rowBytes, pool.height(target));
}

}  // namespace

RttError readRGBA8(const RenderTargetPool& pool, RenderTargetHandle target, int attachment,
                   std::vector<uint8_t>* out) {
    const RenderTargetDesc* desc = nullptr;
    if (RttError e = checkColor(pool, target, attachment, &desc); e != RttError::None) return e;
    const int w = pool.width(target), h = pool.height(target);
    out->resize(size_t(w) * size_t(h) * 4u);
    readPixels(pool, target, GLenum(GL_COLOR_ATTACHMENT0 + attachment), GL_RGBA, GL_UNSIGNED_BYTE, out->data(),
               size_t(w) * 4u);
    return RttError::None;
}

RttError readFloat(const RenderTargetPool& pool, RenderTargetHandle target, int attachment, FloatLayout layout,
                   std::vector<float>* out, int* channels) {
    const RenderTargetDesc* desc = nullptr;
    if (RttError e = checkColor(pool, target, attachment, &desc); e != RttError::None) return e;
    const int n = layout == FloatLayout::RGBA ? 4 : channelCount(desc->color[size_t(attachment)]);
    const GLenum format = n == 1 ? GL_RED : n == 2 ? GL_RG : GL_RGBA;
    const int w = pool.width(target), h = pool.height(target);
    out->resize(size_t(w) * size_t(h) * size_t(n));
    readPixels(pool, target, GLenum(GL_COLOR_ATTACHMENT0 + attachment), format, GL_FLOAT, out->data(),
               size_t(w) * size_t(n) * sizeof(float));
    if (channels) *channels = n;
    return RttError::None;
}

RttError readDepth(const RenderTargetPool& pool, RenderTargetHandle target, std::vector<float>* out) {
    if (!pool.isValid(target)) return RttError::InvalidHandle;
    if (pool.depthFormat(target) == DepthFormat::None) return RttError::InvalidAttachment;
    const int w = pool.width(target), h = pool.height(target);
    out->resize(size_t(w) * size_t(h));
    readPixels(pool, target, GL_NONE, GL_DEPTH_COMPONENT, GL_FLOAT, out->data(), size_t(w) * sizeof(float));
    return RttError::None;
}

void readDefaultFramebufferRGBA8(int width, int height, std::vector<uint8_t>* out) {
    out->resize(size_t(std::max(width, 0)) * size_t(std::max(height, 0)) * 4u);
    if (out->empty()) return;
    ScopedTargetBinding saved;
    ScopedPackState pack;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, out->data());
    flipRows(out->data(), size_t(width) * 4u, height);
}

}  // namespace cube::rtt
