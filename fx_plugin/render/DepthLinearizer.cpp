// The host's z-buffer into linear depth: copy (when only a bound framebuffer is given) and the
// linearise pass.
#include "DepthLinearizer.h"

#include <algorithm>

#include "PrivateGl.h"
#include "Uniforms.h"

namespace fx {

uint32_t supportedDepthFormat(uint32_t f) {
    switch (f) {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH32F_STENCIL8:
        return f;
    default:
        return 0;
    }
}

DepthLinearizer::~DepthLinearizer() { releaseGl(); }

void DepthLinearizer::releaseGl() {
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (sampler_) glDeleteSamplers(1, &sampler_);
    if (copy_) glDeleteTextures(1, &copy_);
    if (resolveFbo_) glDeleteFramebuffers(1, &resolveFbo_);
    program_ = vao_ = sampler_ = copy_ = resolveFbo_ = 0;
    copyWidth_ = copyHeight_ = 0;
    copyFormat_ = 0;
}

bool DepthLinearizer::bind(const ProgramCache& programs) {
    const uint32_t program = programs.passProgram(ProgramCache::LinearizeDepth);
    if (!program) return false;
    // A reload's programs are built while the old ones live: a swapped cache never hands out the
    // name taken before.
    if (program == program_) return true;
    program_ = program;
    locateUniforms(program_, {{&locDepth_, "uDepth"}, {&locCoeffs_, "uCoeffs"}, {&locFarWindow_, "uFarWindow"},
                              {&locReversed_, "uReversed"}, {&locBackground_, "uBackground"},
                              {&locInvSize_, "uInvSize"}, {&locTexelOrigin_, "uTexelOrigin"}});
    if (vao_) return true;
    glGenVertexArrays(1, &vao_);
    // A host's depth texture may carry shadow comparison or mipmapped filtering: read it through
    // a sampler that has neither.
    glGenSamplers(1, &sampler_);
    glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler_, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return true;
}

uint32_t DepthLinearizer::framebufferDepthFormat(uint32_t framebuffer) {
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    const GLenum depthAttachment = framebuffer == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
    const GLenum stencilAttachment = framebuffer == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
    auto query = [](GLenum attachment, GLenum what) {
        GLint v = 0;
        glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, what, &v);
        return v;
    };
    GLint bits = 0, component = GL_NONE, stencil = 0;
    if (query(depthAttachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) != GL_NONE) {
        bits = query(depthAttachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
        component = query(depthAttachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE);
        if (query(stencilAttachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) != GL_NONE) {
            stencil = query(stencilAttachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
        }
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
    if (bits == 0) return 0;
    // The copy keeps every bit of the source, in the source's own layout: a multisampled source
    // is resolved with a blit, which needs the formats to match exactly (stencil included).
    if (component == GL_FLOAT) return stencil ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
    if (bits <= 16) return GL_DEPTH_COMPONENT16;
    if (bits <= 24) return stencil ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
    return GL_DEPTH_COMPONENT32;
}

int DepthLinearizer::framebufferSamples(uint32_t framebuffer) {
    GLint previous = 0, samples = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glGetIntegerv(GL_SAMPLES, &samples);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
    return samples;
}

uint32_t DepthLinearizer::textureFormat(uint32_t texture) {
    glBindTexture(GL_TEXTURE_2D, texture);
    GLint format = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    return uint32_t(format);
}

void DepthLinearizer::textureSize(uint32_t texture, int* width, int* height) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, height);
}

uint32_t DepthLinearizer::copyFramebufferDepth(uint32_t framebuffer, int x, int y, int width, int height,
                                         uint32_t format, int samples, const DepthRegion& region) {
    glActiveTexture(GL_TEXTURE0);
    if (!copy_ || copyWidth_ != width || copyHeight_ != height || copyFormat_ != format) {
        if (!copy_) glGenTextures(1, &copy_);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);  // a null upload must not read from a host PBO
        glBindTexture(GL_TEXTURE_2D, copy_);
        const bool packed = format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
        const GLenum layout = packed ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT;
        const GLenum type = format == GL_DEPTH32F_STENCIL8 ? GL_FLOAT_32_UNSIGNED_INT_24_8_REV
                            : format == GL_DEPTH24_STENCIL8 ? GL_UNSIGNED_INT_24_8
                            : format == GL_DEPTH_COMPONENT32F ? GL_FLOAT
                                                              : GL_UNSIGNED_INT;
        glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), width, height, 0, layout, type, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        copyWidth_ = width;
        copyHeight_ = height;
        copyFormat_ = format;
        if (resolveFbo_) glDeleteFramebuffers(1, &resolveFbo_);
        resolveFbo_ = 0;
    }
    // The pixels to copy: the region (clamped to the texture) or all of it.
    const int rx = region.whole ? 0 : std::max(0, region.x0), ry = region.whole ? 0 : std::max(0, region.y0);
    const int rw = region.whole ? width : std::max(0, std::min(width, region.x1) - rx);
    const int rh = region.whole ? height : std::max(0, std::min(height, region.y1) - ry);
    if (samples > 0) {
        // glCopyTexSubImage2D refuses a multisampled source; a blit resolves it (one sample per
        // pixel, nearest: the z-buffer's own values, as a depth resolve must be).
        if (!resolveFbo_) {
            glGenFramebuffers(1, &resolveFbo_);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
            const bool packed = format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
            glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, packed ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                   GL_TEXTURE_2D, copy_, 0);
            glDrawBuffer(GL_NONE);
        }
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
        glBlitFramebuffer(x + rx, y + ry, x + rx + rw, y + ry + rh, rx, ry, rx + rw, ry + rh, GL_DEPTH_BUFFER_BIT,
                          GL_NEAREST);
    } else {
        glBindTexture(GL_TEXTURE_2D, copy_);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, rx, ry, x + rx, y + ry, rw, rh);
    }
    ++copies_;
    return copy_;
}

void DepthLinearizer::linearize(uint32_t depthTexture, const glm::mat4& proj, const DepthMapping& mapping,
                          float background, uint32_t targetFramebuffer, int width, int height,
                          const DepthRegion& region, glm::ivec2 texelOrigin, glm::ivec2 textureSize) {
    const LinearizeCoefficients k = linearizeCoefficients(proj, mapping);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targetFramebuffer);
    glViewport(0, 0, width, height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (!region.whole) {
        // Outside the region nobody reads: "nothing drawn" there, the pass only inside.
        const GLfloat far[4] = {background, 0.0f, 0.0f, 0.0f};
        glClearBufferfv(GL_COLOR, 0, far);
        glEnable(GL_SCISSOR_TEST);
        glScissor(region.x0, region.y0, std::max(0, region.x1 - region.x0), std::max(0, region.y1 - region.y0));
    }
    glUseProgram(program_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, depthTexture);
    glBindSampler(0, sampler_);
    glUniform1i(locDepth_, 0);
    glUniform4f(locCoeffs_, k.a, k.b, k.c, k.d);
    glUniform1f(locFarWindow_, k.farWindow);
    glUniform1f(locReversed_, k.reversed ? -1.0f : 1.0f);
    glUniform1f(locBackground_, background);
    const int tw = textureSize.x > 0 ? textureSize.x : width, th = textureSize.y > 0 ? textureSize.y : height;
    glUniform2f(locInvSize_, 1.0f / float(tw), 1.0f / float(th));
    glUniform2f(locTexelOrigin_, float(texelOrigin.x), float(texelOrigin.y));
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++linearizations_;
}

}  // namespace fx
