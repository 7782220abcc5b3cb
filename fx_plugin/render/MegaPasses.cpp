#include "MegaPasses.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <glm/gtc/matrix_inverse.hpp>

#include "render/PrivateGl.h"

#include "ViewFrustum.h"

namespace fx {
namespace {

// Texture units (all below GlStateGuard::kTextureUnits).
constexpr int kUnit0 = 0, kUnit1 = 1, kUnit2 = 2;

}  // namespace

void MegaPasses::create(std::unique_ptr<MegaPrograms> programs) {
    programs_ = std::move(programs);
    glGenFramebuffers(1, &fbo_);
    glGenVertexArrays(1, &emptyVao_);
    hostDepth_.create();
    stream_.create();
    ramp_.upload();
}

void MegaPasses::releaseGl() {
    programs_.reset();
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (emptyVao_) glDeleteVertexArrays(1, &emptyVao_);
    fbo_ = emptyVao_ = 0;
}

void MegaPasses::drawFullscreen() {
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

int MegaPasses::blurBorder(const MegaCloud& record) {
    const float sigma = 0.5f * std::clamp(record.mega.blurRadius, 0.0f, 32.0f);
    return int(std::ceil(3.0f * sigma)) + 2;
}

void MegaPasses::beginOwnTarget(PassContext& ctx, Target a, Target b, const float clearA[4]) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, ctx.texture(a, 0).name, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, ctx.texture(b, 0).name, 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    glViewport(0, 0, ctx.width(a), ctx.height(a));
    plainDrawState();
    glDisable(GL_SCISSOR_TEST);  // every texel a later tap may read starts defined
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, clearA);
    glClearBufferfv(GL_COLOR, 1, zero);
}

void MegaPasses::endOwnTarget() {
    // The host's textures are only lent for the pass: leave none attached.
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
}

void MegaPasses::runDepth(PassContext& ctx, const MegaCloud& r, Target sceneDepth, Target megaDepth) {
    if (!targetsFitView(ctx, r.view, sceneDepth, sceneDepth, sizeMismatch_)) return;
    ctx.bindForDraw(megaDepth);
    plainDrawState();
    const int w = ctx.width(megaDepth), h = ctx.height(megaDepth);
    glDisable(GL_SCISSOR_TEST);
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // 0 = nothing drawn: no sphere is hidden
    glClearBufferfv(GL_COLOR, 0, zero);
    scissorTo(r.rect, float(w) / float(r.view.width), blurBorder(r), w, h);
    glUseProgram(programs_->depth);
    const TextureRef depthRef = ctx.texture(sceneDepth, 0);
    hostDepth_.bindTexture(kUnit0, depthRef.name);
    glUniform1i(programs_->depthScene, kUnit0);
    setSceneDepthDecode(programs_->depthDecode, r.depthDecode.placedFor(depthRef, r.view, false));
    sceneDepthBarrier(r.depthDecode);
    glUniform2f(programs_->depthRatio, float(r.view.width) / float(std::max(w, 1)),
                float(r.view.height) / float(std::max(h, 1)));
    drawFullscreen();
}

void MegaPasses::runSpheres(PassContext& ctx, const MegaCloud& r, Target megaDepth, Target color,
                            Target density) {
    const MegaPrograms& p = *programs_;
    const GLfloat noSphere[4] = {0.0f, 0.0f, 0.0f, -65504.0f};  // alpha: -(nearest depth); none
    beginOwnTarget(ctx, color, density, noSphere);
    const int w = ctx.width(color), h = ctx.height(color);
    scissorTo(r.rect, float(w) / float(r.view.width), blurBorder(r), w, h);
    // Order-independent: sums of colour and density, the maximum of -depth (the nearest front).
    glEnable(GL_BLEND);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_MAX);
    glBlendFunc(GL_ONE, GL_ONE);
    glActiveTexture(GL_TEXTURE0);
    ramp_.upload();
    stream_.upload(r.list.instances.data(), r.list.particleCount());
    bindTextureUnit(kUnit0, ramp_.texture());
    bindTextureUnit(kUnit1, ctx.texture(megaDepth, 0).name);
    glUseProgram(p.spheres);
    const glm::vec2 slopes = frustumSlopes(r.view.proj);
    glUniformMatrix4fv(p.sView, 1, GL_FALSE, &r.view.view[0][0]);
    glUniformMatrix4fv(p.sProj, 1, GL_FALSE, &r.view.proj[0][0]);
    glUniform1f(p.sNear, r.view.nearPlane);
    glUniform1f(p.sFar, r.view.farPlane);
    glUniform2f(p.sSlope, slopes.x, slopes.y);
    glUniform1i(p.sRamp, kUnit0);
    glUniform1i(p.sMegaDepth, kUnit1);
    glUniform1f(p.sDensity, kDensity);
    for (const DrawBatch& batch : r.list.batches) {
        glUniform1f(p.sRampRow, ramp_.rowV(batch.rampRow));
        stream_.bindRange(batch.first);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, batch.count);
    }
    endOwnTarget();
}

