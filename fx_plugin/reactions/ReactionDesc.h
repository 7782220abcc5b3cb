#pragma once
// Reaction descriptions: what a reactions/*.yaml file says, after validation. Plain data, no YAML.
// Every field carries its default, unit and the range the loader enforces; reactions/README.md is
// the user-facing copy of these tables. Defaults that depend on the reaction type are resolved in
// one place, defaultReaction() below; the member initialisers are the wheel_smoke defaults.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "fx/Plugin.h"  // Technique
#include "fx/Types.h"   // Surface
#include "reactions/AirFieldDesc.h"  // TurbulenceDesc, VortexDesc

namespace fx {

/// Which per-type behaviour ("continue") a reaction runs.
enum class ReactionType : uint8_t { WheelSmoke = 0, Dust, CollisionBurst, CollisionScrape, OnDemand };
/// Which wheels a wheel-driven reaction watches.
enum class WheelSet : uint8_t { Rear = 0, Front, All };
/// How particles combine with what is behind them. Additive is order-independent (never sorted).
enum class BlendMode : uint8_t { Alpha = 0, Premultiplied, Additive };

constexpr uint32_t surfaceBit(Surface s) { return 1u << static_cast<uint32_t>(s); }

/// When a reaction emits. Defaults (wheel_smoke): slip >= 0.35 on asphalt or kerb, rear wheels.
struct TriggerDesc {
    float slipThreshold = 0.35f;   ///< [0, 1] combined slip where emission starts
    uint32_t surfaces = surfaceBit(Surface::Asphalt) | surfaceBit(Surface::Kerb);  ///< surfaceBit() mask
    WheelSet wheels = WheelSet::Rear;
    float minSpeed = 0.0f;         ///< [0, 200] m/s hub speed below which nothing is emitted
    float collisionThreshold = 0.2f;  ///< [0, 1] collision amount that fires a collision_burst
};

/// How many particles. Defaults: 80/s at full slip, no burst, 1024 slots.
struct EmissionDesc {
    float rate = 80.0f;            ///< [0, 100000] particles/s at full strength (wheel_smoke, dust, collision_scrape)
    int burst = 0;                 ///< [0, capacity] particles per collision at amount 1 (collision_burst)
    int capacity = 1024;           ///< [1, 1000000] pool slots, allocated once at load
    float spawnHeight = 0.15f;     ///< [-10, 10] m above the contact point
    float jitterRadius = 0.25f;    ///< [0, 10] m, spawn points uniform in a horizontal disc
};

/// One stop of the colour ramp: colour at life fraction t, piecewise linear in between.
struct ColorStop {
    float t = 0.0f;                ///< [0, 1] life fraction, non-decreasing along the ramp
    glm::vec4 rgba{1.0f};          ///< each channel [0, 1], straight (not premultiplied) alpha
};

/// One point of an over-life curve (alpha_over_life, size_over_life): value v at life fraction
/// t, piecewise linear in between, held flat before the first and after the last point.
struct CurvePoint {
    float t = 0.0f;                ///< [0, 1] life fraction, non-decreasing along the curve
    float v = 0.0f;                ///< [0, 1]
};

/// One particle's life. Defaults: 2-3.5 s, grows 0.4 m -> 3 m, rises at 0.6 m/s.
struct ParticleDesc {
    float lifetimeMin = 2.0f;      ///< [0.01, 60] s
    float lifetimeMax = 3.5f;      ///< [0.01, 60] s, >= lifetimeMin
    float startSize = 0.4f;        ///< [0, 10000] m, billboard edge length at birth
    float endSize = 3.0f;          ///< [0, 10000] m, at death (growth curve: see sim/Lifecycle.h)
    float sizeVariation = 0.2f;    ///< [0, 0.9] each particle's sizes scaled by 1 +- this
    float riseSpeed = 0.6f;        ///< [-50, 50] m/s terminal upward speed (buoyancy)
    float drag = 1.2f;             ///< [0, 1e6] 1/s, rate at which velocity relaxes to terminal
    float windFactor = 1.0f;       ///< [0, 10] share of the ambient wind in the terminal velocity
    float gravity = 0.0f;          ///< [0, 100] m/s^2 downward acceleration besides the drag (sparks, debris)
    float spreadSpeed = 0.5f;      ///< [0, 100] m/s random initial speed, random upward-hemisphere direction
    float inheritVelocity = 0.3f;  ///< [0, 2] share of the wheel hub velocity at birth
    float spinMin = -0.6f;         ///< [-50, 50] rad/s
    float spinMax = 0.6f;          ///< [-50, 50] rad/s, >= spinMin
    float fadeIn = 0.08f;          ///< [0, 1] life fraction over which alpha rises 0 -> 1
    float fadeOut = 0.6f;          ///< [0, 1] life fraction over which alpha falls 1 -> 0; fadeIn + fadeOut <= 1
    std::vector<ColorStop> colorRamp{ColorStop{0.0f, glm::vec4(1.0f)}, ColorStop{1.0f, glm::vec4(1.0f)}};
    int atlasFirst = 0;            ///< [0, 3] first frame of the 2x2 atlas (row-major from top-left)
    int atlasCount = 4;            ///< [1, 4] frames picked at random per particle; first + count <= 4
    /// Empty (default) = the fade_in/fade_out smoothsteps. Given: the alpha factor over life,
    /// replacing them (the file may not give both).
    std::vector<CurvePoint> alphaOverLife;
    /// Empty (default) = growthCurve (ease-out). Given: the share of the way from start_size to
    /// end_size over life.
    std::vector<CurvePoint> sizeOverLife;
};

/// How it is drawn. Defaults: soft particles, alpha blending, sorted.
struct RenderDesc {
    Technique technique = Technique::Soft;  ///< Hard, Soft, Spherical or Mega (never FromReaction)
    /// `technique: stateless` in the file: birth records evaluated in the vertex shader (no CPU
    /// update), drawn as hard billboards (technique is then Hard). Private to the plugin: the
    /// public Technique enum is the run-time override, which stateless particles ignore.
    bool stateless = false;
    BlendMode blend = BlendMode::Alpha;
    float softness = 0.5f;         ///< [1e-6, 1e6] m of depth difference over which the soft fade reaches 1
    float contrastPower = 1.0f;    ///< [0.1, 16] exponent of the soft-fade contrast curve, 1 = linear
    float nearFade = 0.5f;         ///< [0, 100] m in front of the near plane over which particles fade out
    bool sortBackToFront = true;   ///< ignored (never sorted) for additive blending
};

/// How lit smoke takes the host's sun and ambient (Plugin::setSceneLight). Applies to alpha and
/// premultiplied blending; additive reactions (fire, sparks) are light sources and stay unlit.
/// Defaults: the look of the shipped smoke.
struct LightingDesc {
    bool enabled = true;           ///< false = drawn unlit (the 1.1 look) even under a scene light
    float normalStrength = 0.7f;   ///< [0, 1] share of the atlas normal against a flat, camera-facing card
    float scattering = 0.35f;      ///< [0, 1] share of the sun light scattered by the phase function instead of diffusely
    float anisotropy = 0.6f;       ///< [-0.95, 0.95] Henyey-Greenstein g; > 0 glows toward the sun
    float absorption = 1.0f;       ///< [0, 20] optical depth per unit of accumulated opacity (self-shadowing)
    float ambient = 1.0f;          ///< [0, 2] multiplier of the host's ambient colour
    bool castsShadow = true;       ///< drawn into the opacity map (self-shadowing, shadow on the ground)
    bool lit(BlendMode blend) const { return enabled && blend != BlendMode::Additive; }
};

/// Mega-particles (`technique: mega`, seed 001). Defaults: a half-resolution target, a blur that
/// melts neighbouring spheres together, and medium fractal detail.
struct MegaDesc {
    float resolution = 0.5f;       ///< [0.25, 1] size of the sphere target relative to the view
    float blurRadius = 6.0f;       ///< [0, 32] pixels of the sphere target (Gaussian sigma = radius / 2)
    float noiseStrength = 0.5f;    ///< [0, 1] how much fractal noise eats into the alpha
    float noiseScale = 1.5f;       ///< [0.05, 100] m, the largest noise feature
};

/// One reaction. `name` and `type` are required in the file; the rest default per type.
struct ReactionDesc {
    std::string name;              ///< unique across every loaded file, 1-64 of [A-Za-z0-9_.-]
    ReactionType type = ReactionType::WheelSmoke;
    TriggerDesc trigger;
    EmissionDesc emission;
    ParticleDesc particle;
    RenderDesc render;
    TurbulenceDesc turbulence;     ///< curl-noise air motion added to the terminal velocity
    VortexDesc vortex;             ///< spiral around the vertical axis through each particle's emitter
    LightingDesc lighting;         ///< how it takes the scene light (API 1.2)
    MegaDesc mega;                 ///< technique mega only
    std::string sourceFile;        ///< where it was read, for messages
    int sourceLine = 0;            ///< 1-based line of the reaction's first key
    std::string sourceKey;         ///< its key path in that file, as the author wrote it:
                                   ///< "reactions[1]", or "reactions[0].layers[2]" for a layer
};

/// The defaults for one type; the loader starts from these and overlays the file's keys.
/// dust: slip >= 0, grass/gravel/sand, all wheels, min_speed 2 m/s.
/// collision_burst: burst 24, all wheels (wheels and surfaces are not used by bursts).
/// collision_scrape: like collision_burst's trigger, emitting `rate` x amount per second while in
/// contact.
inline ReactionDesc defaultReaction(ReactionType type) {
    ReactionDesc d;
    d.type = type;
    switch (type) {
    case ReactionType::WheelSmoke:
        break;
    case ReactionType::Dust:
        d.trigger.slipThreshold = 0.0f;
        d.trigger.surfaces = surfaceBit(Surface::Grass) | surfaceBit(Surface::Gravel) |
                             surfaceBit(Surface::Sand);
        d.trigger.wheels = WheelSet::All;
        d.trigger.minSpeed = 2.0f;
        break;
    case ReactionType::CollisionBurst:
        d.trigger.wheels = WheelSet::All;
        d.emission.burst = 24;
        break;
    case ReactionType::CollisionScrape:
        d.trigger.wheels = WheelSet::All;
        break;
    case ReactionType::OnDemand:
        d.trigger.wheels = WheelSet::All;
        d.emission.burst = 24;
        break;
    }
    return d;
}

/// Every reaction of one load (a file, or a directory of files in sorted order).
struct ReactionSet {
    std::vector<ReactionDesc> reactions;
    std::vector<std::string> files;  ///< the files the set was read from, in load order
};

/// Limits the loader enforces beyond per-key ranges (guards against hostile input).
constexpr int kMaxCapacity = 1000000;            ///< per reaction
constexpr long long kMaxTotalCapacity = 4000000; ///< summed over one set (about 250 MB of pools)
constexpr int kMaxReactionsPerFile = 256;
constexpr int kMaxColorStops = 16;
constexpr int kMaxCurvePoints = 16;
constexpr int kMaxLayers = 8;                    ///< layers of one layered reaction
constexpr int kMaxNesting = 16;                  ///< collection levels in a file
constexpr size_t kMaxFileBytes = 4u << 20;       ///< 4 MiB
constexpr size_t kMaxDiagnosticsPerFile = 100;   ///< then one TooManyErrors

/// The words of a reaction file's enums, indexed by the enum's value (ReactionNames.cpp): the
/// loader accepts exactly these and the editor schema offers exactly these. Techniques:
/// TechniqueTable.h.
const std::vector<std::string>& reactionTypeWords();
const std::vector<std::string>& wheelSetWords();
const std::vector<std::string>& blendModeWords();
const std::vector<std::string>& surfaceWords();  ///< Surface::Count words
const char* reactionTypeName(ReactionType type);
const char* wheelSetName(WheelSet wheels);
const char* blendModeName(BlendMode blend);
const char* surfaceName(Surface surface);

}  // namespace fx
