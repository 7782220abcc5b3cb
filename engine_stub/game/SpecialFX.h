#pragma once
// The CUBE SpecialFX component: reads the reactions (SpecialFX::Init), creates one Reaction per
// entry (Reaction::Load -> cubeScene::CreateParticleSystem), and advances them every update
// (SpecialFX::Dyn -> Reaction::Continue(float* currentVehicleCollisionAmount)).
// With --fx plugin the reactions and their particles live in fx_plugin; with --fx legacy they are
// the old hard sprites from data/legacy_smoke.yaml.
#include <memory>
#include <string>
#include <vector>

#include "fx/Plugin.h"
#include "game/Options.h"
#include "render/SunLight.h"

namespace cube {

class cubeScene;
class cubeParticleSystem;
class Vehicle;
struct LegacySmokeDesc;

class Reaction {
public:
    Reaction(class SpecialFX* owner, int index) : owner_(owner), index_(index) {}
    /// Creates this reaction's particle system through the scene's factory.
    void Load(cubeScene& scene, const LegacySmokeDesc* legacy, uint32_t seed);
    /// Advances the reaction by the owner's current step; dispatches on the particle system kind.
    void Continue(float* currentVehicleCollisionAmount);
    cubeParticleSystem* particleSystem() const { return system_; }

private:
    void ContinueLegacySmoke();
    void ContinuePlugin(float* currentVehicleCollisionAmount);

    SpecialFX* owner_;
    int index_;
    cubeParticleSystem* system_ = nullptr;
};

class SpecialFX {
public:
    /// Reads reactions and loads them. False + error (file:line: ...) when the files are bad.
    bool Init(const Options& options, cubeScene& scene, fx::HostAdapter* host, std::string* error);
    /// One update step of every reaction.
    void Dyn(float dt, const Vehicle& vehicle);
    /// With --watch: reloads changed reaction files (plugin path). Errors are printed, the
    /// running set stays.
    void pollHotReload(cubeScene& scene);

    /// Hands the scene's sun to the plugin (fx::SceneLight; the ambient is the mean of the sky
    /// and ground ambients). Game calls it after Init and whenever the sun changes; the legacy
    /// path has nothing to light. A refusal is logged by the plugin (host log). With
    /// --unlit-smoke (Options::litSmoke false) it clears the plugin's light instead.
    void setSceneLight(const SunLight& sun);
    /// Options::litSmoke at run time (the panel); takes effect at the next setSceneLight.
    void setLitSmoke(bool lit) { litSmoke_ = lit; }

    /// After the plugin's set was changed from outside (an editor's loadReactionsFromText):
    /// rebuilds the Reactions when the plugin's count differs from theirs.
    void syncReactions(cubeScene& scene);

    fx::Plugin* plugin() const { return plugin_.get(); }
    FxPath path() const { return path_; }
    float dt() const { return dt_; }
    const Vehicle* vehicle() const { return vehicle_; }
    int reactionCount() const { return int(reactions_.size()); }
    int particlesAlive() const;

private:
    void createReactions(cubeScene& scene);

    FxPath path_ = FxPath::Plugin;
    std::unique_ptr<fx::Plugin> plugin_;
    std::vector<LegacySmokeDesc> legacyDescs_;
    std::vector<Reaction> reactions_;
    uint32_t seed_ = 1;
    float dt_ = 0.0f;
    const Vehicle* vehicle_ = nullptr;
    bool litSmoke_ = true;  ///< Options::litSmoke: false keeps the plugin's smoke unlit
};

}  // namespace cube
