#pragma once
// A particle system as the CUBE scene knows it. Two kinds share the CUBE call sequence
// (cubeScene::CreateParticleSystem -> Initialize -> InitInternalParticle):
//  - Legacy: the old hard smoke. Sprites simulated here, aligned to the view plane on the CPU
//    every frame and spawned hovering above the ground.
//  - Plugin: a proxy for one plugin reaction; its particles live in fx_plugin, which draws them
//    through the particle-bucket hook.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/LegacySmokeDesc.h"

namespace cube {

struct WheelState;

class cubeParticleSystem {
public:
    enum class Kind { Legacy, Plugin };

    /// One CPU-aligned sprite corner: what the legacy renderer uploads.
    struct SpriteVertex {
        glm::vec3 position;
        glm::vec2 uv;
        float alpha;
    };

    explicit cubeParticleSystem(Kind kind) : kind_(kind) {}

    /// Legacy: sets up from the data file's description. Plugin: `pluginReaction` is the index.
    void Initialize(const LegacySmokeDesc* legacy, int pluginReaction, uint32_t seed);

    Kind kind() const { return kind_; }
    int pluginReaction() const { return pluginReaction_; }
    const std::string& name() const { return desc_.name; }
    int alive() const { return int(age_.size()); }
    const glm::vec3& tint() const { return desc_.tint; }

    /// Legacy only: emits at the wheels that slip and moves the sprites.
    void Update(float dt, const WheelState* wheels, int wheelCount);
    /// Legacy only: builds two triangles per sprite facing the camera (right/up of the view),
    /// back to front from `eye`, into `out` (cleared first).
    void BuildQuads(const glm::vec3& eye, const glm::vec3& right, const glm::vec3& up,
                    std::vector<SpriteVertex>* out) const;

private:
    void InitInternalParticle();
    float random01();

    Kind kind_;
    int pluginReaction_ = -1;
    LegacySmokeDesc desc_;
    uint64_t rng_ = 0;
    float emitCarry_ = 0.0f;
    // Structure of arrays, reserved once in InitInternalParticle.
    std::vector<glm::vec3> position_, velocity_;
    std::vector<float> age_, life_;
    mutable std::vector<uint32_t> order_;
    mutable std::vector<float> keys_;
};

}  // namespace cube
