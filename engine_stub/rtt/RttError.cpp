#include "rtt/RttError.h"

#include "gl/Gl.h"

namespace cube::rtt {

const char* rttErrorName(RttError error) {
    switch (error) {
        case RttError::None: return "None";
        case RttError::InvalidSize: return "InvalidSize";
        case RttError::InvalidScale: return "InvalidScale";
        case RttError::TooLarge: return "TooLarge";
        case RttError::NoAttachments: return "NoAttachments";
        case RttError::TooManyColorAttachments: return "TooManyColorAttachments";
        case RttError::ColorAttachmentGap: return "ColorAttachmentGap";
        case RttError::InvalidFormat: return "InvalidFormat";
        case RttError::SharedDepthInvalid: return "SharedDepthInvalid";
        case RttError::SharedDepthSizeMismatch: return "SharedDepthSizeMismatch";
        case RttError::SharedDepthConflict: return "SharedDepthConflict";
        case RttError::FramebufferIncomplete: return "FramebufferIncomplete";
        case RttError::AllocationFailed: return "AllocationFailed";
        case RttError::InvalidHandle: return "InvalidHandle";
        case RttError::InvalidAttachment: return "InvalidAttachment";
        case RttError::FormatMismatch: return "FormatMismatch";
        case RttError::Count: break;
    }
    return "?";
}

RttError rttErrorFromFramebufferStatus(uint32_t glStatus, const char** statusName) {
    const char* name = "unknown framebuffer status";
    switch (glStatus) {
        case GL_FRAMEBUFFER_COMPLETE: name = "GL_FRAMEBUFFER_COMPLETE"; break;
        case GL_FRAMEBUFFER_UNDEFINED: name = "GL_FRAMEBUFFER_UNDEFINED"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: name = "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            name = "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
            break;
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: name = "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: name = "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER"; break;
        case GL_FRAMEBUFFER_UNSUPPORTED: name = "GL_FRAMEBUFFER_UNSUPPORTED"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: name = "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            name = "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
            break;
        default: break;
    }
    if (statusName) *statusName = name;
    return glStatus == GL_FRAMEBUFFER_COMPLETE ? RttError::None : RttError::FramebufferIncomplete;
}

}  // namespace cube::rtt
