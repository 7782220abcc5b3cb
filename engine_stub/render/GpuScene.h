#pragma once
// The scene's meshes on the GPU: one vertex buffer, one index buffer, one VAO, and a draw range
// per mesh. Nodes under the "car" node follow the vehicle transform; everything else is static.
#include <vector>

#include <glm/glm.hpp>

#include "gl/Gl.h"
#include "scene/SceneData.h"

namespace cube {

/// One recorded draw: what the game side hands to the back end (no GL state in it).
struct MeshDraw {
    glm::mat4 model{1.0f};
    glm::vec4 baseColor{1.0f};
    GLsizei indexCount = 0;
    size_t indexOffset = 0;  ///< bytes into the index buffer
    GLint baseVertex = 0;
    glm::vec3 worldMin{0.0f}, worldMax{0.0f};  ///< for frustum culling and sorting
    bool alphaTested = false;
};

class GpuScene : gl::NonCopyable {
public:
    ~GpuScene();

    void upload(const SceneData& scene);
    /// Records a draw per (node, mesh). Descendants of `movingRoot` get `movingTransform` applied.
    void record(const SceneData& scene, int movingRoot, const glm::mat4& movingTransform,
                std::vector<MeshDraw>* out) const;
    /// Binds the VAO and issues the draws with the program's uModel / uBaseColor.
    void draw(const std::vector<MeshDraw>& draws, GLint uModel, GLint uBaseColor) const;
    GLuint vao() const { return vao_; }

private:
    struct Range {
        GLsizei indexCount;
        size_t indexOffset;
        GLint baseVertex;
    };
    GLuint vao_ = 0, vbo_ = 0, ibo_ = 0;
    std::vector<Range> ranges_;
    mutable std::vector<char> moving_;  ///< record() scratch: node is under the moving root
};

}  // namespace cube
