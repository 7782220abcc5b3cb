#include "game/SpecialFX.h"

#include <cstdio>

#include "game/TechniqueModes.h"
#include "game/Vehicle.h"
#include "gl/Paths.h"
#include "platform/Trace.h"
#include "scene/LegacySmokeDesc.h"
#include "scene/cubeParticleSystem.h"
#include "view/cubeScene.h"

namespace cube {

void Reaction::Load(cubeScene& scene, const LegacySmokeDesc* legacy, uint32_t seed) {
    Trace::call("Reaction::Load");
    const bool isLegacy = owner_->path() == FxPath::Legacy;
    system_ = scene.CreateParticleSystem(isLegacy ? cubeParticleSystem::Kind::Legacy
                                                  : cubeParticleSystem::Kind::Plugin);
    system_->Initialize(legacy, isLegacy ? -1 : index_, seed + uint32_t(index_));
}

void Reaction::Continue(float* currentVehicleCollisionAmount) {
    Trace::call("Reaction::Continue");
    // The CUBE switch on the reaction's behaviour.
    switch (system_ ? system_->kind() : cubeParticleSystem::Kind::Plugin) {
        case cubeParticleSystem::Kind::Legacy: ContinueLegacySmoke(); break;
        case cubeParticleSystem::Kind::Plugin: ContinuePlugin(currentVehicleCollisionAmount); break;
    }
}

void Reaction::ContinueLegacySmoke() {
    const Vehicle* v = owner_->vehicle();
    if (v) system_->Update(owner_->dt(), v->wheels().data(), int(v->wheels().size()));
}

void Reaction::ContinuePlugin(float* currentVehicleCollisionAmount) {
    // The plugin's own per-type continue (wheel smoke, dust, collision burst).
    owner_->plugin()->continueReaction(index_, owner_->dt(), currentVehicleCollisionAmount);
}

bool SpecialFX::Init(const Options& options, cubeScene& scene, fx::HostAdapter* host, std::string* error) {
    litSmoke_ = options.litSmoke;
    Trace::call("SpecialFX::Init");
    path_ = options.fx;
    seed_ = options.seed;
    if (path_ == FxPath::Legacy) {
        const std::string file = options.legacyReactions.empty() ? paths::data() + "/legacy_smoke.yaml"
                                                                 : options.legacyReactions;
        if (!loadLegacySmoke(file, &legacyDescs_, error)) return false;
    } else {
        // The plugin carries its shaders and atlas; the engine hands it a shader folder only
        // when the user points CUBE_SHADER_DIR at one (live shader edits).
        fx::PluginImports imports;
        imports.host = host;
        imports.shaderDir = paths::shaderOverride();
        imports.seed = uint64_t(options.seed) + 1;  // the plugin reads 0 as "its default seed"
        fx::ErrorCode code = fx::ErrorCode::None;
        plugin_ = fxCreatePlugin(imports, &code);
        if (!plugin_) {
            *error = std::string("fx_plugin: not created (") + fx::errorCodeName(code) +
                     "; details in the fx log above)";
            return false;
        }
        // Every diagnostic has already gone through the host's log (stderr) once; the error
        // says only what failed, so nothing is printed twice.
        const std::string path = options.reactions.empty() ? paths::reactions() : options.reactions;
        if (!plugin_->loadReactions(path, nullptr)) {
            *error = path + ": reactions could not be loaded (errors above)";
            return false;
        }
        fx::RenderOptions ro;
        const TechniqueMode* mode = findTechniqueMode(options.mode);  // Options checked the word
        ro.techniqueOverride = mode ? mode->technique : fx::Technique::FromReaction;
        ro.quarterRes = options.quarterRes || options.quarterResAlways || options.bilinearUpsample;
        ro.quarterResAlways = options.quarterResAlways || options.bilinearUpsample;  // a comparison: every view
        ro.bilinearUpsample = options.bilinearUpsample;
        plugin_->setRenderOptions(ro);
        // Compile the particle programs now, so a broken shader stops start-up with file:line
        // instead of surfacing at the first frame with smoke. After the options: what the
        // plugin builds is every program the loaded reactions *and* the options can draw with
        // (--mode mega needs the mega programs though no reaction asks for them). A set with no
        // reaction never draws a particle and compiles nothing.
        if (plugin_->reactionCount() > 0 && !plugin_->prepareGl(nullptr)) {
            *error = "fx_plugin: particle shaders or atlas failed to load (errors above)";
            return false;
        }
    }
    createReactions(scene);
    return true;
}

void SpecialFX::setSceneLight(const SunLight& sun) {
    if (!plugin_) return;
    if (!litSmoke_) {
        plugin_->clearSceneLight();
        return;
    }
    fx::SceneLight light;
    light.toSun = sun.toSun;
    light.sunColor = sun.color;
    light.ambient = 0.5f * (sun.ambientSky + sun.ambientGround);
    // A refusal (a value the plugin cannot use) is logged once by the plugin, through the host.
    (void)plugin_->setSceneLight(light);
}

void SpecialFX::createReactions(cubeScene& scene) {
    scene.ClearParticleSystems();
    reactions_.clear();
    const int count = path_ == FxPath::Legacy ? int(legacyDescs_.size()) : plugin_->reactionCount();
    reactions_.reserve(size_t(count));
    for (int i = 0; i < count; ++i) {
        reactions_.emplace_back(this, i);
        reactions_.back().Load(scene, path_ == FxPath::Legacy ? &legacyDescs_[size_t(i)] : nullptr, seed_);
    }
}

void SpecialFX::Dyn(float dt, const Vehicle& vehicle) {
    Trace::call("SpecialFX::Dyn");
    dt_ = dt;
    vehicle_ = &vehicle;
    float collision = vehicle.collisionAmount();
    for (Reaction& r : reactions_) r.Continue(&collision);
}

void SpecialFX::pollHotReload(cubeScene& scene) {
    if (!plugin_) return;
    // A rejected reload is reported once, by the plugin through the host's log. Particle shader
    // edits are picked up too when CUBE_SHADER_DIR points the plugin at a folder (a broken edit
    // keeps the last good programs).
    plugin_->pollShaderReload(nullptr);
    const bool reloaded = plugin_->pollHotReload(nullptr);
    if (reloaded) {
        std::fprintf(stderr, "reactions reloaded: %d live\n", plugin_->reactionCount());
        createReactions(scene);
        // A reloaded set may use a technique the old one did not (stateless, mega): its programs
        // are built now, not at its first particle; a failure is logged once by the plugin and
        // that technique is not drawn (the run goes on, as for a broken shader edit).
        (void)plugin_->prepareGl(nullptr);
    }
}

void SpecialFX::syncReactions(cubeScene& scene) {
    if (plugin_ && plugin_->reactionCount() != int(reactions_.size())) createReactions(scene);
}

int SpecialFX::particlesAlive() const {
    if (plugin_) return plugin_->stats().particlesAlive;
    int n = 0;
    for (const Reaction& r : reactions_) n += r.particleSystem() ? r.particleSystem()->alive() : 0;
    return n;
}

}  // namespace cube
