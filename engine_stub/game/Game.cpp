#include "game/Game.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <unistd.h>

#include "game/JobSystem.h"
#include "gl/Gl.h"
#include "gl/Paths.h"
#include "platform/Trace.h"
#include "scene/SceneLoader.h"

namespace cube {

namespace {
long residentKb() {
    long pages = 0, resident = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}
}  // namespace


Game::Game() = default;
Game::~Game() {
    // GL objects of the plugin and the pool go before the context.
    graph_.reset();
    pool_.reset();
}

bool Game::Init(const Options& options, std::string* error, std::unique_ptr<Platform> platform) {
    Trace::call("Game::Init");
    options_ = options;
    platform_ = std::move(platform);
    if (!platform_) {
        PlatformDesc pd;
        pd.backend = options_.backend;
        pd.width = options_.width;
        pd.height = options_.height;
        platform_ = Platform::create(pd, error);
        if (!platform_) return false;
    }
    // CUBE may run InitProc on a loader thread; this stand-in runs it inline.
    return InitProc(error);
}

bool Game::InitProc(std::string* error) {
    Trace::call("Game::InitProc");
    const std::string scenePath = options_.scene.empty() ? paths::data() + "/race.gltf" : options_.scene;
    SceneError sceneError;
    if (!loadScene(scenePath, &sceneData_, &sceneError)) {
        *error = sceneError.str();
        return false;
    }
    warnings_ = sceneData_.warnings;
    // Any glTF renders: a model without the car node is shown whole, with nothing driving.
    const std::string carName = options_.carNode.empty() ? "car" : options_.carNode;
    std::string carNode = carName;
    if (sceneData_.findNode(carName) < 0) {
        if (!options_.carNode.empty()) {
            *error = "--car-node: " + scenePath + " has no node named '" + carName + "'";
            return false;
        }
        warnings_.push_back(scenePath + ": no node named 'car': the scripted drive, the wheel reactions and "
                            "the mirror are off and the camera frames the model (--car-node NAME picks a car)");
        vehicle_.disable();
        options_.mirror = false;
        carNode.clear();
    } else {
        std::string warning;
        if (!vehicle_.init(sceneData_, error, carName, &warning)) {
            *error = scenePath + ": " + *error;
            return false;
        }
        if (!warning.empty()) warnings_.push_back(scenePath + ": " + warning);
    }
    if (!vehicle_.active()) frameSceneBounds();
    barrierNode_ = sceneData_.findNode("barrier_right");
    scene_.renderer().setFog(options_.fog);  // before Init: the programs are built with it or without
    if (!scene_.Init(sceneData_, error, carNode, options_.reversedZ)) return false;
    // Options were validated (parseOptions); a harness that set them directly gets them clamped.
    sun_ = sunFromAngles(options_.sunAzimuth, options_.sunElevation);
    scene_.renderer().setSun(sun_);
    rtt::RenderTargetPoolDesc poolDesc;
    poolDesc.framesUntilFree = std::max(1, options_.poolFramesUntilFree);
    pool_ = std::make_unique<rtt::RenderTargetPool>(poolDesc);
    graph_ = std::make_unique<rtt::FrameGraph>(*pool_, platform_->softwareRenderer());
    time_ = options_.startTime;
    vehicle_.update(sceneData_, time_);
    animateWheels();
    cameraHeading_ = vehicle_.pose().heading;
    updateCameras(0.0f);
    jobs_ = std::make_unique<JobSystem>(JobSystem::resolveThreads(options_.threads));
    fxHost_ = std::make_unique<EngineFxHost>(&vehicle_, platform_.get(), jobs_.get());
    if (!specialFX_.Init(options_, scene_, fxHost_.get(), error)) return false;
    specialFX_.setSceneLight(sun_);
    return true;
}

bool Game::setSun(double azimuthDeg, double elevationDeg) {
    if (!validSunAngles(azimuthDeg, elevationDeg)) return false;
    options_.sunAzimuth = azimuthDeg;
    options_.sunElevation = elevationDeg;
    sun_ = sunFromAngles(azimuthDeg, elevationDeg);
    scene_.renderer().setSun(sun_);
    specialFX_.setSceneLight(sun_);
    return true;
}

void Game::animateWheels() {
    for (int i = 0; i < 4; ++i) {
        const int node = vehicle_.wheelNode(i);
        if (node >= 0) scene_.setNodeLocal(node, vehicle_.wheelLocal(i));
    }
}

// A camera that shows the whole model: from front-right and above, far enough that the bounding
// sphere fits the 55-degree view, clip planes widened to hold it.
void Game::frameSceneBounds() {
    bool any = false;
    glm::vec3 lo(0.0f), hi(0.0f);
    for (const SceneNode& n : sceneData_.nodes) {
        if (n.meshes.empty()) continue;
        lo = any ? glm::min(lo, n.aabbMin) : n.aabbMin;
        hi = any ? glm::max(hi, n.aabbMax) : n.aabbMax;
        any = true;
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
    const float distance = radius / std::sin(glm::radians(55.0f) * 0.5f) * 1.1f;
    framedTarget_ = centre;
    framedEye_ = centre + distance * glm::normalize(glm::vec3(0.6f, 0.45f, 0.8f));
    if (!options_.fixedCamera) {
        options_.farPlane = std::max(options_.farPlane, distance + 2.0f * radius);
        options_.nearPlane = std::max(options_.nearPlane, std::min(options_.farPlane * 1e-5f, 0.5f * (distance - radius)));
    }
}

void Game::updateCameras(float dt) {
    constexpr float kPi = 3.14159265358979f;
    const DrivePose& pose = vehicle_.pose();
    // The chase camera's heading follows the car's with a lag (exact exponential smoothing, the
    // same for any dt), taking the short way round.
    const float diff = std::remainder(pose.heading - cameraHeading_, 2.0f * kPi);
    cameraHeading_ += diff * (1.0f - std::exp(-2.5f * dt));
    const glm::vec3 fwd(std::cos(cameraHeading_), 0.0f, -std::sin(cameraHeading_));
    ViewCamera& c = chase_.camera();
    c.eye = pose.position - 7.5f * fwd + glm::vec3(0.0f, 2.6f, 0.0f);
    c.target = pose.position + 2.0f * fwd + glm::vec3(0.0f, 0.6f, 0.0f);
    const glm::vec3 carFwd(std::cos(pose.heading), 0.0f, -std::sin(pose.heading));
    if (cameraPreset_ == CameraPreset::BurnoutCloseUp) {
        // Low, beside and behind the rear axle, looking at the rear wheels' smoke.
        const glm::vec3 side = glm::normalize(glm::cross(carFwd, glm::vec3(0.0f, 1.0f, 0.0f)));
        c.eye = pose.position - 3.5f * carFwd + 2.6f * side + glm::vec3(0.0f, 1.0f, 0.0f);
        c.target = pose.position - 1.3f * carFwd + glm::vec3(0.0f, 0.6f, 0.0f);
    } else if (cameraPreset_ == CameraPreset::Barrier && barrierNode_ >= 0) {
        const SceneNode& b = sceneData_.nodes[size_t(barrierNode_)];
        const glm::vec3 centre = 0.5f * (b.aabbMin + b.aabbMax);
        const float reach = std::max(12.0f, 0.35f * glm::length(b.aabbMax - b.aabbMin));
        c.eye = centre + reach * glm::normalize(glm::vec3(-0.6f, 0.35f, 0.7f));
        c.target = centre;
    }
    if (!vehicle_.active()) {
        c.eye = framedEye_;
        c.target = framedTarget_;
    }
    if (options_.fixedCamera) {
        c.eye = glm::vec3(options_.cameraEye[0], options_.cameraEye[1], options_.cameraEye[2]);
        c.target = glm::vec3(options_.cameraTarget[0], options_.cameraTarget[1], options_.cameraTarget[2]);
    }
    c.fovY = glm::radians(55.0f);
    c.nearPlane = options_.nearPlane;
    c.farPlane = options_.farPlane;

    // --split, player two: beside the car on its left and a little behind, looking at the rear
    // wheels, so the same smoke is seen from the other side.
    ViewCamera& p2 = chase2_.camera();
    const glm::vec3 left = -glm::normalize(glm::cross(carFwd, glm::vec3(0.0f, 1.0f, 0.0f)));
    p2.eye = pose.position - 2.5f * carFwd + 6.5f * left + glm::vec3(0.0f, 2.0f, 0.0f);
    p2.target = pose.position - 1.3f * carFwd + glm::vec3(0.0f, 0.8f, 0.0f);
    p2.fovY = c.fovY;
    p2.nearPlane = c.nearPlane;
    p2.farPlane = c.farPlane;

    // Rear-view mirror: from just behind the car, looking back along it.
    ViewCamera& m = mirror_.camera();
    m.eye = pose.position + glm::vec3(0.0f, 1.1f, 0.0f) - 2.5f * carFwd;
    m.target = m.eye - 10.0f * carFwd - glm::vec3(0.0f, 0.9f, 0.0f);
    m.fovY = glm::radians(30.0f);
    m.nearPlane = 0.1f;
    m.farPlane = 500.0f;
}

void Game::Dyn(float dt) {
    Trace::call("Game::Dyn");
    if (overlay_) {
        overlay_->beginFrame(*this, dt);
        specialFX_.syncReactions(scene_);  // the overlay may have loaded a set of another size
    }
    // A scale of 1 multiplies exactly: without an overlay the steps are the ones given.
    Update(paused_ ? 0.0f : dt * timeScale_);
    RenderFrame();
    ++frame_;
}

bool Game::fireExplosionAtCar() {
    fx::Plugin* plugin = specialFX_.plugin();
    return plugin && plugin->fireReaction("explosion", vehicle_.pose().position + glm::vec3(0.0f, 0.3f, 0.0f)) ==
                         fx::ErrorCode::None;
}

bool Game::checkExplodeAt(std::string* error) const {
    if (options_.explodeAt < 0.0) return true;
    const fx::Plugin* plugin = specialFX_.plugin();
    const int count = plugin ? plugin->reactionCount() : 0;
    // The plugin's fireReaction rule: "explosion" itself or one of its layers, type on_demand.
    for (int i = 0; i < count; ++i) {
        const std::string name = plugin->reactionName(i);
        const bool match = name == "explosion" || name.compare(0, 10, "explosion.") == 0;
        if (match && plugin->reactionValue(i, "type") == "on_demand") return true;
    }
    const std::string from = options_.reactions.empty() ? paths::reactions() : options_.reactions;
    *error = "--explode-at: " + from +
             " loads no on_demand reaction named 'explosion' (or 'explosion.<layer>'), so nothing would "
             "fire; expected reactions/explosion.yaml or a recipe like it among --reactions";
    return false;
}

void Game::Update(float dt) {
    if (!std::isfinite(dt) || dt < 0.0f) dt = 0.0f;
    dt = std::min(dt, 10.0f);
    if (options_.watch) specialFX_.pollHotReload(scene_);
    // --explode-at: the explosion recipe fires once, at the car, in the first step that reaches T
    // (the very first one when T is the start time).
    const bool explode = options_.explodeAt >= 0.0 && !explodeFired_ && time_ + dt >= options_.explodeAt;
    time_ += dt;
    if (explode) {
        explodeFired_ = true;
        fireExplosionAtCar();
    }
    vehicle_.update(sceneData_, options_.stationaryCar ? options_.startTime : time_, options_.stationaryCar);
    animateWheels();
    updateCameras(dt);
    specialFX_.Dyn(dt, vehicle_);
}

double Game::RenderFrame() {
    const auto start = std::chrono::steady_clock::now();
    RenderFrameOutputs out;
    out.frame = captureNext_ ? &lastFrame_ : nullptr;
    out.sceneDepth = captureDepthNext_ ? &lastSceneDepth_ : nullptr;
    out.passRuns = &passRuns_;
    out.passCulls = &passCulls_;
    if (render_.Dyn(*this, out)) captureNext_ = captureDepthNext_ = false;
    const auto issued = std::chrono::steady_clock::now();
    gl::finish();  // the frame's GPU work is in the measured time
    // The GPU's pass timings of this very frame (ready after the finish): a later frame, maybe
    // in another mode (fxbench interleaves them), never gets them.
    graph_->resolveTimings();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const double issuedMs = std::chrono::duration<double, std::milli>(issued - start).count();
    lastFrameCpu_.executeMs = std::min(graph_->report().executeCpuMs, issuedMs);
    lastFrameCpu_.declareMs = issuedMs - lastFrameCpu_.executeMs;
    lastFrameCpu_.finishMs = ms - issuedMs;  // the wait, and reading the timings back
    frameMs_.push_back(ms);
    // Memory and pool probes for the soak test (outside the timed window): after warm-up, and
    // the latest frame.
    // The pool's live count depends on which passes the current frame needs, so "flat" means:
    // the most targets alive at once over the whole run is no more than in the first loop of the
    // scripted drive after warm-up (the drive repeats every Vehicle::kLoopSeconds).
    if (options_.watch || !options_.statsJson.empty()) {
        const size_t n = frameMs_.size();
        if (n == 300) rssWarmKb_ = residentKb();
        if (n >= 300) {
            const rtt::RenderTargetPoolStats ps = pool_->stats();
            const bool firstLoop = time_ - options_.startTime < 300.0 * double(std::max(options_.fixedDt, 1e-3)) +
                                                                    Vehicle::kLoopSeconds;
            if (firstLoop) {
                poolFirstLoopMaxTextures_ = std::max(poolFirstLoopMaxTextures_, ps.liveTextures);
                poolFirstLoopMaxFramebuffers_ = std::max(poolFirstLoopMaxFramebuffers_, ps.liveFramebuffers);
            }
            poolMaxTextures_ = std::max(poolMaxTextures_, ps.liveTextures);
            poolMaxFramebuffers_ = std::max(poolMaxFramebuffers_, ps.liveFramebuffers);
        }
        rssLastKb_ = residentKb();
    }
    return ms;
}

namespace {
std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out + "\"";
}
}  // namespace

bool Game::writeStatsJson(const std::string& path, std::string* error) const {
    std::vector<double> sorted = frameMs_;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
    const rtt::RenderTargetPoolStats ps = pool_ ? pool_->stats() : rtt::RenderTargetPoolStats{};
    const rtt::FrameGraphReport& r = graph_->report();
    std::ofstream out(path);
    if (!out) {
        *error = path + ": cannot write stats (folder missing or not writable?)";
        return false;
    }
    auto list = [&](const std::vector<std::string>& v) {
        std::string s = "[";
        for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + jsonString(v[i]);
        return s + "]";
    };
    auto counts = [&](const std::map<std::string, int>& m) {
        std::string s = "{";
        bool first = true;
        for (const auto& kv : m) {
            s += (first ? "" : ", ") + jsonString(kv.first) + ": " + std::to_string(kv.second);
            first = false;
        }
        return s + "}";
    };
    const fx::Stats fs = specialFX_.plugin() ? specialFX_.plugin()->stats() : fx::Stats{};
    // Per reaction, as the plugin counts it (API 1.1); [] on the legacy path.
    std::string reactionStats = "[";
    if (fx::Plugin* plugin = specialFX_.plugin()) {
        for (int i = 0; i < plugin->reactionCount(); ++i) {
            const fx::ReactionStats rs = plugin->reactionStats(i);
            reactionStats += std::string(i ? "," : "") + "\n    {\"name\": " + jsonString(rs.name) +
                             ", \"technique\": " + jsonString(rs.technique) +
                             ", \"alive\": " + std::to_string(rs.alive) +
                             ", \"emitted\": " + std::to_string(rs.emitted) + "}";
        }
        if (plugin->reactionCount() > 0) reactionStats += "\n  ";
    }
    reactionStats += "]";
    char median_s[64];
    std::snprintf(median_s, sizeof median_s, "%.4f", median);
    out << "{\n"
        << "  \"frames\": " << frame_ << ",\n"
        << "  \"renderer\": " << jsonString(platform_ ? platform_->rendererName() : "") << ",\n"
        << "  \"backend\": " << jsonString(platform_ ? backendName(platform_->backend()) : "") << ",\n"
        << "  \"fx\": " << jsonString(specialFX_.path() == FxPath::Legacy ? "legacy" : "plugin") << ",\n"
        << "  \"reactions\": " << specialFX_.reactionCount() << ",\n"
        << "  \"particles_alive\": " << specialFX_.particlesAlive() << ",\n"
        << "  \"particles_drawn\": " << fs.particlesDrawn << ",\n"
        << "  \"reloads\": " << fs.reloads << ",\n"
        << "  \"reload_errors\": " << fs.reloadErrors << ",\n"
        << "  \"reaction_stats\": " << reactionStats << ",\n"
        << "  \"passes_run\": " << list(r.executed) << ",\n"
        << "  \"passes_culled\": " << list(r.culled) << ",\n"
        << "  \"pass_run_frames\": " << counts(passRuns_) << ",\n"
        << "  \"pass_culled_frames\": " << counts(passCulls_) << ",\n"
        << "  \"render_targets_allocated\": " << ps.totalAllocations << ",\n"
        << "  \"render_targets_live\": " << r.targetsLive << ",\n"
        << "  \"render_targets_last_frame\": " << r.targetsAcquired << ",\n"
        << "  \"timing_method\": " << jsonString(r.timingMethod) << ",\n"
        << "  \"rss_kb_after_300_frames\": " << rssWarmKb_ << ",\n"
        << "  \"rss_kb_end\": " << rssLastKb_ << ",\n"
        << "  \"pool_max_live_textures_first_loop\": " << poolFirstLoopMaxTextures_ << ",\n"
        << "  \"pool_max_live_framebuffers_first_loop\": " << poolFirstLoopMaxFramebuffers_ << ",\n"
        << "  \"pool_max_live_textures\": " << poolMaxTextures_ << ",\n"
        << "  \"pool_max_live_framebuffers\": " << poolMaxFramebuffers_ << ",\n"
        << "  \"pool_live_textures\": " << ps.liveTextures << ",\n"
        << "  \"pool_live_framebuffers\": " << ps.liveFramebuffers << ",\n"
        << "  \"gl_errors\": " << gl::errorCount() << ",\n"
        << "  \"frame_ms_median\": " << median_s << "\n"
        << "}\n";
    return bool(out);
}

}  // namespace cube
