#pragma once
// A scoped snapshot of the GL state a draw outside the frame graph may change (the benchmark
// probes draw between frames): they put back every state they touch, so the next frame sees what
// the engine left.
#include <string>

#include "gl/Gl.h"

namespace cube {

/// Saves, and restores on destruction: current program, VAO, GL_ARRAY_BUFFER, active texture
/// unit and its GL_TEXTURE_2D binding (unit 0 after restore is what it was), blend enable,
/// functions and equations, depth test / function / write mask, face culling, scissor test.
/// Framebuffer bindings and the viewport are rtt::ScopedTargetBinding's job.
class ScopedGlState {
public:
    ScopedGlState();
    ~ScopedGlState();
    ScopedGlState(const ScopedGlState&) = delete;
    ScopedGlState& operator=(const ScopedGlState&) = delete;

private:
    GLint program_ = 0, vao_ = 0, arrayBuffer_ = 0, activeTexture_ = 0, texture0_ = 0;
    GLint blendSrcRgb_ = 0, blendDstRgb_ = 0, blendSrcA_ = 0, blendDstA_ = 0, blendEqRgb_ = 0, blendEqA_ = 0;
    GLint depthFunc_ = 0;
    GLboolean depthMask_ = GL_TRUE, blend_ = GL_FALSE, depthTest_ = GL_FALSE, cull_ = GL_FALSE,
              scissor_ = GL_FALSE;
};


}  // namespace cube
