#include "fxbench_gl.h"

namespace fxbench {

GlStateGuard::GlStateGuard() {
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

GlStateGuard::~GlStateGuard() {
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

namespace {

GLuint compile(GLenum stage, const char* source, std::string* error) {
    const GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint ok = GL_FALSE;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        *error = std::string(stage == GL_VERTEX_SHADER ? "fxbench vertex shader: " : "fxbench fragment shader: ") + log;
        glDeleteShader(s);
        return 0;
    }
    return s;
}

}  // namespace

GLuint buildProgram(const char* vertexSource, const char* fragmentSource, std::string* error) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertexSource, error);
    if (!vs) return 0;
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentSource, error);
    if (!fs) {
        glDeleteShader(vs);
        return 0;
    }
    const GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetProgramInfoLog(p, sizeof log, nullptr, log);
        *error = std::string("fxbench program link: ") + log;
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

}  // namespace fxbench
