#pragma once
// Named error codes of the render-to-texture layer (sokol-style: one code per validation rule,
// tests assert the code, not the message). Bad descriptors and driver refusals are reported
// with these; nothing here asserts or crashes on bad data.
#include <cstdint>

namespace cube::rtt {

enum class RttError : uint8_t {
    None = 0,
    InvalidSize,              ///< negative width/height, or exactly one of them 0
    InvalidScale,             ///< relative target with scale <= 0, NaN or infinite
    TooLarge,                 ///< above GL_MAX_TEXTURE_SIZE / GL_MAX_RENDERBUFFER_SIZE
    NoAttachments,            ///< no colour, no depth and no shared depth
    TooManyColorAttachments,  ///< more colour attachments than the driver (or pool limit) allows
    ColorAttachmentGap,       ///< a colour attachment after a ColorFormat::None one
    InvalidFormat,            ///< an enum value outside the listed formats
    SharedDepthInvalid,       ///< sharedDepth is stale/invalid, or that target owns no depth
    SharedDepthSizeMismatch,  ///< sharedDepth target has a different size or sizing rule
    SharedDepthConflict,      ///< both an own depth format and a shared depth were given
    FramebufferIncomplete,    ///< the driver refused the format combination (status in message)
    AllocationFailed,         ///< GL reported an error (e.g. GL_OUT_OF_MEMORY) while allocating
    InvalidHandle,            ///< a stale or never-issued RenderTargetHandle
    InvalidAttachment,        ///< attachment index out of range, unused, or no depth to read
    FormatMismatch,           ///< blit between depth buffers of different formats
    Count
};

/// "None", "InvalidSize", ... (the enumerator's name); "?" for out-of-range values.
const char* rttErrorName(RttError error);

/// Maps a glCheckFramebufferStatus result: GL_FRAMEBUFFER_COMPLETE -> None, anything else ->
/// FramebufferIncomplete. `statusName` (optional) receives e.g. "GL_FRAMEBUFFER_UNSUPPORTED".
RttError rttErrorFromFramebufferStatus(uint32_t glStatus, const char** statusName = nullptr);

}  // namespace cube::rtt
