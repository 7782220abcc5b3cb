// GL loading (glad, through the OSMesa proc-address function), error counting, state snapshots
// and image helpers for the fx_host tests. Never includes GL/osmesa.h.
#include <glad/gl.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <unistd.h>

#include "FxTestHost.h"
#include "render/PrivateGlLoader.h"

namespace fxtest {

namespace {

int g_errors = 0;
std::string g_log;
bool g_khrDebug = false;
bool g_allowCompilerMessages = false;
int g_compilerMessages = 0;

void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                                 const GLchar* message, const void*) {
    if (severity != GL_DEBUG_SEVERITY_HIGH && severity != GL_DEBUG_SEVERITY_MEDIUM) return;
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER && g_allowCompilerMessages) {
        ++g_compilerMessages;  // a test that breaks a shader on purpose
        return;
    }
    ++g_errors;
    char head[64];
    std::snprintf(head, sizeof head, "KHR_debug [id %u]: ", id);
    g_log += head;
    g_log += message ? message : "";
    g_log += '\n';
}


// The plugin's glFlush, counted (pluginFlushes): its GL table gets this wrapper in its place.
int g_pluginFlushes = 0;
bool g_countingFlushes = false;
void(GLAD_API_PTR* g_realFlush)() = nullptr;
void GLAD_API_PTR countingFlush() {
    ++g_pluginFlushes;
    g_realFlush();
}

// The entry points the plugin's private GL table is filled from (ensureGl, TestHostAdapter).
void* procAddressAsPointer(const char* name) {
    void* p = reinterpret_cast<void*>(osMesaProcAddress()(name));
    if (p && std::string(name) == "glFlush") {
        g_realFlush = reinterpret_cast<void(GLAD_API_PTR*)()>(p);
        g_countingFlushes = true;
        return reinterpret_cast<void*>(&countingFlush);
    }
    return p;
}

}  // namespace

void* TestHostAdapter::getProcAddress(const char* name) { return procAddressAsPointer(name); }

int pluginFlushes() { return g_countingFlushes ? g_pluginFlushes : -1; }

bool ensureGl(std::string* error) {
    static bool loaded = false;
    if (loaded) return true;
    if (!createOsMesaContext(error)) return false;
    const int version = gladLoadGL(osMesaProcAddress());
    if (version == 0 || GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
        *error = "glad: no OpenGL 3.3 core entry points";
        return false;
    }
    // The plugin's own (renamed) GL table, for tests that call plugin internals directly before
    // any plugin instance has loaded it through a host.
    if (!fx::loadPrivateGl(&procAddressAsPointer, error)) return false;
    g_khrDebug = GLAD_GL_KHR_debug != 0;
    if (g_khrDebug) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(onDebugMessage, nullptr);
    }
    while (glGetError() != GL_NO_ERROR) {}
    loaded = true;
    return true;
}

int glErrorCount() { return g_errors; }
std::string glErrorLog() { return g_log; }
bool hasKhrDebug() { return g_khrDebug; }

void resetGlErrors() {
    while (glGetError() != GL_NO_ERROR) {}
    g_errors = 0;
    g_log.clear();
    g_allowCompilerMessages = false;
    g_compilerMessages = 0;
}

void allowShaderCompilerMessages() { g_allowCompilerMessages = true; }
int shaderCompilerMessages() { return g_compilerMessages; }

int drainGlErrors(const char* where) {
    int n = 0;
    for (GLenum e = glGetError(); e != GL_NO_ERROR && n < 16; e = glGetError()) {
        ++n;
        ++g_errors;
        char buf[128];
        std::snprintf(buf, sizeof buf, "glGetError 0x%04X after %s\n", e, where);
        g_log += buf;
    }
    return n;
}

// ---- state ------------------------------------------------------------------------------------

