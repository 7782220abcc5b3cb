#include "MegaRenderer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include <glm/gtc/matrix_inverse.hpp>

#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "ShaderLoader.h"
#include "base/ApiErrors.h"

namespace fx {
namespace {

// Texture units (all below GlStateGuard::kTextureUnits).
constexpr int kUnit0 = 0, kUnit1 = 1, kUnit2 = 2;

void plainState() {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

glm::vec2 frustumSlopes(const glm::mat4& proj) {
    const float sx = (1.0f + std::fabs(proj[2][0])) / std::fmax(std::fabs(proj[0][0]), 1e-6f);
    const float sy = (1.0f + std::fabs(proj[2][1])) / std::fmax(std::fabs(proj[1][1]), 1e-6f);
    return glm::vec2(sx, sy) * 1.02f;
}

const std::vector<ColorStop>& whiteRamp() {
    static const std::vector<ColorStop> kWhite{ColorStop{0.0f, glm::vec4(1.0f)}};
    return kWhite;
}

TargetDesc megaTarget(float scale, TargetFormat format) {
    TargetDesc d;
    d.scale = scale;
    d.format = format;
    d.linearFilter = false;  // every read is a texelFetch
    return d;
}

}  // namespace

/// The five programs and their uniform locations.
struct MegaRenderer::Programs {
    GLuint depth = 0, spheres = 0, blur = 0, shade = 0, composite = 0;
    GLint depthScene = -1, depthRatio = -1;
    GLint sView = -1, sProj = -1, sNear = -1, sFar = -1, sSlope = -1, sRamp = -1, sRampRow = -1, sMegaDepth = -1,
          sDensity = -1;
    struct Blur {
        GLint color = -1, density = -1, encoded = -1, direction = -1, taps = -1, sigma = -1, falloff = -1;
        GLint invView = -1, projTerms = -1, time = -1, noiseStrength = -1, noiseScale = -1, lit = -1;
        GLint toSun = -1, sunColor = -1, ambient = -1, scattering = -1, anisotropy = -1, absorption = -1;
    } b[2];  // [0] blur, [1] blur + shade
    GLint cCloud = -1, cCloudDepth = -1, cScene = -1, cSoft = -1;

    ~Programs() {
        for (GLuint p : {depth, spheres, blur, shade, composite}) {
            if (p) glDeleteProgram(p);
        }
    }
    bool ok() const { return depth && spheres && blur && shade && composite; }

