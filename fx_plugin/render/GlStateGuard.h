#pragma once
// Scoped snapshot of every piece of GL state the particle renderer changes: taken on
// construction, put back on destruction. The plugin promises its host that GL state after any
// of its passes (and after its lazy GL loading) equals the state before; every GL call of
// fx_plugin/render/ runs inside one of these guards.
//
// Who restores what: the guard restores everything below, including the framebuffer bindings and
// the viewport that PassContext::bindForDraw() changes, so a host needs no assumptions about the
// plugin's passes. Captured:
//   program, vertex array, GL_ARRAY_BUFFER (the element buffer is vertex-array state: the
//   renderer never binds one, and restoring the VAO restores it), active texture unit, the
//   GL_TEXTURE_2D binding and sampler object of units 0..kTextureUnits-1, blend enable, blend
//   func and equation (separate RGB/alpha), depth test, depth func, depth mask, cull-face
//   enable, stencil-test enable, scissor-test enable and box, colour mask, clear colour, viewport,
//   draw and read framebuffers, GL_PIXEL_UNPACK_BUFFER and the unpack alignment / row length /
//   skip values (texture uploads), GL_PIXEL_PACK_BUFFER and the pack alignment / row length /
//   skip values (the fade-class counter's read-back). In a compatibility context also
//   GL_ALPHA_TEST, which the guard disables for its scope (it applies to shader output there).
// Not captured (the renderer neither changes nor depends on them): per-draw-buffer blend state
// (glEnablei), polygon mode/offset, depth range and clamp, stencil func/ops, sample coverage.
#include <cstdint>

namespace fx {

/// Binds `texture` to GL_TEXTURE_2D of texture unit `unit` (below GlStateGuard::kTextureUnits, so
/// a guard puts the host's binding back) with `sampler` on the unit: by default none, since a host
/// sampler bound there would override the texture's own filtering. Leaves `unit` active.
void bindTextureUnit(int unit, uint32_t texture, uint32_t sampler = 0);

/// A sampler object that reads a texture with GL_NEAREST and GL_CLAMP_TO_EDGE, one level, whatever
/// the texture's own parameters. The host's scene depth is read through it: a host may leave
/// linear filtering on it (the particle shaders read it with textureLod at texel centres, exact
/// only unfiltered), or GL's default mipmapped minification filter on a texture with one level,
/// which leaves the texture incomplete (texelFetch and texture both read 0 there) unless a
/// sampler with a plain filter is bound.
class NearestSampler {
public:
    NearestSampler() = default;
    ~NearestSampler();
    NearestSampler(const NearestSampler&) = delete;
    NearestSampler& operator=(const NearestSampler&) = delete;
    void create();
    /// bindTextureUnit with this sampler on `unit` (below GlStateGuard::kTextureUnits, so a guard
    /// restores the host's).
    void bindTexture(int unit, uint32_t texture) const;

private:
    uint32_t sampler_ = 0;
};

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
    static constexpr int kTextureUnits = 6;

    GlStateGuard();
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    struct State {
        int program = 0, vertexArray = 0, arrayBuffer = 0, activeTexture = 0;
        int texture2D[kTextureUnits] = {};
        int sampler[kTextureUnits] = {};
        bool blend = false;
        int blendSrcRgb = 0, blendDstRgb = 0, blendSrcAlpha = 0, blendDstAlpha = 0;
        int blendEqRgb = 0, blendEqAlpha = 0;
        bool depthTest = false, depthMask = true;
        int depthFunc = 0;
        bool cullFace = false, stencilTest = false, scissorTest = false;
        bool alphaTest = false;  // compatibility context: was on, disabled for the guard's scope
        int scissorBox[4] = {};
        bool colorMask[4] = {true, true, true, true};
        float clearColor[4] = {};
        int viewport[4] = {};
        int drawFramebuffer = 0, readFramebuffer = 0;
        int unpackBuffer = 0, unpackAlignment = 4, unpackRowLength = 0, unpackSkipRows = 0,
            unpackSkipPixels = 0, unpackImageHeight = 0, unpackSkipImages = 0;
        int packBuffer = 0, packAlignment = 4, packRowLength = 0, packSkipRows = 0, packSkipPixels = 0;
    };
    State saved_;
};

}  // namespace fx
