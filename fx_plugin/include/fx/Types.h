#pragma once
// Plain data shared by the plugin and its host. No GL, no engine types.
#include <cstdint>
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

/// One view the host is rendering (chase camera, mirror...). Matrices are OpenGL conventions
/// (right-handed view space, camera looks down -Z, clip depth -1..1).
struct ViewInfo {
    const char* name = "";
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::vec3 eye{0.0f};
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    int width = 0;   ///< pixels of the view's colour target
    int height = 0;
};

/// Colour formats the host's render-to-texture layer must offer to the plugin.
enum class TargetFormat : uint8_t { RGBA8, RGBA16F, R32F, RG32F };

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

/// Counters the plugin reports to the host (stats JSON, benchmarks).
struct Stats {
    int reactions = 0;
    int particlesAlive = 0;
    int particlesDrawn = 0;   ///< in the last declared view, after culling
    int reloads = 0;          ///< successful hot reloads
    int reloadErrors = 0;     ///< rejected hot reloads (old set kept)
};

}  // namespace fx
