#include "ParticleDraw.h"

#include <algorithm>
#include <cmath>

#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "ViewFrustum.h"

namespace fx {
namespace {

// One pixel of a target `height` pixels tall in ray slope (y/depth; square pixels): the spheres'
// margin against the rasteriser's snapping, and with the atlas cell's texels the billboards' LOD
// scale.
float pixelSlopeOf(const glm::mat4& proj, float height) {
    return 2.0f / std::fmax(std::fabs(proj[1][1]) * height, 1e-6f);
}

// render.near_fade `fade` metres in front of the near plane as the shaders' uNearFadeMap: the
// factor clamp(depth * x + y, 0, 1) rises from 0 at the near plane to 1 at `fade` metres past it;
// with fade 0 (off) it is 1 at every depth.
glm::vec2 nearFadeMap(float fade, float nearPlane) {
    return fade > 0.0f ? glm::vec2(1.0f / fade, -nearPlane / fade) : glm::vec2(0.0f, 1.0f);
}

}  // namespace

void ParticleDraw::create() {
    stream_.create();
    depthSampler_.create();
    atlasSampler_.create();
    ramp_.upload();
    shapeTable_ = atlas_.shapes().packed();
    discTable_ = atlas_.shapes().packed(TrimmedShapes::Clip::Disc);
    discInfo_ = atlas_.shapes().packedInfo(TrimmedShapes::Clip::Disc);
    reach_ = BillboardReach::of(atlas_.shapes(), 1.0f);
}

BillboardReach ParticleDraw::billboardReach(const ParticleView& record, bool halfRes) const {
    if (record.settings.shape != ParticleShape::Trimmed || shapeTable_.empty() || reach_.lodScale <= 0.0f) {
        return BillboardReach{};
    }
    // draw()'s LOD scale for a target of the view's height, or half of it (the half-size target
    // may be a row taller or shorter: the reach table's neighbouring buckets cover that).
    const ViewInfo& view = record.view;
    const float height = float(std::max(view.height, 1)) * (halfRes ? 0.5f : 1.0f);
    BillboardReach r = reach_;
    r.lodScale = float(atlas_.cellTexels()) * pixelSlopeOf(view.proj, height);
    return r;
}

float ParticleDraw::lodScaleFor(const glm::mat4& proj, float height) const {
    return float(atlas_.cellTexels()) * pixelSlopeOf(proj, height);
}

void ParticleDraw::draw(const ParticleView& record, const DrawInputs& in) {
    const DrawList& list = record.list;
    const ViewInfo& view = record.view;
    depthSampler_.bindTexture(kSceneDepthUnit, in.sceneDepth);  // the host's, or the half-res copy
    if (in.sceneDepth) sceneDepthBarrier(in.depthDecode);
    // The depth texture's size for uDepthUv where the pass did not place the decode (the half-res
    // depth of quarter res, read in its own target from its (0, 0)).
    SceneDepthDecode depthDecode = in.depthDecode;
    if (in.sceneDepth && depthDecode.depthSize.x == 0) {
        glActiveTexture(GLenum(GL_TEXTURE0 + kSceneDepthUnit));
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &depthDecode.depthSize.x);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &depthDecode.depthSize.y);
    }
    glActiveTexture(GL_TEXTURE0);
    ramp_.upload();
    stream_.upload(list.instances.data(), list.particleCount(), jobs_);

    plainDrawState();
    in.clip.apply();  // a host's scissor on sceneColor keeps clipping the smoke
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    bindTextureUnit(kRampUnit, ramp_.texture());
    if (record.lit()) {
        bindTextureUnit(kOpacityUnit, in.opacity);
    }

    const glm::vec2 slopes = frustumSlopes(view.proj);
    // Trimmed billboards: the LOD estimate needs the target's height in pixels (the viewport the
    // pass bound: full or half resolution).
    static_assert(TrimmedShapes::kFrames * TrimmedShapes::kMaxBuckets * TrimmedShapes::kMaxVertices / 2 == 128,
                  "uShapes[128] in vs_particles.glsl");
    static_assert(TrimmedShapes::kFrames * TrimmedShapes::kMaxBuckets / 2 == 16, "uShapeInfo[16] in vs_particles.glsl");
    GLint viewport[4] = {0, 0, 1, 1};
    glGetIntegerv(GL_VIEWPORT, viewport);
    const bool trimmed = record.settings.shape == ParticleShape::Trimmed && !shapeTable_.empty();
    const float pixelSlope = pixelSlopeOf(view.proj, float(std::max(viewport[3], 1)));
    const float lodScale = lodScaleFor(view.proj, float(std::max(viewport[3], 1)));
    const ProgramCache& programs = *programs_;
    for (const DrawBatch& batch : list.batches) {
        // Lit when the host set a light and the reaction takes it. The cache reduces the key to a
        // program it built (unlit if the lit build failed, the general soft build if the power's
        // own did); nothing here compiles (the cache was filled by prepare() or before the
        // passes: ParticleRenderer::ensureDrawPrograms).
        const ProgramCache::Key key = programs.filter(ProgramCache::drawKey(
            batch.technique, in.quarterRes, batch.contrastPower, record.lit() && batch.lighting.lit(batch.blend)));
        const ParticleProgram* found = programs.find(key);
        if (!found) continue;
        const ParticleProgram& p = *found;
        const bool lit = key.lit;
        // The atlas is read from one mip level, the nearest (atlasSampler_): trilinear's blend of
        // two levels would cost a second bilinear read of every fragment. A billboard faces the
        // camera, so its level of detail is one value over the whole quad (a picture within 4/255
        // of trilinear's). A sphere's varies over its disc by the curve of its atlas mapping, little
        // but enough that, rarely, a pixel whose level of detail sits at the middle between two
        // levels takes the other one with another rounding (a view elsewhere in the window, a
        // trimmed polygon instead of the quad): within 3/255 of trilinear in fxbench's frames, up
        // to 12/255 at two pixels of a hard-edged atlas (TrimmedParticleTest). (A level per
        // sphere through textureLod costs llvmpipe 7 % in the fill scene: its per-pixel path.)
        const bool sphere = key.variant == ProgramCache::Spherical;
        bindTextureUnit(kAtlasUnit, lit ? atlas_.litTexture() : atlas_.texture(), atlasSampler_.name());
        // Full resolution tests against the host's z-buffer without writing it. Hard particles
        // always do (that is their look). Soft and spherical ones only skip fragments there that
        // would shade to nothing (behind geometry their fade / visible chord is 0), which needs a
        // z-buffer whose precision holds at any near/far ratio: reversed-Z. With standard depth a
        // 24-bit buffer at near 0.01, far 1e5 cannot tell 1 m apart at 10 km, so they stay
        // untested there and the fade alone hides them. (Quarter res has no z-buffer.)
        // Quarter res: the half-res z-buffer QuarterResPath::beginQuarter filled (reversed-Z only).
        const bool zTest = in.quarterRes ? in.zTested : (batch.technique == Technique::Hard || record.reversedZ);
        if (zTest) {
            depthTestFor(view.depth);
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
        const glm::vec2 nearFade = nearFadeMap(batch.nearFade, view.nearPlane);
        glUniform2f(p.nearFade, nearFade.x, nearFade.y);
        if (lit) setLightUniforms(p, batch, record, in.opacity);
        glUniform1i(p.atlas, kAtlasUnit);
        glUniform1i(p.ramp, kRampUnit);
        glUniform1i(p.sceneDepth, kSceneDepthUnit);
        setSceneDepthDecode(p.depthDecode, depthDecode);
        setFogUniforms(p.fog, view.fog);
        // Spherical particles trim to their frame's polygon clipped to the disc (the octagon
        // around the sphere where its bounds do not hold: vs_particles.glsl).
        glUniform1i(p.trimmed, trimmed ? 1 : 0);
        if (trimmed) {
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

void ParticleDraw::setLightUniforms(const ParticleProgram& p, const DrawBatch& batch, const ParticleView& record,
                                    uint32_t opacity) const {
    const LightState& light = record.settings.light;
    const LightingDesc& l = batch.lighting;
    const glm::vec3 sunView = glm::normalize(glm::mat3(record.view.view) * light.toSun);
    const glm::vec3 ambient = light.ambient * l.ambient;
    glUniform3f(p.sunView, sunView.x, sunView.y, sunView.z);
    glUniform3f(p.sunColor, light.sunColor.x, light.sunColor.y, light.sunColor.z);
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
