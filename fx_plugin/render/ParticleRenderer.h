#pragma once
// The billboard renderer (one of Renderers.h's): per view it records what is visible
// (DrawList: culled, sorted, packed instances) and hands the view to one rendering path, which
// declares its passes through the host's FrameBuilder; the pass bodies upload the instances and
// draw (ParticleDraw) when the host executes them. The paths: FullResPath, QuarterResPath, and
// SmokeOpacityMap's pass for lit smoke; MegaRenderer and StatelessRenderer draw their techniques
// beside it. How the frame is drawn (shape, quarter res and its upsample, the light) comes in one
// FrameSettings value per declarePasses.
//
// Passes (names are data: they show in the host's pass list, debug groups and timings):
//   nothing at all when no particle is visible in the view (the host allocates nothing);
//   full res:    "particles"  reads sceneDepth only if a visible batch is soft or spherical,
//                             writes sceneColor;
//   quarter res: "particles_depth_downsample", "particles_quarter", "particles_composite"
//                with targets "particles_half_depth" (RG32F: min, max) and "particles_half_color"
//                (RGBA8; RGBA16F with spheres), both half x half, created through FrameBuilder::createTarget
//                (see QuarterResPath.h); where the choice waits for the passes
//                (ParticleView::quarter Pending: a host's frame graph, quarterResAlways off),
//                "particles" after them, and the first to run chooses (QuarterResPath::settle):
//                the passes not chosen return without a GL call.
//   tiled:       "particles_tiled" reads sceneDepth, writes sceneColor (RenderOptions::tiled:
//                TiledPath.h says where it draws; elsewhere the view is drawn at full res);
//                a view the GPU orders, binned in its passes, "particles_tiled_setup" before it
//                (the same reads and write: TiledPath::deferBins).
//
// GL: loaded by prepare() (Plugin::prepareGl), or else lazily by the first declarePasses() that
// finds a visible particle (the host has a context current by then; a scene without smoke never
// compiles a shader): the private GL table through the host's getProcAddress, shaders and atlas
// from inside the library, or from Config::shaderDir / Config::dataDir when set. Every shader
// compile/link error and a missing atlas is reported through HostAdapter::log as
// "file:line: message" (and as Diagnostics by prepare()); a technique whose program failed is
// not drawn, a missing atlas draws nothing, a failed quarter-res program falls back to full res.
// Every GL call runs inside a GlStateGuard, so the host's GL state after each pass (and after
// loading) equals the state before.
// Destroy the renderer with its GL context current (it deletes its GL objects).
//
// Depth testing (ParticleDraw::draw), never with depth writes: at full res hard particles always
// test the host's z-buffer (LEQUAL, or GEQUAL when ViewInfo::depth is ReversedZ), the legacy
// look. Soft and spherical particles test it under reversed-Z (GEQUAL; the engine's convention),
// which only drops fragments that would shade to nothing: their fade and visible chord come from
// linear depths compared in the shader, and a spherical particle's quad lies at its sphere's
// front, so a fragment behind the scene sees no chord. Under standard depth they are not
// z-tested: a 24-bit z-buffer at near 0.01 / far 100 km cannot resolve 100 m at 10 km, so the
// shader's fade alone hides them. At quarter res hard particles compare linear depths in the
// shader instead (HardLinearDepth: the half-res target has no copy of the host's z-buffer), and
// under reversed-Z every technique also tests a half-res z-buffer of each 2x2 block's farthest
// depth (QuarterResPath::beginQuarter); under standard depth nothing there is z-tested.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "DrawList.h"
#include "FrameSettings.h"
#include "FullResPath.h"
#include "ParticleDraw.h"
#include "QuarterResPath.h"
#include "RendererConfig.h"
#include "ShaderLoader.h"
#include "SmokeOpacityMap.h"
#include "TiledPath.h"
#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Plugin.h"

namespace fx {

class ParticleRenderer {
public:
    static constexpr const char* kFullResPass = FullResPath::kPass;
    enum class State { Unloaded, Ready, Failed };

    /// Builds and draws with the programs of `programs` (Renderers' cache, which outlives this).
    ParticleRenderer(RendererConfig config, ProgramCache& programs);
    ~ParticleRenderer();
    ParticleRenderer(const ParticleRenderer&) = delete;
    ParticleRenderer& operator=(const ParticleRenderer&) = delete;

