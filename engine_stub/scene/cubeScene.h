#pragma once
// The CUBE scene: geometry on the GPU, the particle systems the factory created, and the views.
// cubeScene::Render updates lights and animation (the car's transform), then renders each
// cubeView into the frame graph.
#include <memory>
#include <string>
#include <vector>

#include "fx/Plugin.h"
#include "gl/Program.h"
#include "rtt/FrameGraph.h"
#include "scene/GpuScene.h"
#include "scene/Hud.h"
#include "scene/LegacySpriteRenderer.h"
#include "scene/SceneData.h"
#include "scene/cubeParticleSystem.h"
#include "scene/cubeView.h"

namespace cube {

/// Per-frame switches the views read. Defaults: LESS opaque pass, no plugin, HUD on, no inset.
struct FrameSettings {
    bool prepassEqual = false;      ///< opaque reuses the prepass z-buffer, depth test EQUAL
    fx::Plugin* plugin = nullptr;   ///< the particle-bucket hook (null: legacy or no effects)
    bool drawLegacy = true;         ///< draw legacy particle systems (false: the bare engine)
    bool hud = true;
    std::string hudText;
    rtt::FrameGraphResource inset;  ///< drawn into the chase view's HUD bucket (mirror)
    bool insetFlipX = true;
    int overdrawLayers = 0;         ///< fxbench: opaque panels stacked in front of the camera
    int overdrawCost = 16;          ///< noise octaves per panel pixel
};

class cubeScene {
public:
    cubeScene() = default;
    ~cubeScene();
    cubeScene(const cubeScene&) = delete;
    cubeScene& operator=(const cubeScene&) = delete;
    /// Uploads the scene and builds the programs. False + error (shader file:line, ...).
    /// `carNode` names the subtree that moves with the car ("" or absent: nothing moves).
    bool Init(const SceneData& data, std::string* error, const std::string& carNode = "car");

    /// The factory (cubeScene::CreateParticleSystem): a new system owned by the scene.
    cubeParticleSystem* CreateParticleSystem(cubeParticleSystem::Kind kind);
    void ClearParticleSystems() { particleSystems_.clear(); }
    const std::vector<std::unique_ptr<cubeParticleSystem>>& particleSystems() const { return particleSystems_; }

    /// Lights and animation: where the moving car is this frame.
    void setCarTransform(const glm::mat4& m) { carTransform_ = m; }
    /// Declares every view's passes; returns the colour target of the last view (the main one).
    rtt::FrameGraphResource Render(rtt::FrameGraph& graph, std::vector<cubeView*>& views, FrameSettings settings);

    /// fxbench's overdraw panels: `layers` opaque quads facing the camera from 40 m down to 20 m,
    /// drawn back to front (the worst order for depth test LESS) over the upper 70% of the view,
    /// with `p` (uses its uModel and, if present, uBaseColor).
    void drawOverdrawPanels(const gl::Program& p, int layers, const glm::mat4& view, float fovY, float aspect) const;

    const SceneData& data() const { return data_; }
    const GpuScene& gpu() const { return gpu_; }
    int carNode() const { return carNode_; }
    const glm::mat4& carTransform() const { return carTransform_; }

    // Back-end resources the views' passes draw with.
    gl::Program meshProgram, prepassProgram, skyProgram, blitProgram, costlyProgram;
    GLuint panelVao = 0, panelVbo = 0;  ///< one unit quad (z = 0, normal +Z) for the overdraw panels
    LegacySpriteRenderer legacySprites;
    Hud hud;
    GLuint emptyVao = 0;  ///< for gl_VertexID full-screen triangles (core profile needs a VAO)

private:
    SceneData data_;
    GpuScene gpu_;
    int carNode_ = -1;
    glm::mat4 carTransform_{1.0f};
    std::vector<std::unique_ptr<cubeParticleSystem>> particleSystems_;
};

}  // namespace cube
