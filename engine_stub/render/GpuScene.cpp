#include "render/GpuScene.h"

#include <glm/gtc/type_ptr.hpp>

namespace cube {

GpuScene::~GpuScene() {
    gl::deleteVertexArray(vao_, vbo_, ibo_);
}

void GpuScene::upload(const SceneData& scene) {
    std::vector<SceneVertex> vertices;
    std::vector<uint32_t> indices;
    ranges_.clear();
    for (const SceneMesh& m : scene.meshes) {
        ranges_.push_back({GLsizei(m.indices.size()), indices.size() * sizeof(uint32_t),
                           GLint(vertices.size())});
        vertices.insert(vertices.end(), m.vertices.begin(), m.vertices.end());
        indices.insert(indices.end(), m.indices.begin(), m.indices.end());
    }
    if (!vao_) {
        glGenVertexArrays(1, &vao_);
        glGenBuffers(1, &vbo_);
        glGenBuffers(1, &ibo_);
    }
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(SceneVertex)), vertices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(SceneVertex),
                          reinterpret_cast<void*>(offsetof(SceneVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(SceneVertex),
                          reinterpret_cast<void*>(offsetof(SceneVertex, normal)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GpuScene::record(const SceneData& scene, int movingRoot, const glm::mat4& movingTransform,
                      std::vector<MeshDraw>* out) const {
    out->clear();
    // Nodes are in pre-order (a parent precedes its children), so "under the moving root" is one
    // pass: linear in the node count, however deep the hierarchy.
    moving_.assign(scene.nodes.size(), 0);
    for (size_t n = 0; n < scene.nodes.size(); ++n) {
        const SceneNode& node = scene.nodes[n];
        const int parent = node.parent;
        moving_[n] = movingRoot >= 0 && (int(n) == movingRoot ||
                                         (parent >= 0 && size_t(parent) < n && moving_[size_t(parent)]));
        const bool moving = moving_[n] != 0;
        const glm::mat4 model = moving ? movingTransform * node.world : node.world;
        for (int mi : node.meshes) {
            if (mi < 0 || size_t(mi) >= ranges_.size()) continue;
            const SceneMesh& mesh = scene.meshes[size_t(mi)];
            MeshDraw d;
            d.model = model;
            d.baseColor = mesh.baseColor;
            d.indexCount = ranges_[size_t(mi)].indexCount;
            d.indexOffset = ranges_[size_t(mi)].indexOffset;
            d.baseVertex = ranges_[size_t(mi)].baseVertex;
            // World box of the transformed local bounds (8 corners).
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (int c = 0; c < 8; ++c) {
                glm::vec3 p((c & 1) ? mesh.boundsMax.x : mesh.boundsMin.x,
                            (c & 2) ? mesh.boundsMax.y : mesh.boundsMin.y,
                            (c & 4) ? mesh.boundsMax.z : mesh.boundsMin.z);
                p = glm::vec3(model * glm::vec4(p, 1.0f));
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            d.worldMin = lo;
            d.worldMax = hi;
            d.alphaTested = mesh.baseColor.a < 1.0f;
            out->push_back(d);
        }
    }
}

void GpuScene::draw(const std::vector<MeshDraw>& draws, GLint uModel, GLint uBaseColor) const {
    if (draws.empty()) return;
    glBindVertexArray(vao_);
    for (const MeshDraw& d : draws) {
        glUniformMatrix4fv(uModel, 1, GL_FALSE, glm::value_ptr(d.model));
        if (uBaseColor >= 0) glUniform4fv(uBaseColor, 1, glm::value_ptr(d.baseColor));
        glDrawElementsBaseVertex(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<void*>(d.indexOffset), d.baseVertex);
    }
    glBindVertexArray(0);
}

}  // namespace cube
