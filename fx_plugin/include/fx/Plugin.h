#pragma once
// The C++ layer of the plugin's API (API 2: a header-only face over the C table of fx/fx.h,
// compiled into the host; fx/detail/PluginBridge.h). fxCreatePlugin takes the host's imports and
// returns the plugin, or null on a version mismatch; fx::Plugin is the interface the host drives.
//
// What a host does, in order:
//   1. fxApiVersion() (optional): which plugin library was loaded.
//   2. fxCreatePlugin(imports) with apiVersion = kApiVersion and its HostAdapter. No GL needed.
//   3. loadReactions(path) (a .yaml file or a folder of them). No GL needed.
//   4. setRenderOptions(...) if the host overrides techniques, then prepareGl() with its GL
//      context current (optional but recommended: compiles every program the loaded reactions
//      and the options can draw with and uploads the atlas now, so a broken shader of any
//      technique fails start-up with file:line instead of the first frame with smoke). Call it
//      again after changing options or reloading reactions: it builds only what the change
//      reaches, so no frame compiles. A host that does not gets those programs built while the
//      next frame is declared (logged once as a warning); no pass ever compiles.
//   5. Each simulation step: continueReaction(i, dt, &collision) for i in 0 .. reactionCount()-1.
//   6. Each frame, each view, after its opaque scene and sky, either
//        - renderView(view, depth) (API 2, engines without a frame graph): draws the smoke into the
//          framebuffer bound for drawing, reading the scene depth from its own z-buffer by
//          default; or
//        - declarePasses(view, frame) while building the host's frame graph; the host then
//          executes the declared passes in order with its context current.
//   7. pollHotReload() whenever it likes (e.g. once a second); no GL needed. With a shaderDir
//      override, pollShaderReload() (context current) picks up shader edits.
//   8. Destroy the plugin with the same GL context current (it deletes its GL objects).
//
// Threading: the plugin is not thread-safe. Call it from one thread at a time; the calls that
// touch GL (prepareGl, declarePasses, renderView, the pass callbacks, destruction) from the
// thread where the host's context is current. Several plugin instances may live in one process
// if they share a GL context family (the private loader's entry points are process-wide).
//
// GL state: around every plugin call and pass that touches GL, the plugin sets every GL state
// its image depends on to the value it needs and restores every state it touched, in core and
// compatibility contexts; fx_plugin/render/GlStateGuard.h lists each state and the value set.
// The plugin creates its own textures, buffers, vertex arrays and programs and deletes them on
// destruction.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fx/Api.h"
#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Types.h"

