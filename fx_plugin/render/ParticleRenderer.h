#pragma once
// The particle renderer behind PluginImpl's render hook: per view it records what is visible
// (DrawList: culled, sorted, packed instances) and declares its passes through the host's
// FrameBuilder; the pass bodies upload the instances and draw when the host executes them.
//
// Passes (names are data: they show in the host's pass list, debug groups and timings):
//   nothing at all when no particle is visible in the view (the host allocates nothing);
//   full res:    "particles"  reads sceneDepth only if a visible batch is soft or spherical,
//                             writes sceneColor; with fade classification on (and a soft or
//                             spherical batch visible) "particles_tile_depth" comes first, reading
//                             sceneDepth and writing "particles_tiles" and "particles_tiles_coarse"
//                             (RG32F, FadeClassifier.h), which "particles" reads too;
//   quarter res: "particles_depth_downsample", "particles_quarter", "particles_composite"
//                with targets "particles_half_depth" (RG32F: min, max) and "particles_half_color"
//                (RGBA16F), both half x half, created through FrameBuilder::createTarget
//                (see QuarterResPath.h); mixed resolution adds "particles_edges" with the
//                full-size target "particles_edge_color" (RGBA16F + its own z-buffer).
//
// GL: loaded by prepare() (Plugin::prepareGl), or else lazily by the first declarePasses() that
// finds a visible particle (the host has a context current by then; a scene without smoke never
// compiles a shader): the private GL table through the host's getProcAddress, shaders and atlas
// from inside the library, or from Config::shaderDir / Config::dataDir when set. Every shader
// compile/link error and a missing atlas is reported through HostAdapter::log as
// "file:line: message" (and as Diagnostics by prepare()); a technique whose program failed is
// not drawn, a missing atlas draws nothing, a failed quarter-res program falls back to full res. Every GL call runs inside a GlStateGuard, so the
// host's GL state after each pass (and after loading) equals the state before.
// Destroy the renderer with its GL context current (it deletes its GL objects).
//
// Depth testing: hard particles at full res test the host's z-buffer (no writes; LEQUAL, or
// GEQUAL when ViewInfo::depth is ReversedZ), the legacy look. Soft and spherical particles do not: they compare linear depths in the shader,
// which stays exact at near 0.01 / far 100 km where a 24-bit z-buffer cannot resolve 100 m at
// 10 km, and a spherical particle's front may be visible where its quad is behind geometry.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ColorRampTexture.h"
#include "DrawList.h"
#include "FadeClassifier.h"
#include "GlStateGuard.h"
#include "InstanceStream.h"
#include "ProgramCache.h"
#include "LightState.h"
#include "QuarterResPath.h"
#include "SmokeAtlas.h"
#include "ShaderLoader.h"
#include "SmokeOpacityMap.h"
#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Plugin.h"

namespace fx {

class ApiErrors;

/// Defaults: no host (nothing is logged, and GL cannot be loaded), shaders and atlas embedded in
/// the library, refused calls not counted.
struct ParticleRendererConfig {
    HostAdapter* host = nullptr;
    std::string shaderDir;  ///< empty = the shaders embedded in the library
    std::string dataDir;    ///< empty = the atlas embedded in the library
    ApiErrors* errors = nullptr;  ///< where SizeMismatch is reported (may be null)
};

class ParticleRenderer {
public:
    static constexpr const char* kFullResPass = "particles";
    enum class State { Unloaded, Ready, Failed };

    explicit ParticleRenderer(ParticleRendererConfig config);
    ~ParticleRenderer();
    ParticleRenderer(const ParticleRenderer&) = delete;
    ParticleRenderer& operator=(const ParticleRenderer&) = delete;

    /// Declares this view's particle passes (or none) and returns how many particles they draw.
    /// `batches` must stay valid for this call only (instances are copied out).
    int declarePasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                      int batchCount, const RenderOptions& options);

