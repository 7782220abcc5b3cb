#pragma once
// Mega-particles (`technique: mega`, RenderOptions::techniqueOverride = Mega; seed 001,
// Bahnassi & Bahnassi, "Volumetric Clouds and Mega-Particles"): the particles of a view whose
// technique resolves to Mega are drawn as lit spheres into a reduced-resolution target against
// the scene depth, blurred (depth-aware, separable Gaussian) until they melt into one volume,
// given fractal detail, lit, and composited onto sceneColor. The billboard renderer leaves these
// batches out (Mega is never among its usable techniques), so each particle is drawn once.
//
// Passes (declared only when a Mega batch is visible in the view; names are data):
//   mega_depth_downsample  reads sceneDepth                        writes mega_depth
//   mega_spheres           reads mega_depth                        writes mega_color, mega_density
//   mega_blur_h            reads mega_color, mega_density          writes mega_blur_color, mega_blur_density
//   mega_blur_v            reads mega_blur_color, mega_blur_density  writes mega_cloud, mega_cloud_depth
//                          (the vertical blur, then fractal noise and lighting: mega_shade.glsl)
//   mega_composite         reads mega_cloud, mega_cloud_depth, sceneDepth   writes sceneColor
// Targets (FrameBuilder::createTarget, scale = mega.resolution):
//   mega_depth        R32F     nearest scene depth of the covered full-res pixels (min)
//   mega_color        RGBA16F  sum of ramp rgb x tau; alpha: -(nearest sphere front depth)
//   mega_density      RGBA16F  sum of tau (optical depth), sum of view normal.xy x tau
//   mega_blur_*       the same two after the horizontal blur (alpha of colour: depth, 0 = none)
//   mega_cloud        RGBA16F  the finished cloud, premultiplied
//   mega_cloud_depth  R32F     its depth (0 where there is no cloud)
// Every sphere is summed (blend ONE, ONE; ADD for rgb, MAX for alpha, which keeps the nearest
// front as the largest -depth), not depth-tested against the others: each adds optical depth tau
// = kDensity x ramp alpha x life fade x (its chord, clipped to [near, scene depth], / diameter),
// so the pixel's coverage is 1 - exp(-sum tau): 1 through dense overlapping spheres, 0 at a rim,
// and a faint dying sphere in front never hides the dense cloud behind it (keeping only the
// nearest sphere did: measured on the burnout, the whole cloud turned as thin as its outermost,
// oldest spheres). Two RGBA16F attachments written together (MRT) rather than one RGBA32F (not a
// format the host must offer) or packing: colour sums and depth need four channels, density and
// the normal three more; half floats hold depth to 1/2048 of itself (clamped to 60000 m), far
// finer than the blur's depth falloff. The spheres pass and the blurs draw through the
// renderer's own framebuffer object with the host's textures of the pass as its attachments
// (FrameBuilder binds one target per pass).
//
// The pass bodies and their GL objects are MegaPasses (MegaPasses.h), the programs MegaPrograms.
//
// Per view, the first visible Mega batch's `mega:` and `lighting:` keys and render.softness
// apply to the whole cloud (every Mega reaction of the view melts into one volume); each
// particle keeps its own reaction's colour ramp. The composite blends premultiplied "over"
// whatever the reaction's blend mode. Lit when the plugin has a scene light (LightState::on)
// (FrameSettings::light) and the reaction's lighting is on (LightingDesc::lit); otherwise the
// ramp colour, unlit.
//
// RenderOptions::quarterRes does not apply (mega.resolution is the technique's own). Live shader
// edits (Plugin::pollShaderReload) rebuild the mega programs with every other one, in one
// transaction (Renderers::reload, one swap of the ProgramCache): a broken mega file keeps every
// last good program and is reported.
//
// The noise is animated by the first Mega batch's simulation clock (ParticleBatch::time): two
// frames of a paused simulation from a still camera are byte-identical.
//
// GL: loaded on the first view with a visible Mega batch, or by prepare(). Every GL call runs
// inside a GlStateGuard; the framebuffer object detaches the host's textures before the pass
// ends. A shader that fails to build is logged ("file:line: message") and Mega batches are then
// not drawn. No z-buffer of the host is used: every depth test compares linear depths, so the
// technique works alike under standard and reversed-Z.
#include <memory>
#include <string>
#include <vector>

#include "DrawList.h"
#include "FrameSettings.h"
#include "MegaPasses.h"
#include "RendererConfig.h"
#include "ShaderLoader.h"
#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Plugin.h"

namespace fx {

class MegaRenderer {
public:
    static constexpr const char* kDepthPass = "mega_depth_downsample";
    static constexpr const char* kSpheresPass = "mega_spheres";
    static constexpr const char* kBlurHPass = "mega_blur_h";
    static constexpr const char* kBlurVPass = "mega_blur_v";
    static constexpr const char* kCompositePass = "mega_composite";
    static constexpr float kDepthFalloff = MegaPasses::kDepthFalloff;
    static constexpr float kDensity = MegaPasses::kDensity;

    /// `config.dataDir` is not used (mega draws no atlas).
    /// Builds and draws with the programs of `programs` (Renderers' cache, which outlives this).
    MegaRenderer(RendererConfig config, ProgramCache& programs);
    ~MegaRenderer();
    MegaRenderer(const MegaRenderer&) = delete;
    MegaRenderer& operator=(const MegaRenderer&) = delete;

    /// Declares this view's Mega passes (none when no batch resolved to Mega is visible) under
    /// the frame's `settings` and returns how many particles they draw. `batches` must stay
    /// valid for this call only.
    int declarePasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                      int batchCount, const FrameSettings& settings);

    /// Builds the programs into the cache now (Plugin::prepareGl); false with the problems
    /// appended to `out`.
    bool prepare(Diagnostics* out);
    /// After a reload swapped the cache's programs: a loaded renderer takes the new ones. Context
    /// current.
    void programsSwapped();
    bool ready() const { return state_ == State::Ready; }

private:
    enum class State { Unloaded, Ready, Failed };

    bool ensureLoaded();
    void log(LogLevel level, const std::string& message) const { logTo(config_, level, message); }

    RendererConfig config_;
    State state_ = State::Unloaded;
    Diagnostics loadDiagnostics_;
    ProgramCache& programs_;
    MegaPasses passes_;
    DrawListBuilder builder_;
    std::vector<std::shared_ptr<MegaCloud>> records_;
};

}  // namespace fx
