#include "GlStateGuard.h"

#include <algorithm>

#include "render/PrivateGl.h"

namespace fx {
void bindTextureUnit(int unit, uint32_t texture, uint32_t sampler) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, GLuint(texture));
    glBindSampler(GLuint(unit), GLuint(sampler));
}

NearestSampler::~NearestSampler() {
    if (sampler_) glDeleteSamplers(1, &sampler_);
}

void NearestSampler::create() {
    if (sampler_) return;
    glGenSamplers(1, &sampler_);
    glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void NearestSampler::bindTexture(int unit, uint32_t texture) const { bindTextureUnit(unit, texture, sampler_); }

DebugGroup::DebugGroup(const char* name) : active_(FXGLAD_GL_KHR_debug != 0) {
    if (active_) glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}

DebugGroup::~DebugGroup() {
    if (active_) glPopDebugGroup();
}

GlStateGuard::GlStateGuard(DepthConvention depth) {
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
            want.v[1] = depth == DepthConvention::ReversedZ ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE;
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
