// ParticleRenderer's draw of one view's batches (drawBatches): the GL state, program and
// uniforms per batch, and the instanced draw. The passes around it are in ParticleRenderer.cpp.
#include <algorithm>
#include <cmath>

#include "ParticleRenderer.h"
#include "render/PrivateGl.h"

#include "GlStateGuard.h"

namespace fx {
namespace {

// |x/depth| and |y/depth| slightly past the frustum edges, from a perspective projection.
glm::vec2 frustumSlopes(const glm::mat4& proj) {
    const float sx = (1.0f + std::fabs(proj[2][0])) / std::fmax(std::fabs(proj[0][0]), 1e-6f);
    const float sy = (1.0f + std::fabs(proj[2][1])) / std::fmax(std::fabs(proj[1][1]), 1e-6f);
    return glm::vec2(sx, sy) * 1.02f;
}

}  // namespace

void ParticleRenderer::drawBatches(const ViewRecord& record, uint32_t sceneDepth, bool quarterRes, bool halfZ,
                                   uint32_t opacity, uint32_t tiles, uint32_t coarse) {
    const DrawList& list = record.list;
    const ViewInfo& view = record.view;
    glActiveTexture(GL_TEXTURE0);
    ramp_.upload();
    stream_.upload(list.instances.data(), list.particleCount());

    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    bindTextureUnit(kAtlasUnit, atlas_.texture());
    bindTextureUnit(kRampUnit, ramp_.texture());
    depthSampler_.bindTexture(kSceneDepthUnit, sceneDepth);  // the host's, or the half-res copy
    if (record.lit) {
        bindTextureUnit(kOpacityUnit, opacity);
    }
    const bool classified = tiles != 0 && coarse != 0 && classifier_;
    if (classified) {
        bindTextureUnit(FadeClassifier::kTileUnit, tiles);
        bindTextureUnit(FadeClassifier::kCoarseUnit, coarse);
    }

    const glm::vec2 slopes = frustumSlopes(view.proj);
    // Trimmed billboards: the LOD estimate needs the target's height in pixels (the viewport the
    // pass bound: full or half resolution).
    static_assert(TrimmedShapes::kFrames * TrimmedShapes::kMaxBuckets * TrimmedShapes::kMaxVertices / 2 == 128,
                  "uShapes[128] in vs_particles.glsl");
    static_assert(TrimmedShapes::kFrames * TrimmedShapes::kMaxBuckets / 2 == 16, "uShapeInfo[16] in vs_particles.glsl");
    GLint viewport[4] = {0, 0, 1, 1};
    glGetIntegerv(GL_VIEWPORT, viewport);
    const bool trimmable = record.shape == ParticleShape::Trimmed && !shapeTable_.empty();
    // One pixel of the target in ray slope (y/depth; square pixels): the spheres' margin against
    // the rasteriser's snapping, and with the atlas cell's texels the billboards' LOD scale.
    const float pixelSlope = 2.0f / std::fmax(std::fabs(view.proj[1][1]) * float(std::max(viewport[3], 1)), 1e-6f);
    const float lodScale = float(atlas_.cellTexels()) * pixelSlope;
    for (const DrawBatch& batch : list.batches) {
        const ProgramCache::Variant variant =
            ProgramCache::variantFor(batch.technique, quarterRes, batch.contrastPower);
        // Lit when the host set a light and the reaction takes it; unlit if the lit build failed.
        const bool lit = record.lit && batch.lighting.lit(batch.blend) && programs_->get(variant, true).program;
        // Soft and spherical batches take the classified build when the tiles are there.
        const bool classifiable =
            classified && batch.technique != Technique::Hard && programs_->get(variant, lit, true).program;
        // Soft batches take their contrast power's own build; nothing here compiles (the cache
        // was filled by prepare() or ensureDrawPrograms before any pass).
        const ParticleProgram& p = programs_->get(variant, lit, batch.contrastPower, classifiable);
        if (!p.program) continue;
        if (record.lit) bindTextureUnit(kAtlasUnit, lit ? atlas_.litTexture() : atlas_.texture());
        // Full resolution tests against the host's z-buffer without writing it. Hard particles
        // always do (that is their look). Soft and spherical ones only skip fragments there that
        // would shade to nothing (behind geometry their fade / visible chord is 0), which needs a
        // z-buffer whose precision holds at any near/far ratio: reversed-Z. With standard depth a
        // 24-bit buffer at near 0.01, far 1e5 cannot tell 1 m apart at 10 km, so they stay
        // untested there and the fade alone hides them. (Quarter res has no z-buffer.)
        // Quarter res: the half-res z-buffer QuarterResPath::beginQuarter filled (reversed-Z only).
        const bool zTest = quarterRes ? halfZ
                                      : (batch.technique == Technique::Hard || view.depth == DepthConvention::ReversedZ);
        if (zTest) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(view.depth == DepthConvention::ReversedZ ? GL_GEQUAL : GL_LEQUAL);
        } else {
            glDisable(GL_DEPTH_TEST);
        }
        if (batch.blend == BlendMode::Additive) {
            glBlendFunc(GL_ONE, GL_ONE);
        } else {
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        }
        glUseProgram(p.program);
        glUniformMatrix4fv(p.view, 1, GL_FALSE, &view.view[0][0]);
        glUniformMatrix4fv(p.proj, 1, GL_FALSE, &view.proj[0][0]);
        glUniform1f(p.nearPlane, view.nearPlane);
        glUniform1f(p.farPlane, view.farPlane);
        glUniform2f(p.slopeMax, slopes.x, slopes.y);
        glUniform1f(p.pixelSlope, pixelSlope);
        glUniform1f(p.rampRow, ramp_.rowV(batch.rampRow));
        glUniform1i(p.blendMode, static_cast<int>(batch.blend));
        glUniform1f(p.softScale, batch.softScale);
        glUniform1f(p.contrastPower, batch.contrastPower);
        int powerWhole = 0, powerHalf = 0;
        if (ProgramCache::halfWholePower(batch.contrastPower, &powerWhole, &powerHalf)) {
            glUniform1i(p.powerWhole, powerWhole);
            glUniform1i(p.powerHalf, powerHalf);
        }
        glUniform1f(p.nearFade, batch.nearFade);
        if (lit) setLightUniforms(p, batch, record, opacity);
        glUniform1i(p.atlas, kAtlasUnit);
        glUniform1i(p.ramp, kRampUnit);
        glUniform1i(p.sceneDepth, kSceneDepthUnit);
        if (p.tiles >= 0) {
            glUniform1i(p.tiles, FadeClassifier::kTileUnit);
            glUniform1i(p.tilesCoarse, FadeClassifier::kCoarseUnit);
            glUniform2f(p.viewSize, float(view.width), float(view.height));
        }
        // Spherical particles trim to their frame's polygon clipped to the disc (the octagon
        // around the sphere where its bounds do not hold: vs_particles.glsl).
        const bool trimmed = trimmable;
        glUniform1i(p.trimmed, trimmed ? 1 : 0);
        if (trimmed) {
            const bool sphere = variant == ProgramCache::Spherical;
            const std::vector<glm::vec4>& table = sphere ? discTable_ : shapeTable_;
            glUniform1i(p.shapeBuckets, atlas_.shapes().buckets());
            glUniform1f(p.lodScale, lodScale);
            glUniform4fv(p.shapes, GLsizei(table.size()), &table[0][0]);
            if (sphere) glUniform4fv(p.shapeInfo, GLsizei(discInfo_.size()), &discInfo_[0][0]);
        }
        stream_.bindRange(batch.first);
        if (trimmed) {
            glDrawArraysInstanced(GL_TRIANGLE_FAN, 0, TrimmedShapes::kMaxVertices, batch.count);
        } else {
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, batch.count);
        }
    }
}

}  // namespace fx
