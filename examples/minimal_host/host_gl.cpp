// The host's GL side, through its own global glad.
#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "host.h"

namespace {

GLuint g_program[2] = {0, 0};  // [0] colour, [1] linear depth
GLuint g_vao = 0, g_vbo = 0;
int g_vertexCount = 0;

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 uView, uProj;
out vec3 vNormal;
out float vDepth;
void main() {
    vec4 v = uView * vec4(aPos, 1.0);
    vDepth = -v.z;
    vNormal = aNormal;
    gl_Position = uProj * v;
})";
const char* kColour = R"(#version 330 core
in vec3 vNormal;
in float vDepth;
out vec4 oColor;
void main() {
    float light = 0.35 + 0.5 * max(dot(normalize(vNormal), normalize(vec3(0.4, 1.0, 0.3))), 0.0);
    oColor = vec4(vec3(0.32, 0.33, 0.36) * light, 1.0);
})";
const char* kDepth = R"(#version 330 core
in vec3 vNormal;
in float vDepth;
out vec4 oDepth;
void main() { oDepth = vec4(vDepth); })";

GLuint compile(GLenum stage, const char* text) {
    GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        std::fprintf(stderr, "minimal_host: shader: %s\n", log);
    }
    return s;
}

GLuint link(const char* fs) {
    GLuint p = glCreateProgram();
    GLuint v = compile(GL_VERTEX_SHADER, kVertex), f = compile(GL_FRAGMENT_SHADER, fs);
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    return p;
}

void quad(std::vector<float>& out, glm::vec3 o, glm::vec3 u, glm::vec3 v) {
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    const glm::vec3 c[6] = {o, o + u, o + u + v, o, o + u + v, o + v};
    for (const glm::vec3& p : c) out.insert(out.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
}

}  // namespace

bool loadHostGl() {
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(procAddress));
    if (version == 0 || GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) return false;
    g_program[0] = link(kColour);
    g_program[1] = link(kDepth);
    std::vector<float> v;
    quad(v, glm::vec3(-40.0f, 0.0f, 40.0f), glm::vec3(80.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -80.0f));
    quad(v, glm::vec3(-20.0f, 0.0f, -4.0f), glm::vec3(40.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    g_vertexCount = int(v.size() / 6);
    glGenVertexArrays(1, &g_vao);
    glGenBuffers(1, &g_vbo);
    glBindVertexArray(g_vao);
    glBindBuffer(GL_ARRAY_BUFFER, g_vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);
    return true;
}

HostTarget makeTarget(int width, int height, bool linearDepth, uint32_t sharedDepth) {
    HostTarget t;
    t.width = width;
    t.height = height;
    t.linearDepth = linearDepth;
    glGenTextures(1, &t.color);
    glBindTexture(GL_TEXTURE_2D, t.color);
    glTexImage2D(GL_TEXTURE_2D, 0, linearDepth ? GL_R32F : GL_RGBA8, width, height, 0,
                 linearDepth ? GL_RED : GL_RGBA, linearDepth ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (sharedDepth) {
        t.depth = sharedDepth;
    } else {
        glGenRenderbuffers(1, &t.depth);
        glBindRenderbuffer(GL_RENDERBUFFER, t.depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    }
    glGenFramebuffers(1, &t.fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return t;
}

void deleteTarget(HostTarget& t) {
    glDeleteFramebuffers(1, &t.fbo);
    glDeleteTextures(1, &t.color);
    glDeleteRenderbuffers(1, &t.depth);
    t = HostTarget{};
}

void bindTarget(const HostTarget& t) {
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
    glViewport(0, 0, t.width, t.height);
}

void drawScene(const HostTarget& t, const glm::mat4& view, const glm::mat4& proj) {
    bindTarget(t);
    // Where nothing is drawn the linear depth is "infinitely far" (the plugin also accepts 0).
    const float bg = t.linearDepth ? 1e30f : 0.0f;
    if (t.linearDepth) {
        glClearColor(bg, bg, bg, bg);
    } else {
        glClearColor(0.45f, 0.55f, 0.7f, 1.0f);
    }
    glClearDepth(1.0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const GLuint p = g_program[t.linearDepth ? 1 : 0];
    glUseProgram(p);
    glUniformMatrix4fv(glGetUniformLocation(p, "uView"), 1, GL_FALSE, &view[0][0]);
    glUniformMatrix4fv(glGetUniformLocation(p, "uProj"), 1, GL_FALSE, &proj[0][0]);
    glBindVertexArray(g_vao);
    glDrawArrays(GL_TRIANGLES, 0, g_vertexCount);
    glBindVertexArray(0);
    glUseProgram(0);
}

std::string glStateFingerprint() {
    GLint v[16] = {};
    glGetIntegerv(GL_CURRENT_PROGRAM, &v[0]);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &v[1]);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &v[2]);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &v[3]);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &v[4]);
    glGetIntegerv(GL_VIEWPORT, &v[5]);  // 4 values
    glGetIntegerv(GL_DEPTH_FUNC, &v[9]);
    glGetIntegerv(GL_BLEND_SRC_RGB, &v[10]);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &v[11]);
    v[12] = glIsEnabled(GL_BLEND);
    v[13] = glIsEnabled(GL_DEPTH_TEST);
    GLboolean mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    v[14] = mask;
    std::string s;
    for (GLint x : v) s += std::to_string(x) + ",";
    return s;
}

int glErrors() {
    int n = 0;
    while (glGetError() != GL_NO_ERROR && n < 100) ++n;
    return n;
}

std::vector<uint8_t> readPixels(const HostTarget& t) {
    std::vector<uint8_t> rows(size_t(t.width) * size_t(t.height) * 4), flipped(rows.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, t.fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    const size_t stride = size_t(t.width) * 4;
    for (int y = 0; y < t.height; ++y) {  // GL rows come bottom-up; PNG wants top-down
        std::copy_n(&rows[size_t(t.height - 1 - y) * stride], stride, &flipped[size_t(y) * stride]);
    }
    return flipped;
}
