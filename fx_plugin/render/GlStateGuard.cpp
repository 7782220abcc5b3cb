#include "GlStateGuard.h"

#include <algorithm>

#include "render/PrivateGl.h"

#include "PinnedGlState.h"

namespace fx {
void bindTextureUnit(int unit, uint32_t texture, uint32_t sampler) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, GLuint(texture));
    glBindSampler(GLuint(unit), GLuint(sampler));
}

ClampSampler::~ClampSampler() {
    if (sampler_) glDeleteSamplers(1, &sampler_);
}

void ClampSampler::create() {
    if (sampler_) return;
    const GLint filter = filter_ == Filter::Nearest ? GL_NEAREST : GL_LINEAR;
    glGenSamplers(1, &sampler_);
    glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER,
                        filter_ == Filter::LinearNearestMip ? GL_LINEAR_MIPMAP_NEAREST : filter);
    glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, filter);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void ClampSampler::bindTexture(int unit, uint32_t texture) const { bindTextureUnit(unit, texture, sampler_); }

void plainDrawState() {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void depthTestFor(DepthConvention depth) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth == DepthConvention::ReversedZ ? GL_GEQUAL : GL_LEQUAL);
}

DebugGroup::DebugGroup(const char* name)
    : active_(FXGLAD_GL_KHR_debug != 0 && glPushDebugGroup != nullptr && glPopDebugGroup != nullptr) {
    if (active_) glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}

DebugGroup::~DebugGroup() {
    if (active_) glPopDebugGroup();
}

namespace {
// The immediate path's stated mapping (HostDepthMappingScope), while one is alive.
struct HostMapping {
    bool active = false;
    bool clipZeroToOne = false;
    double rangeNear = 0.0, rangeFar = 1.0;
};
HostMapping g_hostMapping;
}  // namespace

HostDepthMappingScope::HostDepthMappingScope(bool clipZeroToOne, float rangeNear, float rangeFar) {
    g_hostMapping = HostMapping{true, clipZeroToOne, rangeNear, rangeFar};
}
HostDepthMappingScope::~HostDepthMappingScope() { g_hostMapping = HostMapping{}; }

GlStateGuard::GlStateGuard(DepthConvention depth, bool viewDepth) {
    const bool host = viewDepth && g_hostMapping.active;
    const std::vector<PinnedGlState>& rows = pinnedGlStates();
    rows_ = int(std::min(rows.size(), saved_.size()));
    for (int i = 0; i < rows_; ++i) rows[size_t(i)].get(rows[size_t(i)], &saved_[size_t(i)]);
    // Backwards, as on exit: the active texture (row 0), which the per-unit rows move, comes last.
    for (int i = rows_ - 1; i >= 0; --i) {
        const PinnedGlState& r = rows[size_t(i)];
        GlStateValue want = r.pinned;
        switch (r.pin) {
        case PinnedGlState::Pin::Restore: continue;
        case PinnedGlState::Pin::Always: break;
        case PinnedGlState::Pin::DepthMode:
            want.v[1] = (host ? g_hostMapping.clipZeroToOne : depth == DepthConvention::ReversedZ)
                            ? GL_ZERO_TO_ONE
                            : GL_NEGATIVE_ONE_TO_ONE;
            if (saved_[size_t(i)] == want) continue;
            break;
        case PinnedGlState::Pin::DepthRange:
            if (host) {
                want.v[0] = g_hostMapping.rangeNear;
                want.v[1] = g_hostMapping.rangeFar;
            }
            if (saved_[size_t(i)] == want) continue;
            break;
        case PinnedGlState::Pin::Value:
            if (saved_[size_t(i)] == want) continue;
            break;
        }
        r.set(r, want);
    }
}

GlStateGuard::~GlStateGuard() {
    const std::vector<PinnedGlState>& rows = pinnedGlStates();
    for (int i = rows_ - 1; i >= 0; --i) rows[size_t(i)].set(rows[size_t(i)], saved_[size_t(i)]);
}

}  // namespace fx
