#include "render/LegacySpriteRenderer.h"

#include "gl/Image.h"
#include "gl/Paths.h"

namespace cube {

LegacySpriteRenderer::~LegacySpriteRenderer() {
    if (atlas_) glDeleteTextures(1, &atlas_);
    gl::deleteVertexArray(vao_, vbo_);
}

bool LegacySpriteRenderer::init(std::string* error, const std::string& defines) {
    if (!gl::Program::load("vs_legacy_sprite.glsl", "fs_legacy_sprite.glsl", &program_, error, defines)) return false;
    ImageRGBA8 atlas;
    if (!readPng(paths::data() + "/smoke_atlas.png", &atlas, error)) return false;
    // stb_image reads rows top-down; GL's t = 0 is the first row uploaded, which is fine for a
    // symmetric puff.
    glGenTextures(1, &atlas_);
    glBindTexture(GL_TEXTURE_2D, atlas_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, atlas.width, atlas.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 atlas.pixels.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);

    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    using V = cubeParticleSystem::SpriteVertex;
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(V), reinterpret_cast<void*>(offsetof(V, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(V), reinterpret_cast<void*>(offsetof(V, uv)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(V), reinterpret_cast<void*>(offsetof(V, alpha)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void LegacySpriteRenderer::draw(const std::vector<cubeParticleSystem::SpriteVertex>& vertices,
                                const float* viewProj, const glm::vec3& tint, bool reversedZ,
                                const SceneFog& fog) {
    if (vertices.empty() || !program_.valid()) return;
    using V = cubeParticleSystem::SpriteVertex;
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    const size_t bytes = vertices.size() * sizeof(V);
    if (bytes > capacity_) {
        capacity_ = bytes * 2;
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacity_), nullptr, GL_STREAM_DRAW);
    }
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), vertices.data());
    glUseProgram(program_.id());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, viewProj);
    glUniform3f(program_.uniform("uTint"), tint.x, tint.y, tint.z);
    glUniform1i(program_.uniform("uAtlas"), 0);
    glUniform1i(program_.uniform("uFogMode"), static_cast<int>(fog.mode));
    glUniform3f(program_.uniform("uFogColor"), fog.color.x, fog.color.y, fog.color.z);
    glUniform3f(program_.uniform("uFogParams"), fog.start, fog.end, fog.density);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, atlas_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversedZ ? GL_GEQUAL : GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
}

}  // namespace cube
