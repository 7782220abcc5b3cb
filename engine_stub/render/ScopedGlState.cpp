#include "render/ScopedGlState.h"

namespace cube {

ScopedGlState::ScopedGlState() {
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture0_);
    blend_ = glIsEnabled(GL_BLEND);
    glGetIntegerv(GL_BLEND_SRC_RGB, &blendSrcRgb_);
    glGetIntegerv(GL_BLEND_DST_RGB, &blendDstRgb_);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendSrcA_);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blendDstA_);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blendEqRgb_);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blendEqA_);
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    cull_ = glIsEnabled(GL_CULL_FACE);
    scissor_ = glIsEnabled(GL_SCISSOR_TEST);
}

ScopedGlState::~ScopedGlState() {
    glUseProgram(GLuint(program_));
    glBindVertexArray(GLuint(vao_));
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(arrayBuffer_));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, GLuint(texture0_));
    glActiveTexture(GLenum(activeTexture_));
    (blend_ ? glEnable : glDisable)(GL_BLEND);
    glBlendFuncSeparate(GLenum(blendSrcRgb_), GLenum(blendDstRgb_), GLenum(blendSrcA_), GLenum(blendDstA_));
    glBlendEquationSeparate(GLenum(blendEqRgb_), GLenum(blendEqA_));
    (depthTest_ ? glEnable : glDisable)(GL_DEPTH_TEST);
    glDepthFunc(GLenum(depthFunc_));
    glDepthMask(depthMask_);
    (cull_ ? glEnable : glDisable)(GL_CULL_FACE);
    (scissor_ ? glEnable : glDisable)(GL_SCISSOR_TEST);
}

}  // namespace cube