namespace fx {

/// How particles are drawn. `FromReaction` uses each reaction's own `render.technique`.
/// Mega (API 1.2): seed 001's mega-particles: spheres into a reduced-resolution target against
/// the scene depth, blurred, given fractal detail, lit and composited as one volume.
enum class Technique : uint8_t { FromReaction = 0, Hard, Soft, Spherical, Mega };

/// Where the tiled path (RenderOptions::tiled) draws. Auto: in a context with compute shaders that
/// is not a software rasterizer (llvmpipe, softpipe, SwiftShader, ...): on the H200 the tiled
/// passes are 6.6-17x shorter than the rasterised ones, on llvmpipe 2.3-5x longer
/// (docs/results.md). Off: rasterised. On: tiled wherever it can draw. Since API 2.4.
enum class Tiling : uint8_t { Auto = 0, Off = 1, On = 2 };

/// Run-time switches. Defaults: every reaction draws its own technique at full resolution; the
/// tiled path on a GPU (Tiling::Auto).
struct RenderOptions {
    Technique techniqueOverride = Technique::FromReaction;
    /// Particles into a half x half target, depth-aware composite; per view, only where that costs
    /// less than full res (the smoke overlaps itself enough to pay for the composite), else that
    /// view is drawn at full res (since API 2.1; before, every view at quarter res). A view the
    /// tiled path draws (`tiling`) is drawn there instead: it costs less than quarter res in every
    /// scene measured (since 2026-11-28). In a host's frame graph such a view declares the three
    /// quarter-res passes and the full-res "particles" pass; the first of them to run makes the
    /// choice, after the host's scene went to the GPU, and the passes not chosen draw nothing
    /// (since 2026-11-28; renderView chooses before its passes, as before).
    bool quarterRes = false;
    bool bilinearUpsample = false; ///< quarter-res composite with plain bilinear (for comparison only)
    /// With quarterRes: every view at quarter res, also where full res is cheaper (the 2.0
    /// behaviour; for comparisons and tests). Since API 2.1.
    bool quarterResAlways = false;
    /// Hard, soft and spherical particles of a full-resolution view, lit or not, shaded per 16 px
    /// tile by a compute shader (one scene-depth read and one blend per pixel) where the context
    /// has compute shaders; elsewhere, and for mega, rasterised as before (lit smoke was
    /// rasterised until 2026-11-28). Since API 2.3; since 2.4 true is `tiling` On whatever
    /// `tiling` says, false leaves it to `tiling`.
    bool tiled = false;
    Tiling tiling = Tiling::Auto;  ///< where the tiled path draws (Tiling); since API 2.4
};

/// How billboard particles (hard, soft) are rasterised. Trimmed: per atlas frame a convex
/// polygon (at most 8 vertices) that holds every texel the sampler can return with alpha > 0
/// replaces the quad, so the transparent corners cost no fragments; the image is the quad's.
/// Spherical billboards draw a regular octagon around the sphere's outline instead of its
/// bounding box (0.83 of the area). Quad: the full quads (for comparison).
/// Since API 1.1.
enum class ParticleShape : uint8_t { Trimmed = 0, Quad = 1 };

/// Deprecated since API 2.1, kept so hosts written against earlier versions still compile: no
/// value has any effect (Plugin::setQuarterResEdges). MixedResolution redrew the quarter-res
/// pixels along depth edges at full resolution (API 1.2 to 2.0); on a GPU its edge pass cost
/// more than quarter res saves, for an image no better, so it was removed. Quarter res always
/// upsamples depth-aware.
enum class QuarterResEdges : uint8_t { DepthAware = 0, MixedResolution = 1 };

/// Deprecated again since API 2.4, kept so hosts written against earlier versions still compile:
/// no value has any effect (Plugin::setFadeClassification); soft and spherical particles read the
/// scene depth at every fragment. On let soft billboards and spheres skip that read where no
/// geometry lay within their reach: per screen tile in API 1.3 to 2.0 (removed in 2.1: the tile
/// pass cost more than it saved), per block of each particle in 2.2 and 2.3, through a pyramid of
/// the scene's nearest depth. On a GPU the pyramid pass and the mask's reads cost more than the
/// fetches it skipped (H200: the particle pass 1.27x longer, soft and spherical alike), so 2.4
/// removed it too. The tiled path (RenderOptions::tiled) reads the depth once per pixel instead.
enum class FadeClassification : uint8_t { Off = 0, On = 1 };

/// Deprecated since API 2.1 with FadeClassification: Plugin::fadeClassCounts always returns it
/// with `counted` false and every count 0.
struct FadeClassCounts {
    int fadeNeeded = 0;  ///< drawn with the per-pixel fade (their footprint meets geometry)
    int inFront = 0;     ///< drawn without reading the scene depth (the fade is exactly 1)
    int hidden = 0;      ///< not drawn (wholly behind the geometry in their tiles)
    bool counted = false;
};

/// One key of the reaction file schema (reactions/README.md), as an editor needs it: enough to
/// build a widget, clamp it to the range the loader enforces and explain it in a tooltip.
/// Defaults: a number in [0, 0] with no unit, help or choices.
struct ReactionKeyInfo {
    enum class Kind : uint8_t {
        Number,        ///< a finite number in [min, max]
        Integer,       ///< a whole number in [min, max]
        Bool,          ///< true | false
        Choice,        ///< one word of `choices`
        ChoiceList,    ///< a list of words of `choices` (1 .. max entries)
        NumberRange,   ///< `[lo, hi]` (or one number meaning [v, v]), each in [min, max], lo <= hi
        IntegerPair,   ///< `[first, count]` integers (the atlas); `help` states the bounds
        ColorRamp,     ///< a list of `{t, rgba: [r, g, b, a]}` stops, every number in [0, 1]
        Name,          ///< 1-64 of [A-Za-z0-9_.-]
    };
    std::string key;   ///< dotted path inside one reaction: "particle.drag", "name"
    Kind kind = Kind::Number;
    double min = 0.0;  ///< inclusive; for ChoiceList/ColorRamp the least entry count
    double max = 0.0;  ///< inclusive; for ChoiceList/ColorRamp the most entries
    std::vector<std::string> choices;  ///< Choice, ChoiceList: the words, in the file's spelling
    std::string unit;  ///< "m", "s", "m/s", "1/s", "rad/s", "particles/s per wheel", "" ...
    std::string help;  ///< what it means, with any cross-key rule ("fade_in + fade_out <= 1")
};

class FX_API Plugin {
public:
    virtual ~Plugin() = default;

