#include "scene/cubeScene.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "game/Trace.h"

namespace cube {

bool cubeScene::Init(const SceneData& data, std::string* error, const std::string& carNode) {
    data_ = data;
    carNode_ = carNode.empty() ? -1 : data_.findNode(carNode);
    gpu_.upload(data_);
    if (!gl::Program::load("vs_mesh.glsl", "fs_mesh.glsl", &meshProgram, error)) return false;
    if (!gl::Program::load("vs_mesh.glsl", "fs_mesh_prepass.glsl", &prepassProgram, error)) return false;
    if (!gl::Program::load("vs_fullscreen.glsl", "fs_sky.glsl", &skyProgram, error)) return false;
    if (!gl::Program::load("vs_fullscreen.glsl", "fs_blit.glsl", &blitProgram, error)) return false;
    if (!gl::Program::load("vs_mesh.glsl", "fs_mesh_costly.glsl", &costlyProgram, error)) return false;
    if (!panelVao) {
        // Two triangles, position + normal, as GpuScene lays out vertices.
        const float v[] = {-1, -1, 0, 0, 0, 1, 1, -1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 1,
                           -1, -1, 0, 0, 0, 1, 1, 1,  0, 0, 0, 1, -1, 1, 0, 0, 0, 1};
        glGenVertexArrays(1, &panelVao);
        glGenBuffers(1, &panelVbo);
        glBindVertexArray(panelVao);
        glBindBuffer(GL_ARRAY_BUFFER, panelVbo);
        glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
    if (!legacySprites.init(error)) return false;
    if (!hud.init(error)) return false;
    if (!emptyVao) glGenVertexArrays(1, &emptyVao);
    return true;
}

cubeScene::~cubeScene() {
    if (panelVbo) glDeleteBuffers(1, &panelVbo);
    if (panelVao) glDeleteVertexArrays(1, &panelVao);
    if (emptyVao) glDeleteVertexArrays(1, &emptyVao);
}

void cubeScene::drawOverdrawPanels(const gl::Program& p, int layers, const glm::mat4& view, float fovY,
                                   float aspect) const {
    if (layers <= 0) return;
    const glm::mat4 camToWorld = glm::inverse(view);
    const GLint uModel = p.uniform("uModel"), uColor = p.uniform("uBaseColor");
    glBindVertexArray(panelVao);
    for (int i = 0; i < layers; ++i) {
        const float d = 40.0f - 20.0f * float(i) / float(std::max(1, layers - 1));
        const float halfH = d * std::tan(0.5f * fovY), halfW = halfH * aspect;
        glm::mat4 m = glm::translate(camToWorld, glm::vec3(0.0f, 0.3f * halfH, -d));
        m = glm::scale(m, glm::vec3(0.95f * halfW, 0.7f * halfH, 1.0f));
        glUniformMatrix4fv(uModel, 1, GL_FALSE, glm::value_ptr(m));
        if (uColor >= 0) glUniform4f(uColor, 0.3f + 0.05f * float(i % 8), 0.35f, 0.5f - 0.03f * float(i % 8), 1.0f);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    glBindVertexArray(0);
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
            s.overdrawLayers = 0;
        } else {
            s.inset = last;  // the previous view (mirror) is inset into the main view
        }
        last = views[i]->Render(*this, graph, s);
    }
    return last;
}

}  // namespace cube
