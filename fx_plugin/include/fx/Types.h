#pragma once
// Plain data shared by the plugin and its host. No GL, no engine types.
#include <cstdint>
#include <string>
#include <glm/glm.hpp>

namespace fx {

/// Ground material under a wheel. The host maps its own materials onto these.
enum class Surface : uint8_t { Asphalt = 0, Kerb, Grass, Gravel, Sand, Count };

/// One wheel's contact with the ground, as the host's vehicle model sees it this step.
/// Defaults: an airborne front wheel at the origin with no slip.
struct WheelContact {
    glm::vec3 position{0.0f};  ///< contact patch centre, world space, metres
    glm::vec3 velocity{0.0f};  ///< hub velocity, world space, m/s
    float slip = 0.0f;         ///< combined slip, 0 = rolling, 1 = full lock/spin; may exceed 1
    Surface surface = Surface::Asphalt;
    bool grounded = false;
    bool rear = false;
};

/// Severity of a message the plugin hands to the host's log.
enum class LogLevel : uint8_t { Info, Warning, Error };

/// How the host fogs its geometry (ViewInfo::fog, API 2.1): fixed-function GL's fog, which the
/// plugin applies to the smoke at the same distance, so smoke fades with the geometry around it.
/// Factor f (1 = no fog), clamped to [0, 1], of the fragment's eye-space distance c = |z_eye| (the
/// distance along the view axis: GL's FRAGMENT_DEPTH fog coordinate in the abs(z) form the spec
/// allows): Linear (end - c) / (end - start), Exp exp(-density c), Exp2 exp(-(density c)^2).
/// Premultiplied smoke becomes f rgb + (1 - f) color alpha (its own light is fogged, its coverage
/// is not); additive smoke f rgb (it fades to nothing). Valid: finite values, density >= 0, and
/// for Linear end != start. Defaults: off (GL's own defaults for the rest: black, 0, 1, 1).
struct Fog {
    enum class Mode : uint8_t { Off = 0, Linear, Exp, Exp2 };
    Mode mode = Mode::Off;
    glm::vec3 color{0.0f};  ///< linear RGB, as the host fogs its geometry with
    float start = 0.0f;     ///< Linear: metres where fog begins
    float end = 1.0f;       ///< Linear: metres where fog is complete
    float density = 1.0f;   ///< Exp, Exp2: 1/m
    bool on() const { return mode != Mode::Off; }
};

/// Which particles one call draws (ViewInfo::slice, API 2.1): those whose view distance (along the
/// view axis to the particle's centre, the distance the draw list is sorted by) lies in
/// [minDistance, maxDistance); maxDistance 0 = no upper bound. A host orders the smoke with its
/// own blended geometry by drawing the view in slices around it: the smoke behind a glass pane at
/// 10 m ({10, 0}), the pane, then the smoke in front ({0, 10}). Valid: finite minDistance >= 0, and
/// maxDistance 0 or > minDistance. Defaults: {0, 0}, every particle (one call draws all).
struct DistanceSlice {
    float minDistance = 0.0f;
    float maxDistance = 0.0f;
    bool everything() const { return minDistance == 0.0f && maxDistance == 0.0f; }
    bool contains(float distance) const {
        return distance >= minDistance && (maxDistance == 0.0f || distance < maxDistance);
    }
};

/// How the host's z-buffer (the depth attachment of sceneColor / sceneDepth) maps distance.
/// The plugin's depth-tested passes follow it: Standard tests LEQUAL (near = 0, cleared to 1),
/// ReversedZ tests GEQUAL (near = 1, cleared to 0; glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)
/// with a float depth buffer). The linear depth texture is the same under both.
enum class DepthConvention : uint8_t { Standard = 0, ReversedZ };

/// Which way the host's camera looks in its view space (API 2.0): right-handed, down -Z (OpenGL),
/// or left-handed, down +Z (Direct3D-style engines such as Irrlicht). The plugin turns a
/// left-handed pair into the right-handed one with the same clip coordinates (view' = F view,
/// proj' = proj F, F = diag(1, 1, -1, 1)), so the host hands in the matrices it draws with.
enum class Handedness : uint8_t { RightHanded = 0, LeftHanded = 1 };

/// Which axis of the host's world points up (PluginImports::upAxis, API 2.1). The plugin's world
/// is Y-up; a Z-up host's vectors and views are turned into it at the boundary (fx/fx.h, upAxis).
enum class UpAxis : uint8_t { Y = 0, Z = 1 };

/// One view the host is rendering (chase camera, mirror...). Matrices as the host draws its scene
/// (right-handed view space unless `handedness` says otherwise). `proj` is the projection the host draws its
/// scene with, so it matches `depth`. Valid: width, height > 0; 0 < nearPlane < farPlane, all
/// finite; finite matrices (declarePasses refuses anything else with ErrorCode::InvalidView).
/// near/far need not equal proj's planes (the scene depth is decoded from proj alone); they bound
/// which smoke is drawn and where the near fade starts: fx/fx.h, fxViewDesc, says what a mismatch
/// does.
/// Defaults: an identity camera at the origin, near 0.1 m, far 1 km, standard depth, size 0
/// (which the host must set), the view alone in its target (x = y = 0, target size = the view's).
struct ViewInfo {
    const char* name = "";  ///< for pass names and debug groups; may be null (read as "")
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::vec3 eye{0.0f};
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    int width = 0;   ///< pixels of the view's colour target (sceneColor), > 0
    int height = 0;
    DepthConvention depth = DepthConvention::Standard;
    Handedness handedness = Handedness::RightHanded;  ///< API 2.0
    /// API 2.1: the view is the rectangle (x, y, width, height) of sceneColor, which is
    /// targetWidth x targetHeight (0 = width x height). PassContext::bindForDraw(sceneColor) sets
    /// that rectangle as the viewport. renderView takes the origin from the viewport the host
    /// set instead and reads neither. Scene depth textures: fx/fx.h, fxViewDesc, states the rule.
    int x = 0, y = 0;
    int targetWidth = 0, targetHeight = 0;
    /// API 2.1, renderView only: the scissor test the host has enabled at the call clips the
    /// smoke too. false: the host's scissor state is ignored (the 2.0 behaviour).
    bool clipToHostScissor = false;
    Fog fog;                ///< API 2.1: the host's fog, applied to the smoke (default off)
    DistanceSlice slice;    ///< API 2.1: the particles this call draws (default every one)
};

/// Where Plugin::renderView (the immediate path, API 2.0) finds the scene depth.
/// Defaults: the depth attachment of the framebuffer bound for drawing, drawn with GL's default
/// clip control and depth range.
struct HostDepth {
    enum class Source : uint8_t {
        BoundFramebuffer = 0,  ///< the draw framebuffer's depth attachment (default framebuffer too);
                               ///< copied into a texture of the plugin's only when a pass reads depth
        DepthTexture = 1,      ///< `texture`: GL_DEPTH_COMPONENT16/24/32F or GL_DEPTH24_STENCIL8
        LinearR32F = 2,        ///< `texture`: linear view depth in metres (FrameBuilder::sceneDepth's form)
        None = 3,              ///< no scene depth: particles are neither z-tested nor faded
    };
    Source source = Source::BoundFramebuffer;
    uint32_t texture = 0;          ///< GL_TEXTURE_2D name for DepthTexture / LinearR32F
    bool clipDepthZeroToOne = false;  ///< the scene was drawn under glClipControl(.., GL_ZERO_TO_ONE)
    float depthRangeNear = 0.0f;   ///< glDepthRange the scene was drawn with
    float depthRangeFar = 1.0f;
};

/// Colour formats the host's render-to-texture layer must offer to the plugin.
/// Depth (API 2.1): only in a TextureRef, for FrameBuilder::sceneZBuffer's depth texture.
enum class TargetFormat : uint8_t { RGBA8, RGBA16F, R32F, RG32F, Depth };

/// A render target the plugin asks the host for.
/// Defaults: follows the view at full size, RGBA8, linear filtering, clamp to edge, no depth.
struct TargetDesc {
    float scale = 1.0f;   ///< size relative to the view when width/height are 0
    int width = 0;        ///< absolute size; 0 = relative to the view
    int height = 0;
    TargetFormat format = TargetFormat::RGBA8;
    bool linearFilter = true;
    bool depth = false;   ///< give the target a depth buffer of its own
};

/// A frame-graph resource handle handed out by the host. Valid for one frame only.
struct Target {
    uint32_t id = 0;
    bool valid() const { return id != 0; }
};

/// A texture of the host's, lent to the plugin for the pass being executed: the GL texture
/// name (GL_TEXTURE_2D, in the host's context) and what it holds. `name` 0 = no such texture.
struct TextureRef {
    uint32_t name = 0;
    TargetFormat format = TargetFormat::RGBA8;
    int width = 0;
    int height = 0;
    bool valid() const { return name != 0; }
};

/// Counters the plugin reports to the host (stats JSON, benchmarks).
struct Stats {
    int reactions = 0;
    int particlesAlive = 0;
    int particleCapacity = 0; ///< pool slots over every reaction (allocated once per load)
    int particlesDrawn = 0;   ///< in the last declared view, after culling
    int reloads = 0;          ///< successful hot reloads
    int reloadErrors = 0;     ///< rejected hot reloads (old set kept)
    int apiErrors = 0;        ///< calls refused with an API error code since creation
};

/// Result of Plugin::checkParticles(): a health check a host or test runs on stiff or extreme
/// input (it reads every live particle, so it costs O(particles)).
struct ParticleCheck {
    int alive = 0;
    int capacity = 0;
    int nonFinite = 0;  ///< NaN or Inf values in any live particle's state (0 when healthy)
};

/// One running reaction's counters (Plugin::reactionStats, API 1.1). Defaults: an empty name (an
/// index outside the running set).
struct ReactionStats {
    std::string name;       ///< the reaction's name in its file
    std::string technique;  ///< its render.technique word: "hard", "soft", "spherical", "stateless" or "mega"
    int alive = 0;          ///< live particles now
    uint64_t emitted = 0;   ///< particles that entered its pool since it was loaded (kept across
                            ///< a hot reload that keeps its particles)
    uint64_t dropped = 0;   ///< particles due while its pool was full
};

/// The scene's sun and sky light, as the host lights its own scene (Plugin::setSceneLight,
/// API 1.2). Valid: finite; toSun not zero (it need not be unit length); colours >= 0.
/// Defaults: a sun 35 degrees high, white, and a grey-blue ambient.
struct SceneLight {
    glm::vec3 toSun{0.47f, 0.57f, 0.67f};   ///< world space, from the scene toward the sun
    glm::vec3 sunColor{1.0f, 0.97f, 0.92f}; ///< linear RGB irradiance of the sun (1 = white)
    glm::vec3 ambient{0.42f, 0.45f, 0.50f}; ///< linear RGB of the sky light from every side
};

/// The smoke's opacity seen from the sun (Plugin::declareShadowPasses, API 1.2), for the host to
/// darken what lies under the smoke. `opacity` is an RGBA16F frame-graph target the plugin's pass
/// writes; a host pass that samples it lists it among its reads. Channel k (k = 0..3) holds the
/// optical depth (>= 0, dimensionless) of the smoke between the sun and light-space depth
/// (k + 1) / 4; alpha is the whole column, so ground light is multiplied by exp(-alpha).
/// `worldToShadow` maps a world position to ([0,1] u, [0,1] v, [0,1] light depth, 1); outside
/// [0,1]^2 there is no smoke. Defaults: no target (no smoke: the host shades as without smoke).
struct SmokeShadow {
    Target opacity;
    glm::mat4 worldToShadow{1.0f};
    bool valid() const { return opacity.valid(); }
};

}  // namespace fx
