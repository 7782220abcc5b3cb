#pragma once
// fxbench's own GL: a state guard and a program built from embedded source. The harness's probes
// (depth for the edge mask, the fill limit) draw between frames, outside the frame graph, and
// put back every GL state they touch so the next RenderFrame sees what the engine left.
#include <string>

#include "gl/Gl.h"

namespace fxbench {

/// Saves, and restores on destruction: current program, VAO, GL_ARRAY_BUFFER, active texture
/// unit and its GL_TEXTURE_2D binding (unit 0 after restore is what it was), blend enable,
/// functions and equations, depth test / function / write mask, face culling, scissor test.
/// Framebuffer bindings and the viewport are rtt::ScopedTargetBinding's job.
class GlStateGuard {
public:
    GlStateGuard();
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    GLint program_ = 0, vao_ = 0, arrayBuffer_ = 0, activeTexture_ = 0, texture0_ = 0;
    GLint blendSrcRgb_ = 0, blendDstRgb_ = 0, blendSrcA_ = 0, blendDstA_ = 0, blendEqRgb_ = 0, blendEqA_ = 0;
    GLint depthFunc_ = 0;
    GLboolean depthMask_ = GL_TRUE, blend_ = GL_FALSE, depthTest_ = GL_FALSE, cull_ = GL_FALSE,
              scissor_ = GL_FALSE;
};

/// A program from GLSL 3.30 core sources embedded in fxbench. Id 0 (draws nothing) on failure,
/// with the compile/link log in `error`.
GLuint buildProgram(const char* vertexSource, const char* fragmentSource, std::string* error);

}  // namespace fxbench