    /// Loads GL resources now (Plugin::prepareGl) and builds every program the options can reach
    /// (ProgramCache::techniqueKeys, the fade classifier's when classification is on) and the
    /// soft programs of the contrast powers in `powerSteps` (2 contrast_power each: those the
    /// loaded reactions draw with). Called again after options or reactions change, it builds
    /// only what is missing. True when everything built; otherwise false with every problem
    /// appended to `out` (the technique that did build still draws). Each distinct
    /// "file:line: message" is logged once.
    bool prepare(Diagnostics* out, const std::vector<int>& powerSteps = {});

    /// Another renderer's part of a shader reload: builds its programs from the folder's current
    /// files, adds every failure to the log, and returns what makes them live (empty: nothing to
    /// swap). Its new programs are dropped when the returned function is dropped uncalled.
    using ShaderRebuild = std::function<std::function<void()>(ShaderErrorLog*)>;

    /// With Config::shaderDir set and the renderer loaded: when a plugin shader file there
    /// ("particles" or "mega" in its name) changed since the running programs were built, builds
    /// new programs, this renderer's and each of `others`'; all build -> they all go live
    /// (true); any fails -> every running program stays, the failure is logged once for this
    /// edit (each distinct line once) and appended to `out`, false. Needs the host's context
    /// current.
    bool reloadShaders(Diagnostics* out, const std::vector<ShaderRebuild>& others = {});

    /// The scene light (Plugin::setSceneLight) from the next declarePasses on.
    void setLight(const LightState& light) { light_ = light; }
    /// Plugin::declareShadowPasses: with the light on and shadow casters alive, declares the
    /// opacity map's pass and returns its target; the next declarePasses reuses it.
    SmokeShadow declareShadowPasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                                    int batchCount);

    /// Trimmed polygons or full quads for billboards, from the next declarePasses on.
    void setParticleShape(ParticleShape shape) { shape_ = shape; }
    /// Quarter res: depth-aware upsample everywhere, or mixed resolution (the edge pixels redrawn
    /// at full res, QuarterResPath.h), from the next declarePasses on.
    void setQuarterResEdges(QuarterResEdges edges) { edges_ = edges; }
    /// Fade classification at full res (FadeClassifier.h) and its counting, from the next
    /// declarePasses on.
    void setFadeClassification(bool classify, bool count) {
        classify_ = classify;
        countClasses_ = count;
    }
    /// The classes counted by the last full-res pass that ran with counting on.
    FadeClassCounts fadeClassCounts() const { return counts_; }

    State state() const { return state_; }
    const std::string& shaderDir() const { return config_.shaderDir; }
    const InstanceStream& instanceStream() const { return stream_; }

