#pragma once
// The plugin behind fx::Plugin: the running reactions (ReactionLibrary: load + hot reload), one
// ReactionRuntime per reaction, the switches and stats. It records; it draws nothing itself.
//
// Drawing is the renderers' (render/Renderers.h), which the plugin owns once installRenderers()
// made them (fxCreatePlugin does). The setters write one FrameSettings; each call that draws
// (declarePasses, declareShadowPasses, renderView, prepareGl) hands the renderers that value and
// the runtimes, so no renderer reads a switch back. Without renderers, declarePasses declares
// nothing, so the host allocates nothing for particles.
//
// Runtimes live in a std::vector that is rebuilt when a new reaction set goes live
// (loadReactions / pollHotReload): references and indices into it are valid until then;
// runtimeGeneration() changes each time. A reaction whose name and capacity survive a reload
// keeps its particles (the smoke on screen does not vanish).
#include <memory>
#include <string>
#include <vector>

#include "fx/HostAdapter.h"
#include "fx/Plugin.h"
#include "../reactions/ReactionLibrary.h"
#include "../render/FrameSettings.h"
#include "../sim/ReactionRuntime.h"
#include "../base/ApiErrors.h"

namespace fx {

class Renderers;
struct ImmediateView;
class ImmediateRenderer;

class PluginImpl final : public Plugin {
public:
    /// `imports.host` must be non-null (fxCreatePlugin checks it).
    explicit PluginImpl(const PluginImports& imports);
    ~PluginImpl() override;  ///< the host's GL context current once the renderers drew

    // fx::Plugin
    bool loadReactions(const std::string& path, Diagnostics* out) override;
    bool pollHotReload(Diagnostics* out) override;
    int reactionCount() const override { return static_cast<int>(runtimes_.size()); }
    std::string reactionName(int index) const override;
    ErrorCode continueReaction(int index, float dt, float* currentVehicleCollisionAmount) override;
    ErrorCode setRenderOptions(const RenderOptions& options) override;
    RenderOptions renderOptions() const override { return settings_.options; }
    bool prepareGl(Diagnostics* out) override;
    ErrorCode declarePasses(const ViewInfo& view, FrameBuilder& frame) override;
    Stats stats() const override;
    ParticleCheck checkParticles() const override;
    bool pollShaderReload(Diagnostics* out) override;
    std::vector<ReactionKeyInfo> reactionSchema() const override;
    std::vector<std::string> reactionFiles() const override { return library_.current().files; }
    std::string reactionFile(int index) const override;
    std::string reactionValue(int index, const std::string& key) const override;
    int reactionParticlesAlive(int index) const override;
    bool loadReactionsFromText(const std::string& file, const std::string& text,
                               Diagnostics* out) override;
    ErrorCode setParticleShape(ParticleShape shape) override;
    ParticleShape particleShape() const override { return settings_.shape; }
    ReactionStats reactionStats(int index) const override;
    ErrorCode fireReaction(const std::string& name, const glm::vec3& point) override;
    ErrorCode setSceneLight(const SceneLight& light) override;
    void clearSceneLight() override { settings_.light = LightState{}; }
    SmokeShadow declareShadowPasses(const ViewInfo& view, FrameBuilder& frame) override;
    // Deprecated switches (Plugin.h): validated and kept for their getters, read by no renderer.
    ErrorCode setQuarterResEdges(QuarterResEdges mode) override;
    QuarterResEdges quarterResEdges() const override { return edges_; }
    ErrorCode setFadeClassification(FadeClassification mode) override;
    FadeClassification fadeClassification() const override { return classification_; }
    ErrorCode setFadeClassCounting(bool on) override {
        (void)on;
        return ErrorCode::None;
    }
    FadeClassCounts fadeClassCounts() const override { return FadeClassCounts{}; }

    /// Makes the renderers (shaders from the plugin's shader dir, the atlas from `dataDir`;
    /// empty = the copies embedded in the library). fxCreatePlugin calls it once; no GL yet.
    void installRenderers(const std::string& dataDir);
    /// The renderers, or null before installRenderers().
    Renderers* renderers() const { return renderers_.get(); }
    /// The immediate path (fxApi::renderView): the renderers' immediate path, or `through` (one
    /// of the caller's own: its refusals go to the log, not to apiErrors), with this plugin's
    /// runtimes and switches; without renderers nothing is drawn (None).
    ErrorCode renderImmediate(const ImmediateView& view, ImmediateRenderer* through = nullptr);
    /// What the setters wrote: every drawing call hands the renderers this value.
    const FrameSettings& frameSettings() const { return settings_; }
    /// The scene light the renderers draw with (LightState::on false = unlit).
    const LightState& light() const { return settings_.light; }
    /// Where refused calls are reported (the renderers report SizeMismatch here).
    ApiErrors& apiErrors() const { return errors_; }

    const std::vector<ReactionRuntime>& runtimes() const { return runtimes_; }
    int runtimeGeneration() const { return runtimeGeneration_; }
    const ReactionLibrary& library() const { return library_; }
    ReactionLibrary& library() { return library_; }
    HostAdapter& host() const { return *host_; }
    const std::string& shaderDir() const { return shaderDir_; }

    /// Seed for reactions created from now on (a reaction kept across a reload keeps its
    /// generator). Default: PluginImports::seed, or ReactionRuntime::kDefaultSeed when that is 0.
    void setSeed(uint64_t seed) { seed_ = seed; }

private:
    /// Builds runtimes for the library's current set, moving over those that keep their pool.
    void adoptCurrentSet();
    /// Before any particle changes (a step, a fire, a reload): what a declared pass still holds of
    /// the pools is written out first (Renderers::settleLists), so it draws what was declared.
    void settleDrawLists();
    void logDiagnostics(const Diagnostics& diags, const char* what);

    HostAdapter* host_;
    std::string shaderDir_;
    uint64_t seed_;
    ReactionLibrary library_;
    std::vector<ReactionRuntime> runtimes_;
    int runtimeGeneration_ = 0;
    FrameSettings settings_;
    // The deprecated switches' values, kept for their getters; no renderer reads them.
    QuarterResEdges edges_ = QuarterResEdges::DepthAware;
    FadeClassification classification_ = FadeClassification::Off;
    std::unique_ptr<Renderers> renderers_;
    mutable ApiErrors errors_;  // mutable: a const query (reactionName) may refuse too
    int particlesDrawn_ = 0;
    int reloads_ = 0;
    int reloadErrors_ = 0;
    bool everLoaded_ = false;
};

/// The PluginImpl behind a plugin made by fxCreatePlugin (the C++ layer's wrapper around the C
/// handle) or a PluginImpl itself; for this repository's tests, which link the library's objects.
PluginImpl& implOf(Plugin& plugin);
const PluginImpl& implOf(const Plugin& plugin);

}  // namespace fx