namespace {

int getInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

// The snapshot's single values: the name diff() gives, the field, the GL enum and whether GL
// reports it through glIsEnabled (else glGetIntegerv). captureGlState and diff both go through it.
struct ScalarState {
    const char* name;
    int GlStateSnapshot::*field;
    GLenum pname;
    bool isEnabled;
};
const ScalarState kScalars[] = {
    {"program", &GlStateSnapshot::program, GL_CURRENT_PROGRAM, false},
    {"vertexArray", &GlStateSnapshot::vertexArray, GL_VERTEX_ARRAY_BINDING, false},
    {"arrayBuffer", &GlStateSnapshot::arrayBuffer, GL_ARRAY_BUFFER_BINDING, false},
    {"elementBuffer", &GlStateSnapshot::elementBuffer, GL_ELEMENT_ARRAY_BUFFER_BINDING, false},
    {"activeTexture", &GlStateSnapshot::activeTexture, GL_ACTIVE_TEXTURE, false},
    {"blend", &GlStateSnapshot::blend, GL_BLEND, true},
    {"blendSrcRgb", &GlStateSnapshot::blendSrcRgb, GL_BLEND_SRC_RGB, false},
    {"blendDstRgb", &GlStateSnapshot::blendDstRgb, GL_BLEND_DST_RGB, false},
    {"blendSrcAlpha", &GlStateSnapshot::blendSrcAlpha, GL_BLEND_SRC_ALPHA, false},
    {"blendDstAlpha", &GlStateSnapshot::blendDstAlpha, GL_BLEND_DST_ALPHA, false},
    {"blendEqRgb", &GlStateSnapshot::blendEqRgb, GL_BLEND_EQUATION_RGB, false},
    {"blendEqAlpha", &GlStateSnapshot::blendEqAlpha, GL_BLEND_EQUATION_ALPHA, false},
    {"depthTest", &GlStateSnapshot::depthTest, GL_DEPTH_TEST, true},
    {"depthFunc", &GlStateSnapshot::depthFunc, GL_DEPTH_FUNC, false},
    {"depthMask", &GlStateSnapshot::depthMask, GL_DEPTH_WRITEMASK, false},
    {"cullFace", &GlStateSnapshot::cullFace, GL_CULL_FACE, true},
    {"scissorTest", &GlStateSnapshot::scissorTest, GL_SCISSOR_TEST, true},
    {"stencilTest", &GlStateSnapshot::stencilTest, GL_STENCIL_TEST, true},
    {"drawFramebuffer", &GlStateSnapshot::drawFramebuffer, GL_DRAW_FRAMEBUFFER_BINDING, false},
    {"readFramebuffer", &GlStateSnapshot::readFramebuffer, GL_READ_FRAMEBUFFER_BINDING, false},
    {"unpackBuffer", &GlStateSnapshot::unpackBuffer, GL_PIXEL_UNPACK_BUFFER_BINDING, false},
    {"unpackAlignment", &GlStateSnapshot::unpackAlignment, GL_UNPACK_ALIGNMENT, false},
};

}  // namespace

GlStateSnapshot captureGlState() {
    GlStateSnapshot s;
    for (const ScalarState& k : kScalars) s.*k.field = k.isEnabled ? int(glIsEnabled(k.pname)) : getInt(k.pname);
    for (int i = 0; i < 8; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        s.texture2D[i] = getInt(GL_TEXTURE_BINDING_2D);
        s.sampler[i] = getInt(GL_SAMPLER_BINDING);
    }
    glActiveTexture(GLenum(s.activeTexture));
    GLboolean mask[4] = {};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    for (int i = 0; i < 4; ++i) s.colorMask[i] = mask[i];
    glGetIntegerv(GL_VIEWPORT, s.viewport);
    glGetIntegerv(GL_SCISSOR_BOX, s.scissorBox);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, s.clearColor);
    return s;
}

std::string GlStateSnapshot::diff(const GlStateSnapshot& after) const {
    std::string out;
    auto cmp = [&out](const char* name, double a, double b) {
        if (a != b) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "%s: %g -> %g; ", name, a, b);
            out += buf;
        }
    };
    for (const ScalarState& k : kScalars) cmp(k.name, this->*k.field, after.*k.field);
    for (int i = 0; i < 8; ++i) {
        const std::string t = "texture2D[" + std::to_string(i) + "]";
        const std::string s = "sampler[" + std::to_string(i) + "]";
        cmp(t.c_str(), texture2D[i], after.texture2D[i]);
        cmp(s.c_str(), sampler[i], after.sampler[i]);
    }
    for (int i = 0; i < 4; ++i) cmp("colorMask", colorMask[i], after.colorMask[i]);
    for (int i = 0; i < 4; ++i) cmp("viewport", viewport[i], after.viewport[i]);
    for (int i = 0; i < 4; ++i) cmp("scissorBox", scissorBox[i], after.scissorBox[i]);
    for (int i = 0; i < 4; ++i) cmp("clearColor", clearColor[i], after.clearColor[i]);
    return out;
}

uint32_t compileTestProgram(const char* vs, const char* fs) {
    GLuint v = glCreateShader(GL_VERTEX_SHADER), f = glCreateShader(GL_FRAGMENT_SHADER);
    glShaderSource(v, 1, &vs, nullptr);
    glShaderSource(f, 1, &fs, nullptr);
    glCompileShader(v);
    glCompileShader(f);
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    assert(ok && "fx_host test shader failed to link");
    glDeleteShader(v);
    glDeleteShader(f);
    return p;
}