    /// SpecialFX::Init: loads every reaction from a .yaml file or a directory of them. On error
    /// nothing running is replaced, every problem is appended to `out` (may be null) and logged,
    /// and false is returned.
    virtual bool loadReactions(const std::string& path, Diagnostics* out) = 0;
    /// Checks the loaded files for changes and reloads them; a bad edit keeps the running set.
    /// Returns true when a new set went live.
    virtual bool pollHotReload(Diagnostics* out) = 0;

    virtual int reactionCount() const = 0;
    /// "" (and IndexOutOfRange in the log) for an index outside 0 .. reactionCount() - 1.
    virtual std::string reactionName(int index) const = 0;
    /// Reaction::Continue: advances reaction `index` by dt seconds (finite, >= 0).
    /// `currentVehicleCollisionAmount` (may be null = no collision) is the host's collision
    /// impulse this step, 0..1. Refused: IndexOutOfRange, InvalidValue (dt NaN, Inf or < 0).
    virtual ErrorCode continueReaction(int index, float dt, float* currentVehicleCollisionAmount) = 0;

    /// Refused (InvalidValue) when the technique is not one of the enum's values.
    virtual ErrorCode setRenderOptions(const RenderOptions& options) = 0;
    virtual RenderOptions renderOptions() const = 0;

    /// Compiles and links every particle program the render options and the loaded reactions can
    /// draw with (quarter res has programs of its own: call it again after switching options) and
    /// uploads the atlas now. Needs the host's GL
    /// context current. Returns false with ShaderBuild ("file:line: message"), ResourceMissing or
    /// NoGlContext diagnostics in `out` (also logged); the plugin then draws what did build.
    /// Without this call the same work happens at the first declarePasses() that sees a
    /// particle (a scene without smoke never compiles a shader).
    virtual bool prepareGl(Diagnostics* out) = 0;

    /// The hook into the host's particle bucket: declares this view's particle passes. Declares
    /// nothing when no particle is visible, so the host allocates nothing for it. Needs the
    /// host's context current (the first visible particle may load GL resources). Refused:
    /// InvalidView (see ViewInfo). A pass that finds sceneColor, sceneDepth and the view
    /// disagreeing on the size draws nothing and logs SizeMismatch.
    virtual ErrorCode declarePasses(const ViewInfo& view, FrameBuilder& frame) = 0;

    virtual Stats stats() const = 0;
    /// Counts live particles, capacity and non-finite state values (O(particles)).
    virtual ParticleCheck checkParticles() const = 0;

    /// Live shader edits: with PluginImports::shaderDir set, rebuilds the particle programs when
    /// a particle shader file there changed since the running ones were built. Needs the host's
    /// GL context current; cheap when nothing changed (it only stats the files). Returns true
    /// when new programs went live. A change that does not build keeps the last good programs:
    /// false, ShaderBuild diagnostics ("file:line") in `out` and in the log, once per edit.
    /// Without shaderDir (the embedded shaders) it does nothing.
    virtual bool pollShaderReload(Diagnostics* out) = 0;

    // ---- API 1.1: editing tools (a tweak panel, an editor) ----

