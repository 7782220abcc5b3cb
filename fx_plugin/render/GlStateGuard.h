#pragma once
// GlStateGuard: the scope every GL call of fx_plugin/render/ runs in (prepareGl's and
// declarePasses' lazy loading, each pass callback the plugin hands the host's frame graph,
// declareShadowPasses' pass, pollShaderReload, and the deletion of the plugin's GL objects).
// The table behind it is PinnedGlState.cpp; one row per value below.
//
// Contract:
//  - host state never reaches the plugin's image: the constructor reads every state listed
//    below and sets each "pinned" one to the value given (a row the host left at that value is
//    not written again), so the pixels the plugin writes and the GL objects it fills depend
//    only on its own inputs, whatever the host left bound, enabled or configured;
//  - the host gets its state back: the destructor writes every listed value back, pinned or
//    not, in reverse order; after any plugin call or pass each listed state reads what the
//    host had before it;
//  - no GL error in a core context: compatibility-only rows ([compat]) exist only when
//    GL_CONTEXT_PROFILE_MASK has no core bit; clip control only with GL 4.5 or
//    ARB_clip_control; primitive restart fixed index only with GL 4.3;
//  - the z-mapping follows the view: a guard around a pass that is z-tested against (or
//    writes) a z-buffer of the view takes the view's DepthConvention and sets clip control to
//    (GL_LOWER_LEFT, Standard: GL_NEGATIVE_ONE_TO_ONE / ReversedZ: GL_ZERO_TO_ONE) and the depth
//    range to [0, 1], the mapping fx::ViewInfo::proj was built for; inside a
//    HostDepthMappingScope (the immediate path) the host's stated mapping instead; a guard
//    without one (loading, passes that draw no z-tested geometry) uses Standard;
//  - cost: on entry every row is read (about 150 glGet calls for the rows below) and the rows
//    the host left off their pinned value are set; on exit every row is written back (no
//    allocation: the saved values live in the guard); a few guards a frame (their measured cost
//    is in docs/results.md, session 12).
//
// Pinned (set on entry, restored on exit):
//   texture units 0..kTextureUnits-1: GL_TEXTURE_2D binding 0, sampler object 0,
//     [compat] texture LOD bias (GL_TEXTURE_FILTER_CONTROL) 0; active texture GL_TEXTURE0;
//   pixel unpack and pack buffer bindings 0; unpack and pack swap bytes false, lsb first false,
//     alignment 4, row length 0, skip rows 0, skip pixels 0, image height 0, skip images 0;
//   clamp read colour GL_FIXED_ONLY (the fade-class counter reads floats back); [compat] pixel
//     transfer: red/green/blue/alpha/depth scale 1 and bias 0, map colour false, map stencil
//     false, index shift 0, index offset 0;
//   rasteriser discard off; primitive restart off, fixed index off, index 0; provoking vertex
//     GL_LAST_VERTEX_CONVENTION; clip distances 0..GL_MAX_CLIP_DISTANCES-1 off (in a
//     compatibility context the same enables are the user clip planes GL_CLIP_PLANEi);
//     clip control and depth range: see above; depth clamp off;
//   polygon mode GL_FILL (front and back: set apart in a compatibility context); [compat]
//     polygon stipple off; polygon offset fill/line/point off, factor 0, units 0; polygon and
//     line smooth off; line width 1; program point size off; point size 1; cull face off;
//   multisample on; sample coverage off, value 1, invert false; alpha to coverage off, alpha to
//     one off; sample mask off, mask word 0 all ones; fragment shader derivative hint
//     GL_DONT_CARE; [compat] clamp fragment colour GL_FIXED_ONLY, clamp vertex colour true;
//     texture cube map seamless off;
//   [compat] alpha test off, alpha func GL_ALWAYS ref 0; scissor test off; stencil test off,
//     front and back: func GL_ALWAYS ref 0 mask all ones, ops GL_KEEP x3, writemask all ones;
//     depth test off, func GL_LESS, writemask true; for each draw buffer
//     0..GL_MAX_DRAW_BUFFERS-1: blend off (glDisablei) and colour writemask all true
//     (glColorMaski); blend func GL_ONE, GL_ZERO (RGB and alpha), equation GL_FUNC_ADD (both),
//     blend colour 0; framebuffer sRGB off; dither off; colour logic op off, logic op GL_COPY;
//     clear colour 0.
// Restored only (the plugin binds or sets its own before any use): program, vertex array (the
//   element buffer and the attribute divisors are the plugin's own VAOs' state), GL_ARRAY_BUFFER,
//   draw and read framebuffers, viewport, scissor box.
// Counts (llvmpipe: 8 clip distances, 8 draw buffers, GL 4.5; per-index rows counted apart):
//   110 rows in a core context; 136 in a compatibility one (109 + 27 compatibility-only: the
//   core polygon-mode row becomes one per face).
//
// Not listed, and why: cull face mode and front face (culling stays off); fixed-function vertex
//   and fragment state (lighting, fog, texture enables, colour sum, shade model, two-sided
//   colour; every plugin draw has a program bound, which replaces all of it); line and point
//   stipple / smooth and point sprite (with polygon mode pinned to GL_FILL the plugin draws only
//   filled triangles); uniform buffer bindings (the plugin's shaders have no uniform blocks);
//   per-draw-buffer blend func / equation (glBlendFunci is GL 4.0: a host's indexed values on
//   draw buffers >= 1 are not restored); transform feedback and conditional rendering (a host
//   must not leave either active across a plugin call: GL 3.3 cannot query them).
#include <array>
#include <cstdint>

