#pragma once
// What a render target looks like: size rule, attachments and sampling. Plain data, no GL.
#include <array>
#include <cstdint>
#include <string>

#include "rtt/RenderTargetHandle.h"
#include "rtt/RttError.h"

namespace cube::rtt {

constexpr int kMaxColorAttachments = 4;

enum class ColorFormat : uint8_t { None = 0, RGBA8, RGBA16F, R32F, RG32F };
enum class DepthFormat : uint8_t { None = 0, Depth24, Depth32F, Depth24Stencil8 };
enum class Filter : uint8_t { Linear = 0, Nearest };
enum class Wrap : uint8_t { Clamp = 0, Repeat };

const char* colorFormatName(ColorFormat format);
const char* depthFormatName(DepthFormat format);
/// Channels a colour format stores (RGBA8 4, RGBA16F 4, R32F 1, RG32F 2; None 0).
int channelCount(ColorFormat format);

/// Defaults: follows the view at full size (width = height = 0, scale = 1), one RGBA8 colour
/// attachment, no depth, depth (when given) as a renderbuffer, no shared depth, linear
/// filtering, clamp to edge, empty debug name.
///
/// Size: absolute when width and height are both > 0, otherwise relative to the pool's view
/// size: max(1, ceil(view * scale)) per axis, so scale 1/2 gives (w+1)/2 and 1/4 gives (w+3)/4
/// (odd sizes round up, a 0x0 view gives 1x1). Relative sizes clamp to the driver's limits.
/// Colour attachments are used from index 0 up to the first ColorFormat::None.
struct RenderTargetDesc {
    int width = 0;        ///< absolute size in pixels; 0 (with height 0) = relative to the view
    int height = 0;
    float scale = 1.0f;   ///< relative size factor (1, 0.5, 0.25 ...) when width/height are 0
    std::array<ColorFormat, kMaxColorAttachments> color = {ColorFormat::RGBA8, ColorFormat::None,
                                                           ColorFormat::None, ColorFormat::None};
    DepthFormat depth = DepthFormat::None;
    /// Depth is a texture (RenderTargetPool::depthTexture) instead of a renderbuffer. Needed
    /// when a pass samples the depth; FrameGraph sets it itself for PassBuilder::readDepth.
    bool sampledDepth = false;
    /// Use this live target's depth attachment instead of owning one (depth must be None; the
    /// other target must have the same width/height/scale rule). Clearing or writing depth
    /// through this target changes the other target's depth.
    RenderTargetHandle sharedDepth;
    Filter filter = Filter::Linear;
    Wrap wrap = Wrap::Clamp;
    /// Debug name (GL object label under KHR_debug). Copied by the pool; not part of matching.
    const char* name = "";
};

/// True for a relative-size descriptor (width and height both 0).
inline bool isRelative(const RenderTargetDesc& desc) { return desc.width == 0 && desc.height == 0; }
/// True when both always resolve to the same size: the same absolute size, or both relative
/// with the same scale. Required of targets sharing a depth attachment.
bool sameSizeRule(const RenderTargetDesc& a, const RenderTargetDesc& b);
/// Number of colour attachments in use (up to the first None).
int colorAttachmentCount(const RenderTargetDesc& desc);

/// The one place sizes resolve: absolute sizes pass through, relative ones become
/// max(1, ceil(viewW * scale)) x max(1, ceil(viewH * scale)) clamped to maxSize (0 = no clamp).
/// The product is snapped by 1e-6 relative so float scales such as 1/3 do not round up a pixel.
void resolveSize(const RenderTargetDesc& desc, int viewWidth, int viewHeight, int maxSize,
                 int* width, int* height);

/// Limits a descriptor is checked against (the pool fills them from the driver).
struct RenderTargetLimits {
    int maxTextureSize = 0;       ///< GL_MAX_TEXTURE_SIZE
    int maxRenderbufferSize = 0;  ///< GL_MAX_RENDERBUFFER_SIZE
    int maxColorAttachments = 0;  ///< min(GL_MAX_COLOR_ATTACHMENTS, GL_MAX_DRAW_BUFFERS, 4)
};

/// Checks the rules that need no GL objects (all but SharedDepth{Invalid,SizeMismatch} and
/// driver refusals). `message` (optional) names the field and what was expected.
RttError validateDesc(const RenderTargetDesc& desc, const RenderTargetLimits& limits,
                      std::string* message = nullptr);

}  // namespace cube::rtt