private:
    /// Texture units of the particle draws (all below GlStateGuard::kTextureUnits).
    static constexpr int kAtlasUnit = 0, kRampUnit = 1, kSceneDepthUnit = 2, kOpacityUnit = 3;

    /// One view's recorded draw, shared with the pass bodies until the host has run them.
    struct ViewRecord {
        ViewInfo view;
        DrawList list;
        ParticleShape shape = ParticleShape::Trimmed;
        QuarterResPath::ScreenRect rect;  ///< quarter res: where the particles can be
        QuarterResPath::ScreenTiles tiles;  ///< quarter res: the same, as screen tiles
        bool lit = false;                 ///< the scene light is on
        Target opacity;                   ///< the opacity map of this frame (invalid: unshadowed)
        glm::mat4 worldToShadow{1.0f};
    };

    bool ensureLoaded();
    uint64_t shaderStamp() const;
    /// True when `first` (and `second`, if valid: both targets this pass declared, sceneColor or
    /// sceneDepth) have the view's size; logs SizeMismatch if not.
    bool sizesAgree(PassContext& ctx, const ViewInfo& view, Target first, Target second);
    std::shared_ptr<ViewRecord> acquireRecord();
    void log(LogLevel level, const std::string& message) const;
    /// Logs the build lines of `errors` not logged before (each once, loadErrors_) and keeps them
    /// as diagnostics for prepare().
    void reportLoadErrors(const std::vector<std::string>& errors);
    /// Draws every batch of `record` into the bound target. `sceneDepth` is the linear depth
    /// texture of that target's size (0 when no batch needs it).
    /// `halfZ`: the bound target's own z-buffer was filled (the half-res z-test, or the mixed-res
    /// edge mask): z-test every batch (GEQUAL, LEQUAL under standard depth).
    /// `tiles`, `coarse`: the fade classifier's tile textures (0: soft and spherical particles
    /// drawn unclassified).
    void drawBatches(const ViewRecord& record, uint32_t sceneDepth, bool quarterRes, bool halfZ = false,
                     uint32_t opacity = 0, uint32_t tiles = 0, uint32_t coarse = 0);
    /// Builds the fade classifier (its tile and counting programs and the classified particle
    /// programs) if it is not built; false (logged once) when it does not build.
    bool ensureClassifier();
    /// Builds the programs `record`'s batches draw with that prepare() has not built (options or
    /// reactions changed since without another prepareGl): before any pass, never inside one.
    void ensureDrawPrograms(const ViewRecord& record, bool quarterRes, bool classified);
    /// Sets the FX_LIT uniforms of `p` for `batch` (the program is in use).
    void setLightUniforms(const ParticleProgram& p, const DrawBatch& batch, const ViewRecord& record,
                          uint32_t opacity) const;
    /// Loads the renderer if needed, records the casters and declares the opacity pass.
    SmokeShadow declareOpacityPass(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                                   int batchCount);
    void setRampRows(const ParticleBatch* batches, int batchCount);

    ParticleRendererConfig config_;
    State state_ = State::Unloaded;
    ParticleShape shape_ = ParticleShape::Trimmed;
    QuarterResEdges edges_ = QuarterResEdges::DepthAware;
    bool classify_ = false;
    bool countClasses_ = false;
    bool classifierFailed_ = false;
    std::unique_ptr<FadeClassifier> classifier_;  ///< built by prepare() when classification is on
    FadeClassCounts counts_;
    std::vector<glm::vec4> shapeTable_;  ///< atlas_.shapes().packed(), uploaded per draw
    std::vector<glm::vec4> discTable_;   ///< the same for spheres (TrimmedShapes::Clip::Disc)
    std::vector<glm::vec4> discInfo_;    ///< and their (inradius, area share)
    bool quarterFallbackLogged_ = false;
    Diagnostics loadDiagnostics_;  ///< what went wrong while loading (prepare() hands them out)
    ShaderErrorLog loadErrors_;    ///< the build lines already logged while loading (each once)
    ShaderReader sources_;         ///< the running programs' files (a snapshot), for later builds
    SmokeAtlas atlas_;
    ColorRampTexture ramp_;
    InstanceStream stream_;
    NearestSampler depthSampler_;  ///< the scene depth's unit, whatever sampling the host set
    // Owned through pointers so a shader reload can build new ones beside them and swap.
    std::unique_ptr<ProgramCache> programs_ = std::make_unique<ProgramCache>();
    std::vector<ProgramCache::Key> drawKeys_;  ///< ensureDrawPrograms' scratch, kept for its capacity
    bool frameBuildLogged_ = false;
    std::unique_ptr<QuarterResPath> quarter_ = std::make_unique<QuarterResPath>();
    std::unique_ptr<SmokeOpacityMap> opacity_ = std::make_unique<SmokeOpacityMap>();
    LightState light_;
    SmokeShadow pendingShadow_;  ///< declared by declareShadowPasses, taken by the next declarePasses
    bool normalsWarned_ = false;
    uint64_t shaderStamp_ = 0;  ///< shaderStamp() when the running programs were built
    DrawListBuilder builder_;
    std::vector<std::shared_ptr<ViewRecord>> records_;
    std::vector<const std::vector<ColorStop>*> rampInputs_;
};

}  // namespace fx
