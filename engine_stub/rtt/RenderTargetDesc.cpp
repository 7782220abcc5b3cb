#include "rtt/RenderTargetDesc.h"

#include <cmath>

namespace cube::rtt {

const char* colorFormatName(ColorFormat format) {
    switch (format) {
        case ColorFormat::None: return "None";
        case ColorFormat::RGBA8: return "RGBA8";
        case ColorFormat::RGBA16F: return "RGBA16F";
        case ColorFormat::R32F: return "R32F";
        case ColorFormat::RG32F: return "RG32F";
    }
    return "?";
}

const char* depthFormatName(DepthFormat format) {
    switch (format) {
        case DepthFormat::None: return "None";
        case DepthFormat::Depth24: return "DEPTH24";
        case DepthFormat::Depth32F: return "DEPTH32F";
        case DepthFormat::Depth24Stencil8: return "DEPTH24_STENCIL8";
    }
    return "?";
}

int channelCount(ColorFormat format) {
    switch (format) {
        case ColorFormat::RGBA8:
        case ColorFormat::RGBA16F: return 4;
        case ColorFormat::R32F: return 1;
        case ColorFormat::RG32F: return 2;
        case ColorFormat::None: break;
    }
    return 0;
}

int colorAttachmentCount(const RenderTargetDesc& desc) {
    int n = 0;
    while (n < kMaxColorAttachments && desc.color[size_t(n)] != ColorFormat::None) ++n;
    return n;
}

bool sameSizeRule(const RenderTargetDesc& a, const RenderTargetDesc& b) {
    if (isRelative(a) != isRelative(b)) return false;
    return isRelative(a) ? a.scale == b.scale : a.width == b.width && a.height == b.height;
}

namespace {

int resolveAxis(int view, float scale, int maxSize) {
    // Snap by 1e-6 relative so 3 * (1/3.f) = 1.00000003 stays 1; power-of-two scales are exact.
    const double exact = double(view > 0 ? view : 0) * double(scale);
    double v = std::ceil(exact * (1.0 - 1e-6));
    if (!(v >= 1.0)) v = 1.0;  // also catches NaN
    if (maxSize > 0 && v > double(maxSize)) v = double(maxSize);
    return int(v);
}

// Built only on failure: validation runs on every acquire and must not allocate when it passes.
std::string prefix(const RenderTargetDesc& desc) {
    return desc.name && *desc.name ? std::string("'") + desc.name + "': " : std::string();
}

void setMessage(std::string* message, std::string text) {
    if (message) *message = std::move(text);
}

}  // namespace

void resolveSize(const RenderTargetDesc& desc, int viewWidth, int viewHeight, int maxSize,
                 int* width, int* height) {
    if (!isRelative(desc)) {
        *width = desc.width;
        *height = desc.height;
        return;
    }
    *width = resolveAxis(viewWidth, desc.scale, maxSize);
    *height = resolveAxis(viewHeight, desc.scale, maxSize);
}

RttError validateDesc(const RenderTargetDesc& desc, const RenderTargetLimits& limits,
                      std::string* message) {
    if (desc.width < 0 || desc.height < 0 || (desc.width == 0) != (desc.height == 0)) {
        setMessage(message, prefix(desc) + "width/height " + std::to_string(desc.width) + "x" +
                                std::to_string(desc.height) +
                                ": expected both > 0 (absolute) or both 0 (relative to the view)");
        return RttError::InvalidSize;
    }
    if (isRelative(desc) && !(desc.scale > 0.0f && std::isfinite(desc.scale))) {
        setMessage(message, prefix(desc) + "scale " + std::to_string(desc.scale) +
                                ": expected a finite value > 0 for a relative-size target");
        return RttError::InvalidScale;
    }
    int used = 0;
    bool gap = false;
    for (int i = 0; i < kMaxColorAttachments; ++i) {
        const ColorFormat f = desc.color[size_t(i)];
        if (uint8_t(f) > uint8_t(ColorFormat::RG32F)) {
            setMessage(message, prefix(desc) + "color[" + std::to_string(i) + "] = " +
                                    std::to_string(int(f)) + ": not a ColorFormat");
            return RttError::InvalidFormat;
        }
        if (f == ColorFormat::None) {
            gap = true;
        } else if (gap) {
            setMessage(message, prefix(desc) + "color[" + std::to_string(i) +
                                    "] follows a None attachment: attachments must be contiguous from 0");
            return RttError::ColorAttachmentGap;
        } else {
            ++used;
        }
    }
    if (uint8_t(desc.depth) > uint8_t(DepthFormat::Depth24Stencil8) ||
        uint8_t(desc.filter) > uint8_t(Filter::Nearest) || uint8_t(desc.wrap) > uint8_t(Wrap::Repeat)) {
        setMessage(message, prefix(desc) + "depth/filter/wrap: value outside its enum");
        return RttError::InvalidFormat;
    }
    if (used == 0 && desc.depth == DepthFormat::None && !desc.sharedDepth.valid()) {
        setMessage(message, prefix(desc) + "no colour attachment, no depth and no shared depth: expected at least one");
        return RttError::NoAttachments;
    }
    if (used > limits.maxColorAttachments) {
        setMessage(message, prefix(desc) + std::to_string(used) + " colour attachments: this context allows " +
                                std::to_string(limits.maxColorAttachments));
        return RttError::TooManyColorAttachments;
    }
    if (desc.depth != DepthFormat::None && desc.sharedDepth.valid()) {
        setMessage(message, prefix(desc) + "depth = " + depthFormatName(desc.depth) +
                                " and sharedDepth are both set: expected one of them");
        return RttError::SharedDepthConflict;
    }
    if (!isRelative(desc)) {
        const bool textures = used > 0 || (desc.depth != DepthFormat::None && desc.sampledDepth);
        const bool renderbuffer = desc.depth != DepthFormat::None && !desc.sampledDepth;
        const int limit = textures && renderbuffer
                              ? (limits.maxTextureSize < limits.maxRenderbufferSize ? limits.maxTextureSize
                                                                                    : limits.maxRenderbufferSize)
                              : (textures ? limits.maxTextureSize : limits.maxRenderbufferSize);
        if (desc.width > limit || desc.height > limit) {
            setMessage(message, prefix(desc) + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                                    ": above the driver's limit of " + std::to_string(limit) +
                                    (textures ? " (GL_MAX_TEXTURE_SIZE" : " (GL_MAX_RENDERBUFFER_SIZE") +
                                    std::string(textures && renderbuffer ? " / GL_MAX_RENDERBUFFER_SIZE)" : ")"));
            return RttError::TooLarge;
        }
    }
    if (message) message->clear();
    return RttError::None;
}

}  // namespace cube::rtt
