#pragma once
// Where a view's passes read the scene depth, and how they turn it into metres
// (shaders/particles_scene_depth.glsl).
//
// Two forms, chosen once per view when its passes are declared (sceneDepthSource):
//  - the z-buffer the opaque scene was drawn into (FrameBuilder::sceneZBuffer, API 2.1), sampled
//    in place while the particle passes depth-test against it with depth writes off, and decoded
//    per fragment with the inversion of DepthMapping.h. Nothing is written for it: no second
//    colour target in the host's opaque pass, no copy, no linearise pass. Reading a depth texture
//    that is attached to the framebuffer being drawn is defined only with texture barriers
//    (GL 4.5, ARB_texture_barrier) between the writes and the reads, and only while nothing
//    writes it; so it is taken only where glTextureBarrier is loaded, and every pass that samples
//    it calls it first (useSceneDepth).
//  - the linear R32F depth the host makes (FrameBuilder::sceneDepth, the API 2.0 contract):
//    every host that offers no z-buffer, a z-buffer whose mapping is not one GL can have, and
//    contexts without texture barriers. Decoded with the identity (t = d, bit for bit).
//
// Where the view lies in it (API 2.1, a view anywhere in the framebuffer): the passes address the
// scene depth by the view's own pixel, p = gl_FragCoord - drawOrigin (drawOrigin: the view's
// origin in the framebuffer being drawn, sceneColor's viewport origin or 0 for the plugin's own
// targets), then read texel p + texel (placedFor): a depth texture of the view's size holds the
// view alone (texel 0: the plugin's copy, a host's per-view linear depth), any other size holds
// the whole framebuffer with the view at its viewport origin (the host's z-buffer of sceneColor).
// With the view at (0, 0) of its own target every offset is 0 and the reads are the 2.0 ones.
#include <cstdint>

#include <glm/glm.hpp>

#include "DepthMapping.h"
#include "fx/HostAdapter.h"

namespace fx {

/// The coefficients of linearSceneDepth() (particles_scene_depth.glsl). Defaults: the identity
/// for linear depth (A = 0, B = 1, C = 1, D = 0; nothing drawn only where t <= 0).
struct SceneDepthDecode {
    float a = 0.0f, b = 1.0f, c = 1.0f, d = 0.0f;
    bool zBuffer = false;       ///< decodes a z-buffer (the passes need a texture barrier first)
    glm::ivec2 texel{0};        ///< the depth texel of the view's pixel (0, 0) (placedFor)
    glm::ivec2 viewSize{0};     ///< the view's size: the full-screen passes' bounds (placedFor)
    glm::ivec2 drawOrigin{0};   ///< the view's pixel (0, 0) in the framebuffer the pass draws into
    glm::ivec2 depthSize{0};    ///< the depth texture's size (placedFor); 0 = not known yet

    static SceneDepthDecode linear() { return SceneDepthDecode{}; }
    /// This decode for the depth texture `depth` of `view`, read by a pass that draws into
    /// sceneColor (`intoSceneColor`: the view's rectangle of it) or into a target of the
    /// plugin's (its own (0, 0)). The rule in the header comment above.
    SceneDepthDecode placedFor(const TextureRef& depth, const ViewInfo& view, bool intoSceneColor) const;
    /// A z-buffer drawn with `proj` under `mapping` (DepthMapping.h's inversion).
    static SceneDepthDecode ofZBuffer(const glm::mat4& proj, const DepthMapping& mapping);
};

/// The scene depth a view's passes read: `target` (sceneZBuffer or sceneDepth) and its decode.
struct SceneDepthSource {
    Target target;
    SceneDepthDecode decode;
};

/// The z-buffer where the host offers one and it can be sampled in place, else sceneDepth.
/// Declares nothing; the caller lists `target` among the reads of each pass that samples it.
SceneDepthSource sceneDepthSource(FrameBuilder& frame, const ViewInfo& view);

/// True when glTextureBarrier is loaded (GL 4.5 or ARB_texture_barrier): the z-buffer can be
/// sampled while it is attached to the framebuffer a pass draws into.
bool canSampleZBufferInPlace();

/// The view's origin in a depth texture of w x h: 0 when it is the view's size, else the origin.
glm::ivec2 viewOriginInDepth(int w, int h, const ViewInfo& view);

/// Uniform locations of uDepthCoeffs, uDepthWindow and uDrawOrigin in one program.
struct SceneDepthUniforms {
    int coeffs = -1, window = -1, drawOrigin = -1, uv = -1;
    /// Looks them up in `program` (uDepthUv: the billboard programs' sceneDepthAt only).
    void locate(uint32_t program);
};
/// Sets the decode (and its placement) on the program in use. uDepthUv, the texture coordinate
/// of a fragment (gl_FragCoord * zw + xy), needs decode.depthSize.
void setSceneDepthDecode(const SceneDepthUniforms& at, const SceneDepthDecode& decode);
/// Once per pass that samples the z-buffer, before its first draw: a texture barrier, so the
/// host's depth writes are visible to the pass's fetches. Nothing for linear depth.
void sceneDepthBarrier(const SceneDepthDecode& decode);

}  // namespace fx
