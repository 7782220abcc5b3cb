#pragma once
// The CUBE scene: geometry on the GPU, the particle systems the factory created, and the views.
// cubeScene::Render updates lights and animation (the car's transform), then renders each
// cubeView into the frame graph.
#include <memory>
#include <string>
#include <vector>

#include "fx/Plugin.h"
#include "render/SceneRenderer.h"
#include "rtt/FrameGraph.h"
#include "scene/SceneData.h"
#include "scene/cubeParticleSystem.h"
#include "view/cubeView.h"

namespace cube {

/// Per-frame switches the views read. Defaults: LESS opaque pass, no plugin, HUD on, no inset.
struct FrameSettings {
    bool prepassEqual = false;      ///< opaque reuses the prepass z-buffer, depth test EQUAL
    /// The plugin draws through its immediate path (Plugin::renderView) from one engine pass,
    /// reading the colour target's own z-buffer, instead of declaring frame-graph passes.
    bool pluginImmediate = false;
    /// The frame-graph passes read the linear R32F scene depth (the opaque pass's second render
    /// target) instead of sampling the z-buffer in place (the default).
    bool pluginLinearDepth = false;
    fx::Plugin* plugin = nullptr;   ///< the particle-bucket hook (null: legacy or no effects)
    bool drawLegacy = true;         ///< draw legacy particle systems (false: the bare engine)
    bool hud = true;
    std::string hudText;
    rtt::FrameGraphResource inset;  ///< drawn into the chase view's HUD bucket (mirror)
    bool insetFlipX = true;
    const CameraQuads* cameraQuads = nullptr;  ///< the application's quads on the main camera
    /// When set, the main view reads its scene depth back into it (metres, R32F as stored,
    /// 1e30 where nothing was drawn): a side-effect pass that keeps the depth prepass alive.
    std::vector<float>* sceneDepthOut = nullptr;
};

class cubeScene {
public:
    cubeScene() = default;
    cubeScene(const cubeScene&) = delete;
    cubeScene& operator=(const cubeScene&) = delete;
    /// Uploads the scene and builds the back end's programs. False + error (shader file:line, ...).
    /// `carNode` names the subtree that moves with the car ("" or absent: nothing moves).
    /// `reversedZ`: ask the back end for reversed-Z depth (SceneRenderer::init says when it is
    /// granted).
    bool Init(const SceneData& data, std::string* error, const std::string& carNode = "car",
              bool reversedZ = false);

    /// The factory (cubeScene::CreateParticleSystem): a new system owned by the scene.
    cubeParticleSystem* CreateParticleSystem(cubeParticleSystem::Kind kind);
    void ClearParticleSystems() { particleSystems_.clear(); }
    const std::vector<std::unique_ptr<cubeParticleSystem>>& particleSystems() const { return particleSystems_; }

    /// Lights and animation: where the moving car is this frame.
    void setCarTransform(const glm::mat4& m) { carTransform_ = m; }
    /// Animation of one node of the scene's copy (the car's wheels): SceneData::setLocal.
    void setNodeLocal(int node, const glm::mat4& local) { data_.setLocal(node, local); }
    /// Declares every view's passes; returns the colour target of the last view (the main one).
    rtt::FrameGraphResource Render(rtt::FrameGraph& graph, std::vector<cubeView*>& views, FrameSettings settings);

    const SceneData& data() const { return data_; }
    int carNode() const { return carNode_; }
    const glm::mat4& carTransform() const { return carTransform_; }
    /// The GL back end the views' passes draw with (scene/ itself calls no GL).
    SceneRenderer& renderer() { return renderer_; }
    const SceneRenderer& renderer() const { return renderer_; }

private:
    SceneData data_;
    SceneRenderer renderer_;
    int carNode_ = -1;
    glm::mat4 carTransform_{1.0f};
    std::vector<std::unique_ptr<cubeParticleSystem>> particleSystems_;
};

}  // namespace cube