    /// Declares this view's particle passes (or none) under the frame's `settings` and returns
    /// how many particles they draw. `batches` must stay valid for this call only; the pools they
    /// name must stay unchanged until the passes ran or settleLists() was called (a view the GPU
    /// bins leaves the writing of its particles to its first pass: DrawList::gatherPending).
    int declarePasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                      int batchCount, const FrameSettings& settings);
    /// Before any pool changes (the plugin: a step, a fire, a reload): each list a declared pass
    /// still holds whose gather is pending is written now, from the pools as they were declared;
    /// one no pass holds any more is dropped. The passes then draw what was declared.
    void settleLists();
    /// Lists settleLists() wrote out (those it dropped not counted), since the renderer was made.
    uint64_t listsSettled() const { return listsSettled_; }

    /// Loads GL resources now (Plugin::prepareGl) and builds every program the options can reach
    /// (ProgramCache::techniqueKeys) and the soft programs of the contrast powers in `powerSteps`
    /// (2 contrast_power each: those the loaded reactions draw with); with `quarterRes` also their
    /// quarter-res builds (ProgramCache::halfResKeys and the powers'); with `tiled`, where the
    /// context has compute shaders, the tiled path's (ProgramCache::tiledKeys). Called again after options
    /// or reactions change, it builds only what is missing. True when everything built; otherwise false with
    /// every problem appended to `out` (the technique that did build still draws). Each distinct
    /// "file:line: message" is logged once.
    bool prepare(Diagnostics* out, const std::vector<int>& powerSteps = {}, bool quarterRes = false,
                 bool tiled = false);

    /// A shader reload (Renderers::reload, one transaction over every renderer): true, once per
    /// edit, when Config::shaderDir is set, the renderer is loaded and a plugin shader file there
    /// ("particles" or "mega" in its name) changed since the running programs were built.
    bool shadersChanged();
    /// After a reload swapped the cache's programs: the passes take the new ones. Context current.
    void programsSwapped() { bindPassPrograms(); }

    /// Plugin::declareShadowPasses: with `light` on and shadow casters alive, declares the
    /// opacity map's pass and returns its target; the next declarePasses reuses it.
    SmokeShadow declareShadowPasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                                    int batchCount, const LightState& light);

    State state() const { return state_; }
    const std::string& shaderDir() const { return config_.shaderDir; }
    const InstanceStream& instanceStream() const { return draw_.stream(); }

private:
    bool ensureLoaded();
    /// The quarter-res passes and the opacity map take their programs from the running cache.
    void bindPassPrograms();
    void log(LogLevel level, const std::string& message) const { logTo(config_, level, message); }
    /// Logs the build lines of `errors` not logged before (each once, loadErrors_) and keeps them
    /// as diagnostics for prepare().
    void reportLoadErrors(const std::vector<std::string>& errors);
    /// Builds the programs `record`'s batches draw with that prepare() has not built (options or
    /// reactions changed since without another prepareGl): before any pass, never inside one.
    void ensureDrawPrograms(const ParticleView& record, bool quarterRes, bool tiled = false);
    /// Loads the renderer if needed, records the casters and declares the opacity pass.
    SmokeShadow declareOpacityPass(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                                   int batchCount, const LightState& light);

    RendererConfig config_;
    State state_ = State::Unloaded;
    ParticleDraw draw_;
    FullResPath fullRes_;
    QuarterResPath quarter_;
    TiledPath tiled_;
    SmokeOpacityMap opacity_;
    bool quarterFallbackLogged_ = false;
    bool frameBuildLogged_ = false;            ///< ensureDrawPrograms' warning, once
    std::vector<ProgramCache::Key> drawKeys_;  ///< ensureDrawPrograms' scratch, kept for its capacity
    Diagnostics loadDiagnostics_;  ///< what went wrong while loading (prepare() hands them out)
    ShaderErrorLog loadErrors_;    ///< the build lines already logged while loading (each once)
    SmokeShadow pendingShadow_;  ///< declared by declareShadowPasses, taken by the next declarePasses
                                 ///< into the host's frame graph (never by renderView's own frame)
    bool normalsWarned_ = false;
    uint64_t shaderStamp_ = 0;  ///< shaderStamp() when the running programs were built
    DrawListBuilder builder_;
    std::vector<std::shared_ptr<ParticleView>> records_;
    uint64_t listsSettled_ = 0;
    std::vector<std::shared_ptr<SmokeOpacityMap::Casters>> opacityRecords_;  ///< one per map until its pass ran
};

}  // namespace fx