#include "fx/Types.h"
#include "render/GlStateRow.h"

namespace fx {

/// Binds `texture` to GL_TEXTURE_2D of texture unit `unit` (below GlStateGuard::kTextureUnits, so
/// a guard puts the host's binding back) with `sampler` on the unit: by default none, since a host
/// sampler bound there would override the texture's own filtering. Leaves `unit` active.
void bindTextureUnit(int unit, uint32_t texture, uint32_t sampler = 0);

/// A sampler object that reads level 0 of a texture clamped to its edge, nearest or linear,
/// whatever the texture's own parameters.
/// - Nearest: the host's scene depth is read through it. A host may leave linear filtering on it
///   (the particle shaders read it with textureLod at texel centres, exact only unfiltered), or
///   GL's default mipmapped minification filter on a texture with one level, which leaves the
///   texture incomplete (texelFetch and texture both read 0 there) unless a sampler with a plain
///   filter is bound.
/// - Linear: the quarter-res composite's half-res colour, whose bilinear weights the filter
///   computes (a host's frame graph may not honour TargetDesc::linearFilter).
/// - LinearNearestMip: bilinear within the nearest mip level (GL_LINEAR_MIPMAP_NEAREST), the
///   levels the texture has: the particles' atlas reads (one level, half trilinear's texels).
class ClampSampler {
public:
    enum class Filter { Nearest, Linear, LinearNearestMip };
    explicit ClampSampler(Filter filter = Filter::Nearest) : filter_(filter) {}
    ~ClampSampler();
    ClampSampler(const ClampSampler&) = delete;
    ClampSampler& operator=(const ClampSampler&) = delete;
    void create();
    /// bindTextureUnit with this sampler on `unit` (below GlStateGuard::kTextureUnits, so a guard
    /// restores the host's).
    void bindTexture(int unit, uint32_t texture) const;
    uint32_t name() const { return sampler_; }

private:
    Filter filter_;
    uint32_t sampler_ = 0;
};
using NearestSampler = ClampSampler;  ///< default-constructed: Filter::Nearest

/// The state every pass of the plugin starts its draws from (inside a guard): no depth test and
/// no depth writes, no culling, stencil, scissor or blending, every colour channel written.
void plainDrawState();
/// The depth test of a view's convention: on, LEQUAL (GEQUAL under reversed-Z); the depth
/// writemask is left as it is.
void depthTestFor(DepthConvention depth);

/// A KHR_debug group around a pass's GL calls (names the pass in a GL debugger's capture); nothing
/// where the context has no KHR_debug.
class DebugGroup {
public:
    explicit DebugGroup(const char* name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;

private:
    bool active_;
};

class GlStateGuard {
public:
    /// Texture units the renderer may bind (0 .. kTextureUnits-1).
    static constexpr int kTextureUnits = kPinnedTextureUnits;
    /// Rows a guard can hold (PinnedGlState.cpp bounds the per-index rows to fit).
    static constexpr int kMaxRows = 200;

    /// A guard around work that draws no z-tested geometry (loading, full-screen passes): clip
    /// control and depth range pinned to GL's defaults.
    GlStateGuard() : GlStateGuard(DepthConvention::Standard, false) {}
    /// `depth`: the z-mapping of the view whose z-buffer the guarded pass tests against or writes
    /// (see the contract above). Inside a HostDepthMappingScope the scope's mapping wins.
    explicit GlStateGuard(DepthConvention depth) : GlStateGuard(depth, true) {}
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    GlStateGuard(DepthConvention depth, bool viewDepth);
    std::array<GlStateValue, kMaxRows> saved_;
    int rows_ = 0;
};

/// The immediate path (Plugin::renderView): the host states how it drew its z-buffer (clip
/// control and depth range, DepthMapping), which need not be either of the two mappings a
/// DepthConvention names (a D3D-style [0, 1] projection under ZERO_TO_ONE without reversal, a
/// depth range of [0.2, 0.9], ...). While a scope is alive, every guard given a view's
/// DepthConvention pins clip control's depth mode and the depth range to the scope's mapping, so
/// the plugin's z-tested fragments land where the host's did. Scopes do not nest.
class HostDepthMappingScope {
public:
    HostDepthMappingScope(bool clipZeroToOne, float rangeNear, float rangeFar);
    ~HostDepthMappingScope();
    HostDepthMappingScope(const HostDepthMappingScope&) = delete;
    HostDepthMappingScope& operator=(const HostDepthMappingScope&) = delete;
};

}  // namespace fx
