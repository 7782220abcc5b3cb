#pragma once
// The stand-in game (CUBE's Game): Init -> InitProc builds every component; Dyn runs one frame
// (the update sequence through SpecialFX::Dyn, then the render sequence through Render::Dyn).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "game/EngineFxHost.h"
#include "game/Options.h"
#include "game/Render.h"
#include "game/SpecialFX.h"
#include "game/Vehicle.h"
#include "gl/Image.h"
#include "platform/Platform.h"
#include "rtt/FrameGraph.h"
#include "rtt/RenderTargetPool.h"
#include "view/cubeScene.h"
#include "view/cubeView.h"

namespace cube {

class Game;
class JobSystem;

/// An application layer over the game (the tweak panel). beginFrame runs at the start of each
/// Dyn, before the update: it may change options, the time scale and the reactions.
/// declarePasses runs while Render::Dyn builds the frame, after every view and before present;
/// it returns the colour target present shows (its argument when it adds nothing). With no
/// overlay set, Dyn and the frame are exactly what they are without this hook.
class GameOverlay {
public:
    virtual ~GameOverlay() = default;
    virtual void beginFrame(Game& game, float dt) = 0;
    virtual rtt::FrameGraphResource declarePasses(Game& game, rtt::FrameGraph& graph,
                                                  rtt::FrameGraphResource color, int width, int height) = 0;
    /// True while the overlay takes typed keys (a text field): the game's own keys stay off.
    virtual bool wantsKeyboard() const { return false; }
};

/// Where the main camera looks. Chase: behind the car (default); BurnoutCloseUp: beside the
/// rear wheels; Barrier: at the barrier node ("barrier_right"; Chase when the scene has none).
/// --camera (Options::fixedCamera) overrides every preset.
enum class CameraPreset { Chase, BurnoutCloseUp, Barrier };

class Game {
public:
    Game();
    ~Game();

    /// Makes the context (unless `platform` is given), loads the scene and reactions.
    /// False + a message naming the file / flag and what was expected.
    bool Init(const Options& options, std::string* error, std::unique_ptr<Platform> platform = nullptr);
    /// One frame: update by `dt` seconds of game time, then render. dt is clamped to [0, 10].
    void Dyn(float dt);
    /// The two halves of Dyn, for harnesses that render one simulated frame several ways
    /// (fxbench): Update advances the drive and the effects; RenderFrame draws the current state
    /// with the current options and waits for the GPU (glFinish). RenderFrame returns its wall ms.
    void Update(float dt);
    /// Sets off the explosion recipe (an on_demand reaction named "explosion", with its layers)
    /// just above the car, in the next simulation step (--explode-at, window key E). False when
    /// no such reaction runs.
    bool fireExplosionAtCar();
    /// With --explode-at: true when fireExplosionAtCar() can act (an on_demand reaction named
    /// "explosion" or "explosion.<layer>" is loaded); else false with a message naming the flag.
    /// Called after Init, before the first frame (the reactions are known only then).
    bool checkExplodeAt(std::string* error) const;
    double RenderFrame();

    /// Asks for a read-back of the next rendered frame (lastFrame()).
    void captureNextFrame() { captureNext_ = true; }
    const ImageRGBA8& lastFrame() const { return lastFrame_; }
    /// The next RenderFrame also reads the chase view's linear scene depth back (metres, rows as
    /// the target stores them, 1e30 where nothing was drawn); it runs the depth prepass for that.
    void captureNextSceneDepth() { captureDepthNext_ = true; }
    /// Empty until a captured frame, or when the read-back failed.
    const std::vector<float>& lastSceneDepth() const { return lastSceneDepth_; }
    bool writeStatsJson(const std::string& path, std::string* error) const;

    /// The sun from the next frame on, for the scene and the smoke plugin alike (degrees, as
    /// --sun: azimuth from +X toward +Z, wraps; elevation 1..90). False, and nothing changes,
    /// when validSunAngles refuses them.
    bool setSun(double azimuthDeg, double elevationDeg);
    /// The light the scene renders with and the plugin was given (from --sun at Init).
    const SunLight& sun() const { return sun_; }

