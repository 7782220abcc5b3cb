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

namespace {

// Each status with its own spelling, written once (a name cannot drift from its value).
#define CUBE_FRAMEBUFFER_STATUS(status) {status, #status}
const struct {
    uint32_t status;
    const char* name;
} kFramebufferStatuses[] = {
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_COMPLETE),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_UNDEFINED),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_UNSUPPORTED),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE),
    CUBE_FRAMEBUFFER_STATUS(GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS),
};
#undef CUBE_FRAMEBUFFER_STATUS

}  // namespace

RttError rttErrorFromFramebufferStatus(uint32_t glStatus, const char** statusName) {
    const char* name = "unknown framebuffer status";
    for (const auto& s : kFramebufferStatuses) {
        if (s.status == glStatus) name = s.name;
    }
    if (statusName) *statusName = name;
    return glStatus == GL_FRAMEBUFFER_COMPLETE ? RttError::None : RttError::FramebufferIncomplete;
}

}  // namespace cube::rtt
