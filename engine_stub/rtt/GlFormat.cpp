#include "rtt/GlFormat.h"

namespace cube::rtt {

GlFormat glFormat(ColorFormat format) {
    switch (format) {
        case ColorFormat::RGBA8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_NONE};
        case ColorFormat::RGBA16F: return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, GL_NONE};
        case ColorFormat::R32F: return {GL_R32F, GL_RED, GL_FLOAT, GL_NONE};
        case ColorFormat::RG32F: return {GL_RG32F, GL_RG, GL_FLOAT, GL_NONE};
        case ColorFormat::None: break;
    }
    return {};
}

GlFormat glFormat(DepthFormat format) {
    switch (format) {
        case DepthFormat::Depth24:
            return {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, GL_DEPTH_ATTACHMENT};
        case DepthFormat::Depth32F:
            return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, GL_DEPTH_ATTACHMENT};
        case DepthFormat::Depth24Stencil8:
            return {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
                    GL_DEPTH_STENCIL_ATTACHMENT};
        case DepthFormat::None: break;
    }
    return {};
}

}  // namespace cube::rtt
