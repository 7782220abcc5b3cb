#pragma once
// Draws the legacy smoke: CPU-aligned quads, depth-tested, no depth writes, straight alpha,
// one untextured-rotation atlas frame. The baseline the plugin replaces.
#include <string>
#include <vector>

#include "gl/Gl.h"
#include "gl/Program.h"
#include "render/SceneFog.h"
#include "scene/cubeParticleSystem.h"

namespace cube {

class LegacySpriteRenderer {
public:
    ~LegacySpriteRenderer();
    /// `defines`: "#define CUBE_FOG 1\n" in a fogged scene (shaders/common.glsl), else "".
    bool init(std::string* error, const std::string& defines = "");
    /// Draws `vertices` (triangles) with the view-projection matrix into the bound framebuffer,
    /// depth-tested without writes (LEQUAL, or GEQUAL on a reversed-Z buffer), fogged as the
    /// scene is (`fog`; off: the sprites as before).
    void draw(const std::vector<cubeParticleSystem::SpriteVertex>& vertices, const float* viewProj,
              const glm::vec3& tint, bool reversedZ, const SceneFog& fog = SceneFog{});

private:
    gl::Program program_;
    GLuint vao_ = 0, vbo_ = 0, atlas_ = 0;
    size_t capacity_ = 0;
};

}  // namespace cube
