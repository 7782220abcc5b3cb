#include "view/cubeScene.h"

#include "platform/Trace.h"

namespace cube {

bool cubeScene::Init(const SceneData& data, std::string* error, const std::string& carNode, bool reversedZ) {
    data_ = data;
    carNode_ = carNode.empty() ? -1 : data_.findNode(carNode);
    return renderer_.init(data_, error, reversedZ);
}

cubeParticleSystem* cubeScene::CreateParticleSystem(cubeParticleSystem::Kind kind) {
    Trace::call("cubeScene::CreateParticleSystem");
    particleSystems_.push_back(std::make_unique<cubeParticleSystem>(kind));
    return particleSystems_.back().get();
}

rtt::FrameGraphResource cubeScene::Render(rtt::FrameGraph& graph, std::vector<cubeView*>& views,
                                          FrameSettings settings) {
    Trace::call("cubeScene::Render");
    rtt::FrameGraphResource last;
    for (size_t i = 0; i < views.size(); ++i) {
        FrameSettings s = settings;
        const bool main = i + 1 == views.size();
        if (!main) {
            s.hud = false;
            s.inset = {};
            s.cameraQuads = nullptr;
            s.sceneDepthOut = nullptr;
        } else if (!views[i]->placed()) {
            s.inset = last;  // the previous view (mirror) is inset into the main view
        } else {
            s.inset = {};  // split screen: the previous view is the other half, not a mirror
        }
        last = views[i]->Render(*this, graph, s);
    }
    return last;
}

}  // namespace cube
