#include "SmokeOpacityMap.h"

#include <algorithm>
#include <cmath>

#include "render/PrivateGl.h"

#include "Uniforms.h"

namespace fx {
namespace {

constexpr int kAtlasUnit = 0, kRampUnit = 1;

// Rounds `v` (> 0) up to a power of 2^(1/4): the box changes size in steps of 19 %, so a cloud
// that grows slowly changes its shadow's texel size only now and then.
float quantizeUp(float v) { return std::exp2(std::ceil(std::log2(std::max(v, 1e-3f)) * 4.0f) / 4.0f); }

}  // namespace

void SmokeOpacityMap::bind(const ProgramCache& programs) {
    program_ = programs.passProgram(ProgramCache::OpacityMap);
    locateUniforms(program_, {{&locView_, "uView"}, {&locProj_, "uProj"}, {&locRampRow_, "uRampRow"},
                              {&locAtlas_, "uAtlas"}, {&locRamp_, "uRamp"}, {&locDepthRange_, "uDepthRange"},
                              {&locTrimmed_, "uTrimmed"}, {&locNear_, "uNear"}});
}

int SmokeOpacityMap::sizeFor(int viewWidth, int viewHeight) {
    const int wanted = std::max(viewWidth, viewHeight) / 5;
    int size = kMinSize;
    while (size < kMaxSize && size * 2 <= wanted) size *= 2;
    return size;
}

bool SmokeOpacityMap::record(const LightState& light, const ParticleBatch* batches, int batchCount, int size,
                             Casters* out) {
    Casters& c = *out;
    c.instances.clear();
    c.ranges.clear();
    if (!light.on) return false;
    // The light's axes: right and up span the map, toSun points back toward the sun.
    const glm::vec3 toSun = light.toSun;
    const glm::vec3 hint = std::fabs(toSun.z) < 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 right = glm::normalize(glm::cross(-toSun, hint));
    const glm::vec3 up = glm::cross(right, -toSun);

    glm::vec3 lo(3.0e38f), hi(-3.0e38f);  // (u, v, w) bounds, w = height toward the sun
    for (int b = 0; b < batchCount; ++b) {
        const ParticleBatch& in = batches[b];
        if (!in.pool || !in.desc || in.pool->alive() == 0) continue;
        const LightingDesc& l = in.desc->lighting;
        if (!l.lit(in.desc->render.blend) || !l.castsShadow || in.desc->render.stateless) continue;
        const ParticlePool& pool = *in.pool;
        Range range;
        range.first = int(c.instances.size());
        range.batch = b;
        for (int i = 0; i < pool.alive(); ++i) {
            const float size = pool.size()[i], fade = pool.fade()[i];
            if (!(size > 0.0f) || !(fade > 0.0f) || !std::isfinite(size)) continue;
            const glm::vec3 p(pool.posX()[i], pool.posY()[i], pool.posZ()[i]);
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
            const float r = size * 0.70710678f;  // half the quad's diagonal: any rotation
            const glm::vec3 q(glm::dot(p, right), glm::dot(p, up), glm::dot(p, toSun));
            lo = glm::min(lo, q - r);
            hi = glm::max(hi, q + r);
            ParticleInstance inst;
            inst.x = p.x;
            inst.y = p.y;
            inst.z = p.z;
            inst.size = size;
            inst.life = pool.life()[i];
            inst.rotation = pool.rotation()[i];
            inst.fade = std::min(fade, 1.0f);
            inst.frame = float(pool.frame()[i] & 3u);
            c.instances.push_back(inst);
        }
        range.count = int(c.instances.size()) - range.first;
        if (range.count > 0) c.ranges.push_back(range);
    }
    if (c.instances.empty()) return false;

    // Square box, snapped (see the header): side up to a power of 2^(1/4) with a margin of a
    // few texels, centre on whole texels of a grid fixed in the world.
    const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
    const int texels = std::max(size, 1);
    c.side = quantizeUp(extent * (1.0f + 4.0f / float(texels)) + 1e-3f);
    const float texel = c.side / float(texels);
    const float uc = std::round(0.5f * (lo.x + hi.x) / texel) * texel;
    const float vc = std::round(0.5f * (lo.y + hi.y) / texel) * texel;
    // Depth: from the top of the casters down, a sixth more than their span below them, so
    // every centre lies before 7/8 and the last channel holds each caster whole.
    const float depthSpan = quantizeUp((hi.z - lo.z) * 7.0f / 6.0f + 1e-3f);
    const float step = depthSpan / 64.0f;
    const float top = std::ceil(hi.z / step) * step;
    c.depthRange = glm::vec2(0.0f, depthSpan);

    // View: x = u - uc, y = v - vc, z = w - top (the distance below the top is -z).
    glm::mat4 rows(0.0f);
    rows[0] = glm::vec4(right, -uc);
    rows[1] = glm::vec4(up, -vc);
    rows[2] = glm::vec4(toSun, -top);
    rows[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    c.lightView = glm::transpose(rows);
    // Orthographic, depth into [0.05, 0.95] of NDC: inside the clip volume under either clip
    // convention the host may have set (-1..1 or 0..1); the shader computes its own depth.
    c.lightProj = glm::mat4(1.0f);
    c.lightProj[0][0] = 2.0f / c.side;
    c.lightProj[1][1] = 2.0f / c.side;
    c.lightProj[2][2] = -0.9f / depthSpan;
    c.lightProj[3][2] = 0.05f;
    // World -> (u, v, depth, 1), each in [0, 1] inside the box.
    glm::mat4 tex(0.0f);
    tex[0] = glm::vec4(right / c.side, 0.5f - uc / c.side);
    tex[1] = glm::vec4(up / c.side, 0.5f - vc / c.side);
    tex[2] = glm::vec4(-toSun / depthSpan, top / depthSpan);
    tex[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    c.worldToShadow = glm::transpose(tex);
    return true;
}

void SmokeOpacityMap::draw(const Casters& c, uint32_t atlas, uint32_t ramp, const std::vector<float>& rampRows) {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearBufferfv(GL_COLOR, 0, zero);
    if (!program_ || c.instances.empty()) return;
    if (!stream_.created()) stream_.create();
    stream_.upload(c.instances.data(), int(c.instances.size()));
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    for (int unit : {kAtlasUnit, kRampUnit}) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, unit == kAtlasUnit ? atlas : ramp);
        glBindSampler(GLuint(unit), 0);
    }
    glUseProgram(program_);
    glUniformMatrix4fv(locView_, 1, GL_FALSE, &c.lightView[0][0]);
    glUniformMatrix4fv(locProj_, 1, GL_FALSE, &c.lightProj[0][0]);
    glUniform1i(locAtlas_, kAtlasUnit);
    glUniform1i(locRamp_, kRampUnit);
    glUniform2f(locDepthRange_, c.depthRange.x, c.depthRange.y);
    glUniform1i(locTrimmed_, 0);
    glUniform1f(locNear_, 0.0f);
    for (const Range& r : c.ranges) {
        glUniform1f(locRampRow_, r.batch < int(rampRows.size()) ? rampRows[size_t(r.batch)] : 0.5f);
        stream_.bindRange(r.first);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, r.count);
    }
}

}  // namespace fx