    Options& options() { return options_; }
    const Options& options() const { return options_; }
    /// Opaque quads the application attaches to the main (chase) camera from the next frame on
    /// (the benchmark's overdraw scenario); empty = none.
    void setCameraQuads(CameraQuads quads) { cameraQuads_ = std::move(quads); }
    /// The overlay drawn over each frame from the next Dyn on (null: none). Not owned.
    void setOverlay(GameOverlay* overlay) { overlay_ = overlay; }
    GameOverlay* overlay() const { return overlay_; }
    /// Game time per wall second in Dyn (default 1; clamped to [0, 10]); paused: no time passes
    /// (Dyn still renders).
    void setTimeScale(float scale) { timeScale_ = std::isfinite(scale) ? std::min(std::max(scale, 0.0f), 10.0f) : 1.0f; }
    float timeScale() const { return timeScale_; }
    void setPaused(bool paused) { paused_ = paused; }
    bool paused() const { return paused_; }
    void setCameraPreset(CameraPreset preset) { cameraPreset_ = preset; }
    CameraPreset cameraPreset() const { return cameraPreset_; }
    /// False when the scene has no barrier node for CameraPreset::Barrier.
    bool hasBarrier() const { return barrierNode_ >= 0; }
    const CameraQuads& cameraQuads() const { return cameraQuads_; }
    Platform& platform() { return *platform_; }
    /// The job system the plugin's parallel work runs on (Options::threads); null before Init.
    const JobSystem* jobs() const { return jobs_.get(); }
    SpecialFX& specialFX() { return specialFX_; }
    cubeScene& scene() { return scene_; }
    Vehicle& vehicle() { return vehicle_; }
    rtt::RenderTargetPool& pool() { return *pool_; }
    rtt::FrameGraph& graph() { return *graph_; }
    cubeView& chaseView() { return chase_; }
    cubeView& mirrorView() { return mirror_; }
    cubeView& chase2View() { return chase2_; }
    /// Things Init read past (scene features ignored, no car node, ...), one line each, for the
    /// app to print once.
    const std::vector<std::string>& warnings() const { return warnings_; }
    /// False when the scene has no car node: nothing drives and the camera frames the model.
    bool driving() const { return vehicle_.active(); }
    double time() const { return time_; }
    long long frame() const { return frame_; }
    /// Frame wall times in ms (CPU clock including glFinish), one per rendered frame.
    const std::vector<double>& frameMs() const { return frameMs_; }
    /// The last RenderFrame's wall ms in its three CPU stretches, which add up to its frame ms:
    /// declaring (the views' culling and declarations, the plugin's particle sort and bins, the
    /// graph's compile: no pass has run yet, so the GPU waits), executing (issuing the passes:
    /// draws, dispatches, uploads) and waiting in glFinish for the GPU to finish.
    struct FrameCpu {
        double declareMs = 0.0, executeMs = 0.0, finishMs = 0.0;
    };
    const FrameCpu& lastFrameCpu() const { return lastFrameCpu_; }
    /// How many frames each pass ran / was culled in.
    const std::map<std::string, int>& passRuns() const { return passRuns_; }
    const std::map<std::string, int>& passCulls() const { return passCulls_; }

private:
    bool InitProc(std::string* error);
    void updateCameras(float dt);
    void frameSceneBounds();
    /// The wheel nodes' spin (Vehicle::wheelLocal) into the scene, after each vehicle update.
    void animateWheels();

    Options options_;
    CameraQuads cameraQuads_;
    GameOverlay* overlay_ = nullptr;
    float timeScale_ = 1.0f;
    bool paused_ = false;
    CameraPreset cameraPreset_ = CameraPreset::Chase;
    int barrierNode_ = -1;
    SunLight sun_;
    std::unique_ptr<Platform> platform_;
    SceneData sceneData_;
    cubeScene scene_;
    Vehicle vehicle_;
    // Before fxHost_ and specialFX_: the plugin may use it until it is destroyed.
    std::unique_ptr<JobSystem> jobs_;
    std::unique_ptr<EngineFxHost> fxHost_;
    SpecialFX specialFX_;
    std::unique_ptr<rtt::RenderTargetPool> pool_;
    std::unique_ptr<rtt::FrameGraph> graph_;
    Render render_;
    cubeView mirror_{"mirror", 0};
    cubeView chase_{"chase", 1};
    cubeView chase2_{"chase2", 2};  ///< --split: player two's camera, the right half
    double time_ = 0.0;
    bool explodeFired_ = false;  ///< --explode-at has fired (once per run)
    long long frame_ = 0;
    float cameraHeading_ = 0.0f;
    glm::vec3 framedEye_{0.0f, 2.0f, 8.0f}, framedTarget_{0.0f};  ///< no car: the whole model
    std::vector<std::string> warnings_;
    bool captureNext_ = false;
    bool captureDepthNext_ = false;
    std::vector<float> lastSceneDepth_;
    ImageRGBA8 lastFrame_;
    std::vector<double> frameMs_;
    FrameCpu lastFrameCpu_;
    long rssWarmKb_ = 0, rssLastKb_ = 0;
    int poolFirstLoopMaxTextures_ = 0, poolFirstLoopMaxFramebuffers_ = 0;
    int poolMaxTextures_ = 0, poolMaxFramebuffers_ = 0;
    std::map<std::string, int> passRuns_, passCulls_;
};

}  // namespace cube