    /// Every key a reaction may have, in the order reactions/README.md lists them. No GL.
    virtual std::vector<ReactionKeyInfo> reactionSchema() const = 0;
    /// The files the running set was read from, in load order (empty before a load).
    virtual std::vector<std::string> reactionFiles() const = 0;
    /// The file that defines reaction `index` ("" and IndexOutOfRange for a bad index).
    virtual std::string reactionFile(int index) const = 0;
    /// The running value of `key` (a ReactionKeyInfo::key) of reaction `index`, as YAML flow
    /// text: "1.2", "[3, 5]", "soft", "true", "[asphalt, kerb]", "[{t: 0, rgba: [1, 1, 1, 1]}]".
    /// Keys the file leaves out give their defaults. "" for an unknown key or a bad index.
    virtual std::string reactionValue(int index, const std::string& key) const = 0;
    /// Live particles of reaction `index` (0 for a bad index).
    virtual int reactionParticlesAlive(int index) const = 0;
    /// Validates `text` as the content of `file` (one of reactionFiles()) together with the
    /// other files of the set, exactly as loadReactions/hot reload validate files on disk. On
    /// success the new set goes live (reactions whose name and capacity stay keep their
    /// particles) and `text` stands in for the file's content until the next loadReactions()
    /// or loadReactionsFromText() of that file: hot reload keeps using it even when the file
    /// on disk changes (the editor decides what to do about that). On error nothing running
    /// changes, the diagnostics (file:line:col, key, message) go to `out` and false is returned;
    /// FileNotFound when `file` is not part of the running set. No GL.
    virtual bool loadReactionsFromText(const std::string& file, const std::string& text,
                                       Diagnostics* out) = 0;

    /// How billboards are rasterised (ParticleShape). Default Trimmed. Refused (InvalidValue)
    /// for a value outside the enum.
    virtual ErrorCode setParticleShape(ParticleShape shape) = 0;
    virtual ParticleShape particleShape() const = 0;

    // ---- API 1.1: recipes and per-reaction counters ----

    /// API 1.1: the counters of running reaction `index` (0 .. reactionCount() - 1); for any
    /// other index an empty ReactionStats (and IndexOutOfRange in the log). Cheap (no particle
    /// is read). Not pure, so an adapter written against 1.0 still compiles.
    virtual ReactionStats reactionStats(int index) const {
        (void)index;
        return ReactionStats{};
    }

    /// API 1.1: sets off every `on_demand` reaction named `name`, or whose name starts with
    /// `name` + "." (the layers of a recipe fire together), at world `point`, in their next
    /// continueReaction step. Refused: InvalidValue (a non-finite point, or no on_demand reaction
    /// of that name). Not pure, so an adapter written against 1.0 still compiles.
    virtual ErrorCode fireReaction(const std::string& name, const glm::vec3& point) {
        (void)name;
        (void)point;
        return ErrorCode::InvalidValue;
    }

    // ---- API 1.2: light and shadow ----

    /// API 1.2: lights the smoke with the host's sun and ambient from the next declarePasses on
    /// (each reaction's `lighting:` keys say how). Until the first call the smoke is unlit (the
    /// 1.1 look). Refused (InvalidValue, nothing changes): a non-finite value, a zero toSun or a
    /// negative colour. Not pure, so an adapter written against 1.1 still compiles.
    virtual ErrorCode setSceneLight(const SceneLight& light) {
        (void)light;
        return ErrorCode::InvalidValue;
    }
    /// API 1.2: back to unlit smoke (the 1.1 look); no opacity map is drawn.
    virtual void clearSceneLight() {}
    /// API 1.2: with a scene light set and lit smoke alive, declares the pass that draws the
    /// smoke's opacity along the sun into a target of this frame and returns it (else declares
    /// nothing and returns an invalid SmokeShadow). Call it for a view before declaring the host
    /// passes that sample the result (the ground); the particle passes of declarePasses() for the
    /// same view reuse it for self-shadowing. A host that never calls it still gets self-shadowed
    /// smoke (declarePasses declares the pass itself). Refused like declarePasses (InvalidView).
    virtual SmokeShadow declareShadowPasses(const ViewInfo& view, FrameBuilder& frame) {
        (void)view;
        (void)frame;
        return SmokeShadow{};
    }

