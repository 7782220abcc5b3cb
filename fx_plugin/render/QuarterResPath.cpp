#include "QuarterResPath.h"

#include "render/PrivateGl.h"

#include "ShaderLoader.h"

namespace fx {
namespace {

void bindTextureUnit(int unit, GLuint texture) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindSampler(GLuint(unit), 0);
}

void fullscreenState() {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace

TargetDesc QuarterResPath::depthTargetDesc() {
    TargetDesc d;
    d.scale = 0.5f;
    d.format = TargetFormat::R32F;
    d.linearFilter = false;
    return d;
}

TargetDesc QuarterResPath::colorTargetDesc() {
    TargetDesc d;
    d.scale = 0.5f;
    d.format = TargetFormat::RGBA16F;
    d.linearFilter = true;
    return d;
}

QuarterResPath::~QuarterResPath() {
    if (downsample_) glDeleteProgram(downsample_);
    if (composite_) glDeleteProgram(composite_);
    if (emptyVao_) glDeleteVertexArrays(1, &emptyVao_);
}

void QuarterResPath::build(const std::string& shaderDir, std::vector<std::string>* errors) {
    std::string error;
    if (!downsample_) {
        downsample_ = buildProgram(shaderDir, "vs_particles_fullscreen.glsl",
                                   "fs_particles_depth_downsample.glsl", "", &error);
        if (downsample_) {
            downsampleDepthLoc_ = glGetUniformLocation(downsample_, "uSceneDepth");
        } else {
            errors->push_back(error);
        }
    }
    if (!composite_) {
        composite_ = buildProgram(shaderDir, "vs_particles_fullscreen.glsl",
                                  "fs_particles_composite.glsl", "", &error);
        if (composite_) {
            halfColorLoc_ = glGetUniformLocation(composite_, "uHalfColor");
            halfDepthLoc_ = glGetUniformLocation(composite_, "uHalfDepth");
            sceneDepthLoc_ = glGetUniformLocation(composite_, "uSceneDepth");
            bilinearLoc_ = glGetUniformLocation(composite_, "uBilinear");
            thresholdLoc_ = glGetUniformLocation(composite_, "uDepthThreshold");
        } else {
            errors->push_back(error);
        }
    }
    if (!emptyVao_) glGenVertexArrays(1, &emptyVao_);  // core profile draws need a VAO
}

void QuarterResPath::downsampleDepth(PassContext& ctx, Target sceneDepth, Target halfDepth) {
    ctx.bindForDraw(halfDepth);
    fullscreenState();
    glDisable(GL_BLEND);
    glUseProgram(downsample_);
    bindTextureUnit(0, ctx.texture(sceneDepth, 0).name);
    glUniform1i(downsampleDepthLoc_, 0);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void QuarterResPath::beginQuarter(PassContext& ctx, Target halfColor) {
    ctx.bindForDraw(halfColor);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

void QuarterResPath::composite(PassContext& ctx, Target sceneColor, Target halfColor,
                               Target halfDepth, Target sceneDepth, bool bilinear) {
    ctx.bindForDraw(sceneColor);
    fullscreenState();
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(composite_);
    bindTextureUnit(0, ctx.texture(halfColor, 0).name);
    bindTextureUnit(1, ctx.texture(halfDepth, 0).name);
    bindTextureUnit(2, ctx.texture(sceneDepth, 0).name);
    glUniform1i(halfColorLoc_, 0);
    glUniform1i(halfDepthLoc_, 1);
    glUniform1i(sceneDepthLoc_, 2);
    glUniform1i(bilinearLoc_, bilinear ? 1 : 0);
    glUniform1f(thresholdLoc_, kDepthThreshold);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace fx
