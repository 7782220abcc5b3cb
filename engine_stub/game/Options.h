#pragma once
// cube_game's command line. Parsing is separate from main() so tests can feed it bad values.
#include <string>

#include "platform/Platform.h"
#include "render/SceneFog.h"
#include "render/SunLight.h"

namespace cube {

enum class FxPath { Plugin, Legacy };

/// Defaults: 300 frames at 1280x1024 on OSMesa, real-time dt, seed 1, the plugin with the
/// reactions in reactions/, each reaction's own technique, prepass-EQUAL and quarter-res off,
/// one job-system thread per hardware thread.
struct Options {
    int frames = 300;
    int width = 1280;
    int height = 1024;
    double fixedDt = 0.0;         ///< 0 = measure wall time per frame
    double startTime = 0.0;       ///< seconds into the scripted drive at frame 0
    unsigned seed = 1;
    std::string screenshot;       ///< PNG of the last frame
    int screenshotEvery = 0;      ///< with screenshotDir: a PNG every K frames
    std::string screenshotDir;
    std::string scene;            ///< empty = data/race.gltf
    std::string reactions;        ///< empty = reactions/ (every *.yaml in it)
    std::string legacyReactions;  ///< empty = data/legacy_smoke.yaml
    std::string carNode;          ///< empty = "car", and a scene without it still renders
    Backend backend = Backend::OSMesa;
    bool window = false;
    std::string statsJson;
    FxPath fx = FxPath::Plugin;
    std::string mode = "reaction";  ///< a TechniqueModes.h word: reaction (each reaction's own), hard, soft, ...
    bool prepassEqual = false;
    /// --fx-depth zbuffer: the plugin draws through API 2's immediate path and reads the engine's
    /// own z-buffer (copied and linearised by the plugin) instead of the linear R32F scene depth.
    bool pluginZBuffer = false;
    /// --fx-depth linear: the frame-graph passes read a linear R32F scene depth the opaque pass
    /// writes as a second render target (API 2.0's contract) instead of sampling the z-buffer.
    bool pluginLinearDepth = false;
    bool quarterRes = false;
    /// --quarter-res-always: every view at quarter res, also where full res is cheaper
    bool quarterResAlways = false;
    bool bilinearUpsample = false;
    bool watch = false;
    bool mirror = true;
    /// --split: two-player split screen, two chase cameras side by side in one framebuffer, each
    /// with its own smoke (no mirror, no HUD)
    bool split = false;
    /// --split-alone left|right: only that half's camera, over the whole window (no mirror, no
    /// HUD): the picture each half of --split must equal (tests/engine/SplitScreenTest.cpp);
    /// 0 = off, 1 = left (player one), 2 = right (player two)
    int splitAlone = 0;
    bool hud = true;
    bool litSmoke = true;         ///< hand the sun to the plugin (false: --unlit-smoke, the 1.1 look)
    bool panel = false;           ///< the live tweak panel (engine_stub/panel), window or headless
    /// --sun: degrees; azimuth in the ground plane from +X toward +Z, elevation above the
    /// horizon (render/SunLight.h). Default: the race scene's first sun, from before the sun became an option.
    double sunAzimuth = kDefaultSunAzimuthDeg;
    double sunElevation = kDefaultSunElevationDeg;
    /// --fog: the track's fog, which the plugin then applies to the smoke too. Default off: the
    /// golden frames and every benchmark scenario are drawn without it.
    SceneFog fog;
    float nearPlane = 0.1f;
    float farPlane = 2000.0f;
    /// Reversed-Z in a 32-bit float z-buffer where the context has clip control (GL 4.5 /
    /// ARB_clip_control); false, or a context without it: GL's default [-1, 1] with 24 bits.
    bool reversedZ = true;
    /// --threads N: threads for the plugin's parallel work (the job system), the frame thread
    /// included; 0 = one per hardware thread, 1 = it all stays on the frame thread. 0..64.
    int threads = 0;
    bool help = false;
    // Harness switches (fxbench; no command-line flag in cube_game).
    bool effects = true;          ///< false: the bare engine, no particle passes at all
    int poolFramesUntilFree = 3;  ///< render targets unused this many frames are freed
    bool stationaryCar = false;   ///< the car holds its start pose, velocity 0 (wheels still spin)
    double explodeAt = -1.0;      ///< drive time (s) at which the explosion recipe fires at the car; < 0 = never
    bool fixedCamera = false;     ///< chase view from cameraEye towards cameraTarget (world space)
    float cameraEye[3] = {0.0f, 2.0f, 8.0f};
    float cameraTarget[3] = {0.0f, 0.0f, 0.0f};
};

/// Parses argv and checks every value before a run starts (checkOptions). On a bad flag or
/// value returns false with a message naming the flag and what was expected.
bool parseOptions(int argc, const char* const* argv, Options* out, std::string* error);
/// The checks that need more than one flag or the file system: --frames 0 needs a window; a
/// pinned camera is not degenerate (eye on its target, looking straight up or down); every
/// output folder exists and is writable. False + a message naming the flag.
bool checkOptions(const Options& options, std::string* error);
std::string usage();

/// The readers parseOptions checks values with, shared with fxbench's command line: true (and
/// *out set) when `s` is wholly a number in [lo, hi], a double also finite.
bool parseInt(const std::string& s, long long lo, long long hi, long long* out);
bool parseDouble(const std::string& s, double lo, double hi, double* out);
/// "a,b,c": the parts between commas (an empty part stays, so "1,,2" has three).
std::vector<std::string> splitCommas(const std::string& text);

}  // namespace cube
