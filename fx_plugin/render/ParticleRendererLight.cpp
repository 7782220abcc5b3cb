// ParticleRenderer's lit smoke (Plugin::setSceneLight, API 1.2): the opacity map's pass and the
// FX_LIT uniforms. The rest of the renderer is in ParticleRenderer.cpp.
#include <vector>

#include "ParticleRenderer.h"
#include "render/PrivateGl.h"

#include "GlStateGuard.h"

namespace fx {

SmokeShadow ParticleRenderer::declareShadowPasses(const ViewInfo& view, FrameBuilder& frame,
                                                  const ParticleBatch* batches, int batchCount) {
    pendingShadow_ = SmokeShadow{};
    if (state_ == State::Failed || !light_.on) return SmokeShadow{};
    setRampRows(batches, batchCount);
    pendingShadow_ = declareOpacityPass(view, frame, batches, batchCount);
    return pendingShadow_;
}

SmokeShadow ParticleRenderer::declareOpacityPass(const ViewInfo& view, FrameBuilder& frame,
                                                 const ParticleBatch* batches, int batchCount) {
    // Nothing is loaded for a frame without shadow casters.
    const int size = SmokeOpacityMap::sizeFor(view.width, view.height);
    if (!opacity_->record(light_, batches, batchCount, size)) return SmokeShadow{};
    if (!ensureLoaded() || !opacity_->ok()) return SmokeShadow{};
    TargetDesc desc;
    desc.width = desc.height = size;
    desc.format = TargetFormat::RGBA16F;
    SmokeShadow shadow;
    shadow.opacity = frame.createTarget(SmokeOpacityMap::kTarget, desc);
    shadow.worldToShadow = opacity_->worldToShadow();
    const Target target = shadow.opacity;
    frame.addPass(SmokeOpacityMap::kPass, {}, {target}, [this, target](PassContext& ctx) {
        GlStateGuard guard;
        DebugGroup group(SmokeOpacityMap::kPass);
        ctx.bindForDraw(target);
        glActiveTexture(GL_TEXTURE0);  // the ramp upload binds on the active unit: a guarded one
        ramp_.upload();
        std::vector<float> rows(rampInputs_.size());
        for (size_t i = 0; i < rows.size(); ++i) rows[i] = ramp_.rowV(int(i));
        opacity_->draw(atlas_.texture(), ramp_.texture(), rows);
    });
    return shadow;
}

void ParticleRenderer::setLightUniforms(const ParticleProgram& p, const DrawBatch& batch, const ViewRecord& record,
                                        uint32_t opacity) const {
    const LightingDesc& l = batch.lighting;
    const glm::vec3 sunView = glm::normalize(glm::mat3(record.view.view) * light_.toSun);
    const glm::vec3 ambient = light_.ambient * l.ambient;
    glUniform3f(p.sunView, sunView.x, sunView.y, sunView.z);
    glUniform3f(p.sunColor, light_.sunColor.x, light_.sunColor.y, light_.sunColor.z);
    glUniform3f(p.ambient, ambient.x, ambient.y, ambient.z);
    glUniform1f(p.normalStrength, l.normalStrength);
    glUniform1f(p.scattering, l.scattering);
    glUniform1f(p.anisotropy, l.anisotropy);
    glUniform1f(p.absorption, l.absorption);
    glUniform1i(p.shadowed, opacity ? 1 : 0);
    const glm::mat4 viewToShadow = record.worldToShadow * glm::inverse(record.view.view);
    glUniformMatrix4fv(p.viewToShadow, 1, GL_FALSE, &viewToShadow[0][0]);
    glUniform1i(p.opacity, kOpacityUnit);
}

}  // namespace fx
