#include "render/SceneRenderer.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "render/RenderState.h"

namespace cube {
namespace {

void setCamera(const gl::Program& p, const CameraMatrices& cam) {
    glUseProgram(p.id());
    glUniformMatrix4fv(p.uniform("uView"), 1, GL_FALSE, glm::value_ptr(cam.view));
    glUniformMatrix4fv(p.uniform("uProj"), 1, GL_FALSE, glm::value_ptr(cam.proj));
}

// The scene light of shaders/common.glsl (absent uniforms are -1: glUniform ignores them).
void setSunUniforms(const gl::Program& p, const SunLight& sun) {
    glUniform3fv(p.uniform("uToSun"), 1, glm::value_ptr(sun.toSun));
    glUniform3fv(p.uniform("uSunColor"), 1, glm::value_ptr(sun.color));
    glUniform3fv(p.uniform("uSkyAmbient"), 1, glm::value_ptr(sun.ambientSky));
    glUniform3fv(p.uniform("uGroundAmbient"), 1, glm::value_ptr(sun.ambientGround));
}

// The fog of shaders/common.glsl (mode 0: off, the picture as without fog, bit for bit).
void setFogUniforms(const gl::Program& p, const SceneFog& fog) {
    glUniform1i(p.uniform("uFogMode"), static_cast<int>(fog.mode));
    glUniform3fv(p.uniform("uFogColor"), 1, glm::value_ptr(fog.color));
    glUniform3f(p.uniform("uFogParams"), fog.start, fog.end, fog.density);
}

// The texture unit of the smoke's opacity map in the lit scene programs.
constexpr int kSmokeUnit = 4;

// The depth test that keeps the nearer surface: LESS/LEQUAL, or GREATER/GEQUAL reversed.
GLenum nearerTest(bool reversedZ, bool orEqual) {
    if (reversedZ) return orEqual ? GL_GEQUAL : GL_GREATER;
    return orEqual ? GL_LEQUAL : GL_LESS;
}

}  // namespace

bool SceneRenderer::init(const SceneData& data, std::string* error, bool reversedZ) {
    // Clip control is context state: set once here, for every pass of the scene.
    reversedZ_ = reversedZ && gl::hasClipControl() && gl::setClipDepthZeroToOne(true);
    if (!reversedZ_ && gl::hasClipControl()) gl::setClipDepthZeroToOne(false);
    gpu_.upload(data);
    // Fog is built into the programs of a fogged scene only (shaders/common.glsl, CUBE_FOG).
    const std::string fog = fog_.mode != SceneFog::Mode::Off ? "#define CUBE_FOG 1\n" : "";
    if (!gl::Program::load("vs_mesh.glsl", "fs_mesh.glsl", &meshProgram_, error, fog)) return false;
    if (!gl::Program::load("vs_mesh.glsl", "fs_mesh_prepass.glsl", &prepassProgram_, error)) return false;
    if (!gl::Program::load("vs_fullscreen.glsl", "fs_sky.glsl", &skyProgram_, error, fog)) return false;
    if (!gl::Program::load("vs_fullscreen.glsl", "fs_blit.glsl", &blitProgram_, error)) return false;
    if (!gl::Program::load("vs_mesh.glsl", "fs_mesh_costly.glsl", &costlyProgram_, error, fog)) return false;
    if (!panelVao_) {
        // Two triangles, position + normal, as GpuScene lays out vertices (the camera quads).
        const float v[] = {-1, -1, 0, 0, 0, 1, 1, -1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 1,
                           -1, -1, 0, 0, 0, 1, 1, 1,  0, 0, 0, 1, -1, 1, 0, 0, 0, 1};
        glGenVertexArrays(1, &panelVao_);
        glGenBuffers(1, &panelVbo_);
        glBindVertexArray(panelVao_);
        glBindBuffer(GL_ARRAY_BUFFER, panelVbo_);
        glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
    if (!legacySprites_.init(error, fog)) return false;
    if (!hud_.init(error)) return false;
    if (!emptyVao_) glGenVertexArrays(1, &emptyVao_);
    return true;
}

void SceneRenderer::useLitProgram(const gl::Program& p, const CameraMatrices& cam) const {
    setCamera(p, cam);
    setSunUniforms(p, sun_);
    setFogUniforms(p, fog_);
    // The smoke's shadow on texture unit kSmokeUnit (unbound again by the opaque pass).
    glActiveTexture(GL_TEXTURE0 + kSmokeUnit);
    glBindTexture(GL_TEXTURE_2D, smokeTexture_);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(p.uniform("uSmokeOpacity"), kSmokeUnit);
    glUniformMatrix4fv(p.uniform("uWorldToSmoke"), 1, GL_FALSE, glm::value_ptr(worldToSmoke_));
    glUniform1f(p.uniform("uSmokeAbsorption"), smokeAbsorption_);
}

SceneRenderer::~SceneRenderer() {
    if (panelVbo_) glDeleteBuffers(1, &panelVbo_);
    if (panelVao_) glDeleteVertexArrays(1, &panelVao_);
    if (emptyVao_) glDeleteVertexArrays(1, &emptyVao_);
}

void SceneRenderer::drawCameraQuads(const gl::Program& p, const CameraQuads& quads,
                                    const CameraMatrices& cam) const {
    if (quads.empty()) return;
    const glm::mat4 camToWorld = glm::inverse(cam.view);
    const GLint uModel = p.uniform("uModel"), uColor = p.uniform("uBaseColor");
    glBindVertexArray(panelVao_);
    for (const CameraQuad& q : quads.quads) {
        const float halfH = q.distance * std::tan(0.5f * cam.fovY), halfW = halfH * cam.aspect;
        glm::mat4 m = glm::translate(camToWorld, glm::vec3(0.0f, q.centerY * halfH, -q.distance));
        m = glm::scale(m, glm::vec3(q.halfWidth * halfW, q.halfHeight * halfH, 1.0f));
        glUniformMatrix4fv(uModel, 1, GL_FALSE, glm::value_ptr(m));
        if (uColor >= 0) glUniform4f(uColor, q.color.r, q.color.g, q.color.b, q.color.a);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    glBindVertexArray(0);
}

void SceneRenderer::depthPrepass(const std::vector<MeshDraw>& opaque, const std::vector<MeshDraw>& alphaTested,
                                 const CameraMatrices& cam, const CameraQuads& quads) const {
    ScopedPassState state({true, nearerTest(reversedZ_, false), true, true});
    setCamera(prepassProgram_, cam);
    const GLint uModel = prepassProgram_.uniform("uModel");
    gpu_.draw(opaque, uModel, -1);
    gpu_.draw(alphaTested, uModel, -1);
    drawCameraQuads(prepassProgram_, quads, cam);
}

void SceneRenderer::opaque(const std::vector<MeshDraw>& draws, const CameraMatrices& cam, bool equal,
                           const CameraQuads& quads) const {
    // LEQUAL, not LESS: where two surfaces meet at exactly the same depth the last drawn wins,
    // which is what EQUAL on the prepass z-buffer does too. So the two paths give the same
    // pixel even at coplanar seams.
    ScopedPassState state({true, equal ? GLenum(GL_EQUAL) : nearerTest(reversedZ_, true), !equal, true});
    useLitProgram(meshProgram_, cam);
    gpu_.draw(draws, meshProgram_.uniform("uModel"), meshProgram_.uniform("uBaseColor"));
    if (!quads.empty()) {
        useLitProgram(costlyProgram_, cam);
        glUniform1i(costlyProgram_.uniform("uCost"), quads.cost);
        drawCameraQuads(costlyProgram_, quads, cam);
    }
    glActiveTexture(GL_TEXTURE0 + kSmokeUnit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
}

void SceneRenderer::alphaTested(const std::vector<MeshDraw>& draws, const CameraMatrices& cam, bool equal) const {
    // Culling as in the prepass, or EQUAL would differ.
    ScopedPassState state({true, equal ? GLenum(GL_EQUAL) : nearerTest(reversedZ_, true), !equal, true});
    useLitProgram(meshProgram_, cam);
    gpu_.draw(draws, meshProgram_.uniform("uModel"), meshProgram_.uniform("uBaseColor"));
}

void SceneRenderer::sky(const CameraMatrices& cam) const {
    ScopedPassState state({true, nearerTest(reversedZ_, true), false, false});
    glUseProgram(skyProgram_.id());
    setSunUniforms(skyProgram_, sun_);
    setFogUniforms(skyProgram_, fog_);
    const glm::mat4 inv = glm::inverse(cam.proj * glm::mat4(glm::mat3(cam.view)));
    glUniformMatrix4fv(skyProgram_.uniform("uInvViewProj"), 1, GL_FALSE, glm::value_ptr(inv));
    glUniform1f(skyProgram_.uniform("uDepth"), reversedZ_ ? 0.0f : 1.0f);  // the far plane
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void SceneRenderer::sprites(const std::vector<cubeParticleSystem::SpriteVertex>& vertices,
                            const glm::mat4& viewProj, const glm::vec3& tint) {
    legacySprites_.draw(vertices, glm::value_ptr(viewProj), tint, reversedZ_, fog_);
}

void SceneRenderer::inset(uint32_t texture, int iw, int ih, bool flipX, int w, int h) const {
    const int x = (w - iw) / 2, y = h - ih - 12;
    glViewport(x - 3, y - 3, iw + 6, ih + 6);  // frame
    glEnable(GL_SCISSOR_TEST);
    glScissor(x - 3, y - 3, iw + 6, ih + 6);
    const GLfloat frame[4] = {0.05f, 0.05f, 0.05f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, frame);
    glDisable(GL_SCISSOR_TEST);
    glViewport(x, y, iw, ih);
    glUseProgram(blitProgram_.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(blitProgram_.uniform("uSource"), 0);
    glUniform1f(blitProgram_.uniform("uFlipX"), flipX ? 1.0f : 0.0f);
    glUniform1f(blitProgram_.uniform("uDepth"), 0.0f);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
    glViewport(0, 0, w, h);
}

void SceneRenderer::text(const std::string& text, int w, int h) {
    hud_.setText(text);
    hud_.draw(w, h);
}

}  // namespace cube
