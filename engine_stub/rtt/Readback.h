#pragma once
// Reading render targets back to CPU memory (tests, screenshots, image-error reports). Every
// result is rows top-down (row 0 = the top of the image), tightly packed, ready for a PNG
// writer. Pixel-pack state (alignment, row length, skips, swap bytes, pack buffer, read
// clamping) and framebuffer bindings are saved, set for the read, and restored.
// Read-backs stall the pipeline (glReadPixels waits for rendering): not for per-frame use.
#include <cstdint>
#include <vector>

#include "rtt/RenderTargetHandle.h"
#include "rtt/RttError.h"

namespace cube::rtt {

class RenderTargetPool;

/// How readFloat lays out each pixel.
enum class FloatLayout : uint8_t {
    RGBA,    ///< 4 floats per pixel; channels the format lacks read as G = B = 0, A = 1 (GL rules)
    Native,  ///< the format's own channel count: R32F 1, RG32F 2, RGBA8/RGBA16F 4
};

/// Colour attachment as RGBA8 (width * height * 4 bytes). Float formats clamp to [0,1] and
/// round to the nearest 1/255. InvalidHandle / InvalidAttachment on bad input.
RttError readRGBA8(const RenderTargetPool& pool, RenderTargetHandle target, int attachment,
                   std::vector<uint8_t>* out);
/// Colour attachment of any format as float, unclamped (RGBA8 gives k/255). `channels`
/// (optional) receives the floats per pixel written.
RttError readFloat(const RenderTargetPool& pool, RenderTargetHandle target, int attachment,
                   FloatLayout layout, std::vector<float>* out, int* channels = nullptr);
/// The depth attachment (shared or own, texture or renderbuffer) as window-space depth in
/// [0,1], one float per pixel. InvalidAttachment when the target has no depth.
RttError readDepth(const RenderTargetPool& pool, RenderTargetHandle target, std::vector<float>* out);
/// The default framebuffer's current read buffer, (0,0,width,height), RGBA8 top-down: what
/// present() showed.
void readDefaultFramebufferRGBA8(int width, int height, std::vector<uint8_t>* out);

}  // namespace cube::rtt