void applyDirtyHostState() {
    struct Objects {
        GLuint program = 0, vao = 0, vbo = 0, ebo = 0, pbo = 0, fboDraw = 0, fboRead = 0;
        GLuint textures[8] = {};
        GLuint samplers[2] = {};
    };
    static Objects o;
    if (!o.program) {
        const char* vs = "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n";
        const char* fs = "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
        o.program = compileTestProgram(vs, fs);
        glGenVertexArrays(1, &o.vao);
        glGenBuffers(1, &o.vbo);
        glGenBuffers(1, &o.ebo);
        glGenBuffers(1, &o.pbo);
        glBindVertexArray(o.vao);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, o.ebo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, 64, nullptr, GL_STATIC_DRAW);
        glBindVertexArray(0);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, o.pbo);
        glBufferData(GL_PIXEL_UNPACK_BUFFER, 16, nullptr, GL_STREAM_DRAW);  // too small for any upload
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glGenTextures(8, o.textures);
        for (GLuint t : o.textures) {
            glBindTexture(GL_TEXTURE_2D, t);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        }
        glGenSamplers(2, o.samplers);
        glSamplerParameteri(o.samplers[0], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glSamplerParameteri(o.samplers[1], GL_TEXTURE_WRAP_S, GL_REPEAT);
        glGenFramebuffers(1, &o.fboDraw);
        glGenFramebuffers(1, &o.fboRead);
        glBindFramebuffer(GL_FRAMEBUFFER, o.fboDraw);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, o.textures[6], 0);
        glBindFramebuffer(GL_FRAMEBUFFER, o.fboRead);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, o.textures[7], 0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    glUseProgram(o.program);
    glBindVertexArray(o.vao);
    glBindBuffer(GL_ARRAY_BUFFER, o.vbo);
    for (int i = 0; i < 8; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, o.textures[i]);
    }
    glBindSampler(0, o.samplers[0]);
    glBindSampler(2, o.samplers[1]);
    glActiveTexture(GL_TEXTURE5);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_MAX);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glEnable(GL_SCISSOR_TEST);
    glScissor(3, 5, 7, 11);
    glEnable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glViewport(1, 2, 33, 44);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, o.fboDraw);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, o.fboRead);
    glClearColor(0.25f, 0.5f, 0.75f, 0.125f);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, o.pbo);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

void applyDefaultHostState() {
    glUseProgram(0);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    for (int i = 0; i < 8; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindSampler(GLuint(i), 0);
    }
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

// ---- images -----------------------------------------------------------------------------------

HostTarget::HostTarget(int w, int h, uint32_t depthFormat) : width(w), height(h) {
    glGenTextures(1, &colour);
    glBindTexture(GL_TEXTURE_2D, colour);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    if (depthFormat) {
        glGenTextures(1, &depth);
        glBindTexture(GL_TEXTURE_2D, depth);
        glTexImage2D(GL_TEXTURE_2D, 0, GLint(depthFormat), w, h, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    if (depth) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

HostTarget::~HostTarget() {
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &colour);
    if (depth) glDeleteTextures(1, &depth);
}

Image readFramebuffer(uint32_t framebuffer, int width, int height) {
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(size_t(width) * size_t(height) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(framebuffer));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return img;
}

bool writePng(const std::string& path, const Image& image) {
    const size_t row = size_t(image.width) * 4;
    std::vector<uint8_t> flipped(image.rgba.size());
    for (int y = 0; y < image.height; ++y) {
        std::copy_n(&image.rgba[size_t(image.height - 1 - y) * row], row, &flipped[size_t(y) * row]);
    }
    return stbi_write_png(path.c_str(), image.width, image.height, 4, flipped.data(), int(row)) != 0;
}

double psnr(const Image& a, const Image& b, const std::vector<uint8_t>* mask) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t p = 0; p < size_t(a.width) * size_t(a.height); ++p) {
        if (mask && !(*mask)[p]) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.rgba[p * 4 + size_t(c)]) - double(b.rgba[p * 4 + size_t(c)]);
            sum += d * d;
            ++n;
        }
    }
    if (n == 0 || sum == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(255.0 * 255.0 / (sum / double(n)));
}

int maxAbsDiff(const Image& a, const Image& b) {
    int worst = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if ((i & 3) == 3) continue;
        worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
    }
    return worst;
}

std::string scratchDir() {
    // Removed again when the test program exits.
    struct Scratch {
        std::string dir;
        ~Scratch() {
            std::error_code ignored;
            // FX_HOST_KEEP_IMAGES=1 keeps the pictures the tests wrote, for looking at them.
            const char* keep = std::getenv("FX_HOST_KEEP_IMAGES");
            if (keep && std::string(keep) == "1") return;
            if (!dir.empty()) std::filesystem::remove_all(dir, ignored);
        }
    };
    static Scratch scratch;
    if (scratch.dir.empty()) {
        char tmpl[] = "/tmp/fx_host_XXXXXX";
        if (const char* made = mkdtemp(tmpl)) scratch.dir = made;
    }
    return scratch.dir.empty() ? std::string("/tmp") : scratch.dir;
}

}  // namespace fxtest