    void build(const std::string& dir, std::vector<std::string>* errors) {
        auto make = [&](const char* vs, const char* fs, const char* defines) {
            std::string error;
            const GLuint p = buildProgram(dir, vs, fs, defines, &error);
            if (!p) errors->push_back(error);
            return p;
        };
        depth = make("vs_particles_fullscreen.glsl", "fs_mega_depth.glsl", "");
        spheres = make("vs_mega.glsl", "fs_mega_spheres.glsl", "");
        blur = make("vs_particles_fullscreen.glsl", "fs_mega_blur.glsl", "");
        shade = make("vs_particles_fullscreen.glsl", "fs_mega_blur.glsl", "#define FX_MEGA_SHADE 1\n");
        composite = make("vs_particles_fullscreen.glsl", "fs_mega_composite.glsl", "");
        if (depth) {
            depthScene = glGetUniformLocation(depth, "uSceneDepth");
            depthRatio = glGetUniformLocation(depth, "uRatio");
        }
        if (spheres) {
            sView = glGetUniformLocation(spheres, "uView");
            sProj = glGetUniformLocation(spheres, "uProj");
            sNear = glGetUniformLocation(spheres, "uNear");
            sFar = glGetUniformLocation(spheres, "uFar");
            sSlope = glGetUniformLocation(spheres, "uSlopeMax");
            sRamp = glGetUniformLocation(spheres, "uRamp");
            sRampRow = glGetUniformLocation(spheres, "uRampRow");
            sMegaDepth = glGetUniformLocation(spheres, "uMegaDepth");
            sDensity = glGetUniformLocation(spheres, "uDensity");
        }
        const GLuint blurs[2] = {blur, shade};
        for (int i = 0; i < 2; ++i) {
            const GLuint p = blurs[i];
            if (!p) continue;
            Blur& u = b[i];
            u.color = glGetUniformLocation(p, "uColor");
            u.density = glGetUniformLocation(p, "uDensity");
            u.encoded = glGetUniformLocation(p, "uEncodedDepth");
            u.direction = glGetUniformLocation(p, "uDirection");
            u.taps = glGetUniformLocation(p, "uTaps");
            u.sigma = glGetUniformLocation(p, "uSigma");
            u.falloff = glGetUniformLocation(p, "uDepthFalloff");
            u.invView = glGetUniformLocation(p, "uInvView");
            u.projTerms = glGetUniformLocation(p, "uProjTerms");
            u.time = glGetUniformLocation(p, "uTime");
            u.noiseStrength = glGetUniformLocation(p, "uNoiseStrength");
            u.noiseScale = glGetUniformLocation(p, "uNoiseScale");
            u.lit = glGetUniformLocation(p, "uLit");
            u.toSun = glGetUniformLocation(p, "uToSun");
            u.sunColor = glGetUniformLocation(p, "uSunColor");
            u.ambient = glGetUniformLocation(p, "uAmbient");
            u.scattering = glGetUniformLocation(p, "uScattering");
            u.anisotropy = glGetUniformLocation(p, "uAnisotropy");
            u.absorption = glGetUniformLocation(p, "uAbsorption");
        }
        if (composite) {
            cCloud = glGetUniformLocation(composite, "uCloud");
            cCloudDepth = glGetUniformLocation(composite, "uCloudDepth");
            cScene = glGetUniformLocation(composite, "uSceneDepth");
            cSoft = glGetUniformLocation(composite, "uSoftScale");
        }
    }
};

MegaRenderer::MegaRenderer(MegaRendererConfig config) : config_(std::move(config)) {}

MegaRenderer::~MegaRenderer() {
    if (state_ == State::Unloaded || !privateGlLoaded()) return;  // no GL was ever touched
    GlStateGuard guard;
    programs_.reset();
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (emptyVao_) glDeleteVertexArrays(1, &emptyVao_);
}

void MegaRenderer::log(LogLevel level, const std::string& message) const {
    if (config_.host) config_.host->log(level, message.c_str());
}

bool MegaRenderer::ensureLoaded() {
    if (state_ != State::Unloaded) return state_ == State::Ready;
    state_ = State::Failed;
    std::string error;
    if (!loadPrivateGlOrDiagnose(config_.host, &loadDiagnostics_, &error)) {
        log(LogLevel::Error, "fx: mega-particles disabled: " + error);
        return false;
    }
    GlStateGuard guard;
    glActiveTexture(GL_TEXTURE0);
    programs_ = std::make_unique<Programs>();
    std::vector<std::string> errors;
    programs_->build(config_.shaderDir, &errors);
    // The blur and shade programs share fs_mega_blur.glsl, and four programs share
    // vs_particles_fullscreen.glsl: one cause is told once.
    ShaderErrorLog unique;
    for (const std::string& e : errors) unique.add(e);
    if (!unique.empty()) {
        log(LogLevel::Error, "fx: mega-particle shader build failed:\n" + unique.text());
        addShaderDiagnostics(unique.text(), &loadDiagnostics_);
    }
    if (!programs_->ok()) return false;
    glGenFramebuffers(1, &fbo_);
    glGenVertexArrays(1, &emptyVao_);
    hostDepth_.create();
    stream_.create();
    ramp_.upload();
    state_ = State::Ready;
    return true;
}

std::function<void()> MegaRenderer::rebuildShaders(ShaderErrorLog* errors) {
    // Built whether or not mega is in use, so a broken mega file is reported at the edit and not
    // later, when a reaction or the override first asks for mega; made live only when loaded.
    auto next = std::make_shared<std::unique_ptr<Programs>>(std::make_unique<Programs>());
    std::vector<std::string> failed;
    (*next)->build(config_.shaderDir, &failed);
    for (const std::string& e : failed) errors->add(e);
    if (!failed.empty() || state_ != State::Ready) return {};  // deleted here, with `next`
    // After the swap `next` holds the old programs: deleted when the caller drops the function.
    return [this, next]() { programs_.swap(*next); };
}

bool MegaRenderer::prepare(Diagnostics* out) {
    const bool ok = ensureLoaded();
    if (out) out->insert(out->end(), loadDiagnostics_.begin(), loadDiagnostics_.end());
    return ok;
}

std::shared_ptr<MegaRenderer::ViewRecord> MegaRenderer::acquireRecord() {
    for (const std::shared_ptr<ViewRecord>& r : records_) {
        if (r.use_count() == 1) return r;
    }
    records_.push_back(std::make_shared<ViewRecord>());
    return records_.back();
}

bool MegaRenderer::sizesAgree(PassContext& ctx, const ViewInfo& view, Target a, Target b) {
    const int w = ctx.width(a), h = ctx.height(a);
    if (w == view.width && h == view.height && ctx.width(b) == w && ctx.height(b) == h) return true;
    if (config_.errors) {
        config_.errors->refuse(ErrorCode::SizeMismatch, "mega pass",
                               "the scene targets are " + std::to_string(w) + "x" + std::to_string(h) + " and " +
                                   std::to_string(ctx.width(b)) + "x" + std::to_string(ctx.height(b)) +
                                   ", ViewInfo " + std::to_string(view.width) + "x" +
                                   std::to_string(view.height) + "; they must be equal; nothing drawn");
    }
    return false;
}

int MegaRenderer::declarePasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                                int batchCount, const RenderOptions& options, const LightState& light) {
    if (state_ == State::Failed) return 0;
    std::shared_ptr<ViewRecord> record = acquireRecord();
    builder_.build(view, batches, batchCount, options.techniqueOverride, techniqueBit(Technique::Mega),
                   &record->list);
    const int drawn = record->list.particleCount();
    if (drawn == 0) return 0;  // no Mega batch visible: nothing declared, nothing loaded
    if (!ensureLoaded()) return 0;

    record->view = view;
    record->view.name = "";  // the host's string is not ours to keep
    const ParticleBatch& first = batches[record->list.batches.front().rampRow];
    record->mega = first.desc->mega;
    record->lighting = first.desc->lighting;
    record->light = light;
    record->softScale = record->list.batches.front().softScale;
    record->time = first.time;
    record->rect = QuarterResPath::screenRect(view, record->list.instances.data(), drawn);
    if (!record->rect.whole && record->rect.x1 <= record->rect.x0) return 0;  // nothing in front

    rampInputs_.clear();
    for (int b = 0; b < batchCount; ++b) {
        rampInputs_.push_back(batches[b].desc ? &batches[b].desc->particle.colorRamp : &whiteRamp());
    }
    ramp_.setRows(rampInputs_);

    const float scale = std::clamp(record->mega.resolution, 0.25f, 1.0f);
    const Target sceneColor = frame.sceneColor();
    const Target sceneDepth = frame.sceneDepth();
    const Target megaDepth = frame.createTarget("mega_depth", megaTarget(scale, TargetFormat::R32F));
    const Target color = frame.createTarget("mega_color", megaTarget(scale, TargetFormat::RGBA16F));
    const Target density = frame.createTarget("mega_density", megaTarget(scale, TargetFormat::RGBA16F));
    const Target blurColor = frame.createTarget("mega_blur_color", megaTarget(scale, TargetFormat::RGBA16F));
    const Target blurDensity = frame.createTarget("mega_blur_density", megaTarget(scale, TargetFormat::RGBA16F));
    const Target cloud = frame.createTarget("mega_cloud", megaTarget(scale, TargetFormat::RGBA16F));
    const Target cloudDepth = frame.createTarget("mega_cloud_depth", megaTarget(scale, TargetFormat::R32F));

    frame.addPass(kDepthPass, {sceneDepth}, {megaDepth}, [this, record, sceneDepth, megaDepth](PassContext& ctx) {
        GlStateGuard guard;
        runDepth(ctx, *record, sceneDepth, megaDepth);
    });
    frame.addPass(kSpheresPass, {megaDepth}, {color, density},
                  [this, record, megaDepth, color, density](PassContext& ctx) {
                      GlStateGuard guard;
                      runSpheres(ctx, *record, megaDepth, color, density);
                  });
    frame.addPass(kBlurHPass, {color, density}, {blurColor, blurDensity},
                  [this, record, color, density, blurColor, blurDensity](PassContext& ctx) {
                      GlStateGuard guard;
                      runBlur(ctx, *record, color, density, blurColor, blurDensity, false);
                  });
    frame.addPass(kBlurVPass, {blurColor, blurDensity}, {cloud, cloudDepth},
                  [this, record, blurColor, blurDensity, cloud, cloudDepth](PassContext& ctx) {
                      GlStateGuard guard;
                      runBlur(ctx, *record, blurColor, blurDensity, cloud, cloudDepth, true);
                  });
    frame.addPass(kCompositePass, {cloud, cloudDepth, sceneDepth}, {sceneColor},
                  [this, record, cloud, cloudDepth, sceneDepth, sceneColor](PassContext& ctx) {
                      GlStateGuard guard;
                      runComposite(ctx, *record, cloud, cloudDepth, sceneDepth, sceneColor);
                  });
    return drawn;
}

int MegaRenderer::blurBorder(const ViewRecord& record) {
    const float sigma = 0.5f * std::clamp(record.mega.blurRadius, 0.0f, 32.0f);
    return int(std::ceil(3.0f * sigma)) + 2;
}

void MegaRenderer::scissorTo(const ViewRecord& record, float scale, int border, int w, int h) {
    const QuarterResPath::ScreenRect& rect = record.rect;
    if (rect.whole) {
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    const int x0 = std::max(0, int(std::floor(float(rect.x0) * scale)) - border);
    const int y0 = std::max(0, int(std::floor(float(rect.y0) * scale)) - border);
    const int x1 = std::min(w, int(std::ceil(float(rect.x1) * scale)) + border);
    const int y1 = std::min(h, int(std::ceil(float(rect.y1) * scale)) + border);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

void MegaRenderer::beginOwnTarget(PassContext& ctx, Target a, Target b, const float clearA[4]) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, ctx.texture(a, 0).name, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, ctx.texture(b, 0).name, 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    glViewport(0, 0, ctx.width(a), ctx.height(a));
    plainState();
    glDisable(GL_SCISSOR_TEST);  // every texel a later tap may read starts defined
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, clearA);
    glClearBufferfv(GL_COLOR, 1, zero);
}

void MegaRenderer::endOwnTarget() {
    // The host's textures are only lent for the pass: leave none attached.
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
}

void MegaRenderer::runDepth(PassContext& ctx, const ViewRecord& r, Target sceneDepth, Target megaDepth) {
    if (ctx.width(sceneDepth) != r.view.width || ctx.height(sceneDepth) != r.view.height) {
        sizesAgree(ctx, r.view, sceneDepth, sceneDepth);
        return;
    }
    ctx.bindForDraw(megaDepth);
    plainState();
    const int w = ctx.width(megaDepth), h = ctx.height(megaDepth);
    glDisable(GL_SCISSOR_TEST);
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // 0 = nothing drawn: no sphere is hidden
    glClearBufferfv(GL_COLOR, 0, zero);
    scissorTo(r, float(w) / float(r.view.width), blurBorder(r), w, h);
    glUseProgram(programs_->depth);
    hostDepth_.bindTexture(kUnit0, ctx.texture(sceneDepth, 0).name);
    glUniform1i(programs_->depthScene, kUnit0);
    glUniform2f(programs_->depthRatio, float(r.view.width) / float(std::max(w, 1)),
                float(r.view.height) / float(std::max(h, 1)));
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void MegaRenderer::runSpheres(PassContext& ctx, const ViewRecord& r, Target megaDepth, Target color,
                              Target density) {
    const Programs& p = *programs_;
    const GLfloat noSphere[4] = {0.0f, 0.0f, 0.0f, -65504.0f};  // alpha: -(nearest depth); none
    beginOwnTarget(ctx, color, density, noSphere);
    const int w = ctx.width(color), h = ctx.height(color);
    scissorTo(r, float(w) / float(r.view.width), blurBorder(r), w, h);
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

void MegaRenderer::runBlur(PassContext& ctx, const ViewRecord& r, Target inColor, Target inDensity,
                           Target outColor, Target outSecond, bool shade) {
    const Programs::Blur& u = programs_->b[shade ? 1 : 0];
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    beginOwnTarget(ctx, outColor, outSecond, zero);
    const int w = ctx.width(outColor), h = ctx.height(outColor);
    scissorTo(r, float(w) / float(r.view.width), blurBorder(r) - 1, w, h);
    glUseProgram(shade ? programs_->shade : programs_->blur);
    bindTextureUnit(kUnit0, ctx.texture(inColor, 0).name);
    bindTextureUnit(kUnit1, ctx.texture(inDensity, 0).name);
    glUniform1i(u.color, kUnit0);
    glUniform1i(u.density, kUnit1);
    glUniform1i(u.encoded, shade ? 0 : 1);
    glUniform2i(u.direction, shade ? 0 : 1, shade ? 1 : 0);
    const float sigma = 0.5f * std::clamp(r.mega.blurRadius, 0.0f, 32.0f);
    glUniform1i(u.taps, int(std::ceil(3.0f * sigma)));
    glUniform1f(u.sigma, std::max(sigma, 1e-3f));
    glUniform1f(u.falloff, kDepthFalloff);
    if (shade) {
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
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    endOwnTarget();
}

void MegaRenderer::runComposite(PassContext& ctx, const ViewRecord& r, Target cloud, Target cloudDepth,
                                Target sceneDepth, Target sceneColor) {
    if (!sizesAgree(ctx, r.view, sceneColor, sceneDepth)) return;
    ctx.bindForDraw(sceneColor);
    plainState();
    const int w = ctx.width(sceneColor), h = ctx.height(sceneColor);
    const float scale = float(ctx.width(cloud)) / float(std::max(w, 1));
    scissorTo(r, 1.0f, int(std::ceil(float(blurBorder(r)) / std::max(scale, 0.25f))), w, h);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(programs_->composite);
    bindTextureUnit(kUnit0, ctx.texture(cloud, 0).name);
    bindTextureUnit(kUnit1, ctx.texture(cloudDepth, 0).name);
    hostDepth_.bindTexture(kUnit2, ctx.texture(sceneDepth, 0).name);
    glUniform1i(programs_->cCloud, kUnit0);
    glUniform1i(programs_->cCloudDepth, kUnit1);
    glUniform1i(programs_->cScene, kUnit2);
    glUniform1f(programs_->cSoft, r.softScale);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace fx
