// ParticleRenderer's lit smoke (Plugin::setSceneLight, API 1.2): the opacity map's pass, declared
// by declareShadowPasses or else by the first declarePasses of a lit frame. The FX_LIT uniforms
// are ParticleDraw's; the rest of the renderer is in ParticleRenderer.cpp.
#include <vector>

#include "ParticleRenderer.h"
#include "render/PrivateGl.h"

#include "GlStateGuard.h"

namespace fx {

SmokeShadow ParticleRenderer::declareShadowPasses(const ViewInfo& view, FrameBuilder& frame,
                                                  const ParticleBatch* batches, int batchCount,
                                                  const LightState& light) {
    pendingShadow_ = SmokeShadow{};
    if (state_ == State::Failed || !light.on) return SmokeShadow{};
    draw_.ramp().setRows(batches, batchCount);
    pendingShadow_ = declareOpacityPass(view, frame, batches, batchCount, light);
    return pendingShadow_;
}

SmokeShadow ParticleRenderer::declareOpacityPass(const ViewInfo& view, FrameBuilder& frame,
                                                 const ParticleBatch* batches, int batchCount,
                                                 const LightState& light) {
    // Nothing is loaded for a frame without shadow casters.
    const int size = SmokeOpacityMap::sizeFor(view.width, view.height);
    // Recorded for this map alone: another view's map may be declared before this one's pass runs.
    std::shared_ptr<SmokeOpacityMap::Casters> casters = reuseRecord(opacityRecords_);
    if (!opacity_.record(light, batches, batchCount, size, casters.get())) return SmokeShadow{};
    if (!ensureLoaded() || !opacity_.ok()) return SmokeShadow{};
    TargetDesc desc;
    desc.width = desc.height = size;
    desc.format = TargetFormat::RGBA16F;
    SmokeShadow shadow;
    shadow.opacity = frame.createTarget(SmokeOpacityMap::kTarget, desc);
    shadow.worldToShadow = casters->worldToShadow;
    const Target target = shadow.opacity;
    frame.addPass(SmokeOpacityMap::kPass, {}, {target}, [this, target, casters](PassContext& ctx) {
        GlStateGuard guard;
        DebugGroup group(SmokeOpacityMap::kPass);
        ctx.bindForDraw(target);
        glActiveTexture(GL_TEXTURE0);  // the ramp upload binds on the active unit: a guarded one
        ColorRampTexture& ramp = draw_.ramp();
        ramp.upload();
        std::vector<float> rows(size_t(ramp.rows()));
        for (size_t i = 0; i < rows.size(); ++i) rows[i] = ramp.rowV(int(i));
        opacity_.draw(*casters, draw_.atlas().texture(), ramp.texture(), rows);
    });
    return shadow;
}

}  // namespace fx