void MegaPasses::runBlur(PassContext& ctx, const MegaCloud& r, Target inColor, Target inDensity,
                         Target outColor, Target outSecond, bool shade) {
    const MegaPrograms::Blur& u = programs_->b[shade ? 1 : 0];
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    beginOwnTarget(ctx, outColor, outSecond, zero);
    const int w = ctx.width(outColor), h = ctx.height(outColor);
    scissorTo(r.rect, float(w) / float(r.view.width), blurBorder(r) - 1, w, h);
    glUseProgram(shade ? programs_->shade : programs_->blur);
    bindTextureUnit(kUnit0, ctx.texture(inColor, 0).name);
    bindTextureUnit(kUnit1, ctx.texture(inDensity, 0).name);
    glUniform1i(u.color, kUnit0);
    glUniform1i(u.density, kUnit1);
    glUniform1i(u.encoded, shade ? 0 : 1);
    glUniform2i(u.direction, shade ? 0 : 1, shade ? 1 : 0);
    // Taps out to 3 sigma each side, sigma = blur_radius / 2 texels (at most 16: 48 taps); their
    // Gaussian weights once here (fs_mega_blur.glsl's uTapWeight).
    const float sigma = 0.5f * std::clamp(r.mega.blurRadius, 0.0f, 32.0f);
    const int taps = int(std::ceil(3.0f * sigma));
    const float inv2s2 = 0.5f / std::max(sigma * sigma, 1e-6f);
    std::array<GLfloat, 49> weights{};
    for (int i = 0; i <= taps; ++i) weights[size_t(i)] = std::exp(-float(i * i) * inv2s2);
    glUniform1i(u.taps, taps);
    glUniform1fv(u.tapWeights, taps + 1, weights.data());
    glUniform1f(u.falloff, kDepthFalloff);
    if (shade) {
        setFogUniforms(programs_->shadeFog, r.view.fog);
        const glm::mat4 invView = glm::inverse(r.view.view);
        glUniformMatrix4fv(u.invView, 1, GL_FALSE, &invView[0][0]);
        glUniform4f(u.projTerms, r.view.proj[0][0], r.view.proj[1][1], r.view.proj[2][0], r.view.proj[2][1]);
        glUniform1f(u.time, r.time);
        glUniform1f(u.noiseStrength, r.mega.noiseStrength);
        glUniform1f(u.noiseScale, std::max(r.mega.noiseScale, 1e-3f));
        const bool lit = r.light.on && r.lighting.lit(BlendMode::Alpha);
        glUniform1i(u.lit, lit ? 1 : 0);
        const glm::vec3 toSun = glm::normalize(glm::mat3(r.view.view) * r.light.toSun);
        glUniform3f(u.toSun, toSun.x, toSun.y, toSun.z);
        glUniform3f(u.sunColor, r.light.sunColor.x, r.light.sunColor.y, r.light.sunColor.z);
        const glm::vec3 ambient = r.light.ambient * r.lighting.ambient;
        glUniform3f(u.ambient, ambient.x, ambient.y, ambient.z);
        glUniform1f(u.scattering, r.lighting.scattering);
        glUniform1f(u.anisotropy, r.lighting.anisotropy);
        glUniform1f(u.absorption, r.lighting.absorption);
    }
    drawFullscreen();
    endOwnTarget();
}

void MegaPasses::runComposite(PassContext& ctx, const MegaCloud& r, Target cloud, Target cloudDepth,
                              Target sceneDepth, Target sceneColor) {
    if (!targetsFitView(ctx, r.view, sceneColor, sceneDepth, sizeMismatch_)) return;
    ctx.bindForDraw(sceneColor);
    const HostClip clip = HostClip::current();
    plainDrawState();
    const float scale = float(ctx.width(cloud)) / float(std::max(r.view.width, 1));
    scissorToView(r.rect, int(std::ceil(float(blurBorder(r)) / std::max(scale, 0.25f))), r.view, clip);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(programs_->composite);
    bindTextureUnit(kUnit0, ctx.texture(cloud, 0).name);
    hostDepth_.bindTexture(kUnit1, ctx.texture(cloudDepth, 0).name);  // gathered: clamped to its edge
    const TextureRef depthRef = ctx.texture(sceneDepth, 0);
    hostDepth_.bindTexture(kUnit2, depthRef.name);
    glUniform1i(programs_->cCloud, kUnit0);
    glUniform1i(programs_->cCloudDepth, kUnit1);
    glUniform1i(programs_->cScene, kUnit2);
    const SceneDepthDecode placed = r.depthDecode.placedFor(depthRef, r.view, true);  // into sceneColor
    setSceneDepthDecode(programs_->cDecode, placed);
    sceneDepthBarrier(r.depthDecode);
    glUniform1f(programs_->cSoft, r.softScale);
    // The footprint's line in gl_FragCoord (fs_mega_composite.glsl), worked out once here.
    const glm::vec2 lowSize(float(ctx.width(cloud)), float(ctx.height(cloud)));
    const glm::vec2 footprintScale = lowSize / glm::vec2(float(r.view.width), float(r.view.height));
    const glm::vec2 origin = -glm::vec2(placed.drawOrigin) * footprintScale - 0.5f;
    glUniform4f(programs_->cLowMap, footprintScale.x, footprintScale.y, origin.x, origin.y);
    glUniform2f(programs_->cInvLow, 1.0f / lowSize.x, 1.0f / lowSize.y);
    glUniform2i(programs_->cLowLast, ctx.width(cloud) - 1, ctx.height(cloud) - 1);
    drawFullscreen();
}

}  // namespace fx