    // ---- API 1.2: mixed-resolution particles (deprecated since API 2.1) ----

    /// API 1.2; deprecated since API 2.1, no effect (QuarterResEdges says why). The value is
    /// still validated and kept: refused (InvalidValue, nothing changes) for a value outside the
    /// enum, else quarterResEdges() returns it. Default DepthAware. Not pure, so an adapter
    /// written against 1.1 still compiles.
    virtual ErrorCode setQuarterResEdges(QuarterResEdges mode) {
        (void)mode;
        return ErrorCode::InvalidValue;
    }
    virtual QuarterResEdges quarterResEdges() const { return QuarterResEdges::DepthAware; }

    // ---- API 1.3: fade classification (deprecated since API 2.4; no effect in 2.1 either) ----

    /// API 1.3; deprecated since API 2.4, no effect on the picture or the work (FadeClassification
    /// says why). The value is still validated and kept: refused (InvalidValue, nothing changes)
    /// for a value outside the enum, else fadeClassification() returns it. Default Off.
    virtual ErrorCode setFadeClassification(FadeClassification mode) {
        (void)mode;
        return ErrorCode::InvalidValue;
    }
    virtual FadeClassification fadeClassification() const { return FadeClassification::Off; }
    /// API 1.3; deprecated since API 2.1, no effect: accepted (None) and nothing is counted.
    virtual ErrorCode setFadeClassCounting(bool on) {
        (void)on;
        return ErrorCode::InvalidValue;
    }
    /// API 1.3; deprecated since API 2.1: always `counted` false, every count 0.
    virtual FadeClassCounts fadeClassCounts() const { return FadeClassCounts{}; }

    // ---- API 2.0: the immediate path ----

    /// API 2.0: for engines without a frame graph. One call after the opaque scene and the sky
    /// draws this view's smoke into the framebuffer bound for drawing (GL_DRAW_FRAMEBUFFER, the
    /// default framebuffer included) over view.width x view.height from the origin of the
    /// viewport the host set (anywhere since API 2.1; with view.clipToHostScissor the host's
    /// scissor clips it too), with the
    /// scene depth from `depth` (by default that framebuffer's own depth attachment, copied only
    /// when a pass reads depth). The plugin owns and pools its transient targets (resized with
    /// the view, freed when the plugin is destroyed; a frame without visible particles allocates
    /// and copies nothing). Needs the host's context current. Refused: InvalidView (see
    /// ViewInfo), UnsupportedDepth (a depth texture format it cannot read), NullArgument (a
    /// depth source that needs a texture without one).
    virtual ErrorCode renderView(const ViewInfo& view, const HostDepth& depth = HostDepth{}) {
        (void)view;
        (void)depth;
        return ErrorCode::InvalidValue;
    }
};

/// What the host hands the plugin at creation. Defaults: this header's API version, no host
/// (refused), shaders and atlas from inside the library, the plugin's default seed.
struct PluginImports {
    uint32_t apiVersion = kApiVersion;
    HostAdapter* host = nullptr;  ///< required; must outlive the plugin
    std::string shaderDir;   ///< empty = the shaders embedded in the library; a folder = read the
                             ///< particle shaders from there instead (live shader edits)
    std::string dataDir;     ///< empty = the embedded smoke atlas; a folder = its smoke_atlas.png
    uint64_t seed = 0;       ///< global random seed for the reactions; 0 = the plugin's default
    /// API 2.1: the host world's up axis (fx/fx.h, fxPluginDesc::upAxis, says what is turned and
    /// why it is the plugin's and not a view's). Default +Y.
    UpAxis upAxis = UpAxis::Y;
};

}  // namespace fx

/// The entry point. Returns null, sets *error (when given) and logs through imports.host (when
/// there is one) on VersionMismatch (see fx/Api.h) or NullArgument (no host). Inline since API
/// 2.0: it builds the plugin through the C table (fx/fx.h), see fx/detail/PluginBridge.h.
inline std::unique_ptr<fx::Plugin> fxCreatePlugin(const fx::PluginImports& imports,
                                                  fx::ErrorCode* error = nullptr);

#include "fx/detail/PluginBridge.h"
