#include "FadePyramid.h"

#include <algorithm>

#include "render/PrivateGl.h"

#include "ProgramCache.h"

namespace fx {

void FadePyramid::bind(const ProgramCache& programs) {
    first_ = programs.passProgram(ProgramCache::FadePyramidFirst);
    reduce_ = programs.passProgram(ProgramCache::FadePyramidReduce);
    if (first_) {
        firstDepthLoc_ = glGetUniformLocation(first_, "uSceneDepth");
        firstInvSizeLoc_ = glGetUniformLocation(first_, "uInvDepthSize");
        firstDecode_.locate(first_);
    }
    if (reduce_) reduceBelowLoc_ = glGetUniformLocation(reduce_, "uBelow");
}

int FadePyramid::levelCount(glm::ivec2 viewSize) {
    glm::ivec2 s = baseSize(viewSize);
    int n = 1;
    while (std::max(s.x, s.y) > 4) {
        s = (s + 1) / 2;
        ++n;
    }
    return n;
}

bool FadePyramid::build(uint32_t sceneDepth, const SceneDepthDecode& decode, glm::ivec2 viewSize,
                        const NearestSampler& sampler, int depthUnit, int pyramidUnit) {
    if (!ok() || sceneDepth == 0 || viewSize.x <= 0 || viewSize.y <= 0 || decode.depthSize.x <= 0 ||
        decode.depthSize.y <= 0) {
        return false;
    }
    // Level 0 padded so that every level halves exactly (GL's mip sizes round down): the padding
    // texels read pixels past the view, which only lowers the minima above them.
    const int levels = levelCount(viewSize);
    glm::ivec2 top = baseSize(viewSize);
    for (int l = 1; l < levels; ++l) top = (top + 1) / 2;
    const glm::ivec2 padded = top * (1 << (levels - 1));
    if (!fbo_) glGenFramebuffers(1, &fbo_);
    if (!vao_) glGenVertexArrays(1, &vao_);
    if (!texture_ || padded != size_ || levels != levels_) {
        if (!texture_) glGenTextures(1, &texture_);
        bindTextureUnit(pyramidUnit, texture_);
        for (int l = 0; l < levels; ++l) {
            glTexImage2D(GL_TEXTURE_2D, l, GL_R32F, padded.x >> l, padded.y >> l, 0, GL_RED, GL_FLOAT, nullptr);
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        size_ = padded;
        levels_ = levels;
    }
    GLint drawFramebuffer = 0, vertexArray = 0, viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
    glGetIntegerv(GL_VIEWPORT, viewport);

    plainDrawState();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
    glBindVertexArray(vao_);
    // Level 0 from the scene depth.
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    glViewport(0, 0, padded.x, padded.y);
    sampler.bindTexture(depthUnit, sceneDepth);
    glUseProgram(first_);
    glUniform1i(firstDepthLoc_, depthUnit);
    glUniform2f(firstInvSizeLoc_, 1.0f / float(decode.depthSize.x), 1.0f / float(decode.depthSize.y));
    setSceneDepthDecode(firstDecode_, decode);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // Each level from the one below, the only level in the texture's sampling range meanwhile (so
    // the level drawn is no feedback loop).
    bindTextureUnit(pyramidUnit, texture_);
    glUseProgram(reduce_);
    glUniform1i(reduceBelowLoc_, pyramidUnit);
    for (int l = 1; l < levels; ++l) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, l - 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, l - 1);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, l);
        glViewport(0, 0, padded.x >> l, padded.y >> l);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer));
    glBindVertexArray(GLuint(vertexArray));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    return true;
}

void FadePyramid::releaseGl() {
    if (texture_) glDeleteTextures(1, &texture_);
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
    texture_ = fbo_ = vao_ = 0;
    size_ = glm::ivec2(0);
    levels_ = 0;
}

}  // namespace fx
