#pragma once
// Small GL helpers for the rtt tests: inline test shaders (kept here rather than in shaders/
// because they exist only to put known values into targets) and a quad drawer.
#include <gtest/gtest.h>

#include <string>

#include "gl/Gl.h"
#include "rtt/RenderTargetDesc.h"

namespace cube::rtt::testutil {

/// Draws an axis-aligned quad (NDC rect x0,y0,x1,y1 at NDC depth z) writing uColor0..3 to
/// fragment outputs 0..3.
constexpr const char* kVsQuad = R"(#version 330 core
uniform vec4 uRect;
uniform float uZ;
void main() {
    vec2 p = vec2((gl_VertexID & 1) != 0 ? uRect.z : uRect.x, (gl_VertexID & 2) != 0 ? uRect.w : uRect.y);
    gl_Position = vec4(p, uZ, 1.0);
}
)";
constexpr const char* kFsConstant = R"(#version 330 core
uniform vec4 uColor0;
uniform vec4 uColor1;
uniform vec4 uColor2;
uniform vec4 uColor3;
layout(location = 0) out vec4 o0;
layout(location = 1) out vec4 o1;
layout(location = 2) out vec4 o2;
layout(location = 3) out vec4 o3;
void main() { o0 = uColor0; o1 = uColor1; o2 = uColor2; o3 = uColor3; }
)";
/// Copies a depth texture texel by texel into output 0's red channel.
constexpr const char* kFsCopyDepth = R"(#version 330 core
uniform sampler2D uDepth;
layout(location = 0) out vec4 o0;
void main() { o0 = vec4(texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r, 0.0, 0.0, 1.0); }
)";

inline GLuint compileShader(GLenum stage, const char* source) {
    GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        ADD_FAILURE() << "shader compile failed: " << log;
    }
    return s;
}

/// An inline program plus the empty VAO core profile needs for attribute-less draws.
class TestProgram {
public:
    TestProgram(const char* vs, const char* fs) {
        GLuint v = compileShader(GL_VERTEX_SHADER, vs), f = compileShader(GL_FRAGMENT_SHADER, fs);
        program_ = glCreateProgram();
        glAttachShader(program_, v);
        glAttachShader(program_, f);
        glLinkProgram(program_);
        glDeleteShader(v);
        glDeleteShader(f);
        GLint ok = 0;
        glGetProgramiv(program_, GL_LINK_STATUS, &ok);
        if (!ok) ADD_FAILURE() << "program link failed";
        glGenVertexArrays(1, &vao_);
    }
    ~TestProgram() {
        glDeleteVertexArrays(1, &vao_);
        glDeleteProgram(program_);
    }
    TestProgram(const TestProgram&) = delete;
    TestProgram& operator=(const TestProgram&) = delete;

    GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }
    void set(const char* name, float x, float y, float z, float w) {
        glUseProgram(program_);
        glUniform4f(uniform(name), x, y, z, w);
    }
    void set(const char* name, float x) {
        glUseProgram(program_);
        glUniform1f(uniform(name), x);
    }
    void setInt(const char* name, int x) {
        glUseProgram(program_);
        glUniform1i(uniform(name), x);
    }
    /// Draws the quad (kVsQuad); leaves program and VAO unbound afterwards.
    void drawQuad(float x0 = -1.0f, float y0 = -1.0f, float x1 = 1.0f, float y1 = 1.0f, float z = 0.0f) {
        glUseProgram(program_);
        glUniform4f(uniform("uRect"), x0, y0, x1, y1);
        glUniform1f(uniform("uZ"), z);
        glBindVertexArray(vao_);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glBindVertexArray(0);
        glUseProgram(0);
    }

private:
    GLuint program_ = 0;
    GLuint vao_ = 0;
};

/// An absolute-size descriptor with one colour attachment and an optional depth.
inline RenderTargetDesc fixed(int w, int h, ColorFormat c = ColorFormat::RGBA8, DepthFormat d = DepthFormat::None) {
    RenderTargetDesc desc;
    desc.width = w;
    desc.height = h;
    desc.color[0] = c;
    desc.depth = d;
    return desc;
}

}  // namespace cube::rtt::testutil
