#include <cstdio>
#include <cstring>

#include "gl/Gl.h"
#include "platform/Platform.h"

namespace cube {

namespace {
int g_errorCount = 0;
std::string g_lastError;
bool g_hasDebug = false;

void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                             const GLchar* message, const void*) {
    // Compile errors arrive through the info log with file:line (gl/Program.cpp); the driver's
    // copy of them is not an API error.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION || severity == GL_DEBUG_SEVERITY_LOW) return;
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
    // Performance remarks are advice, not errors.
    if (type == GL_DEBUG_TYPE_PERFORMANCE || type == GL_DEBUG_TYPE_OTHER) return;
    ++g_errorCount;
    g_lastError = message ? message : "";
    std::fprintf(stderr, "GL debug [id %u]: %s\n", id, g_lastError.c_str());
}
}  // namespace

std::string glRendererString() {
    const GLubyte* r = glGetString(GL_RENDERER);
    return r ? reinterpret_cast<const char*>(r) : "unknown";
}

bool loadGL(GetProcFn getProc, std::string* error) {
    int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProc));
    if (version == 0) {
        *error = "GL: the loader found no OpenGL entry points";
        return false;
    }
    if (GLAD_VERSION_MAJOR(version) < 3 ||
        (GLAD_VERSION_MAJOR(version) == 3 && GLAD_VERSION_MINOR(version) < 3)) {
        *error = "GL: need OpenGL 3.3 core, the context offers " +
                 std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                 std::to_string(GLAD_VERSION_MINOR(version));
        return false;
    }
    g_hasDebug = GLAD_GL_KHR_debug != 0;
    if (g_hasDebug) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(onDebugMessage, nullptr);
    }
    while (glGetError() != GL_NO_ERROR) {}
    return true;
}

namespace gl {

int errorCount() { return g_errorCount; }
std::string lastError() { return g_lastError; }
void resetErrorCount() { g_errorCount = 0; g_lastError.clear(); }
bool hasDebug() { return g_hasDebug; }
void finish() { glFinish(); }

bool hasClipControl() { return GLAD_GL_ARB_clip_control && glClipControl != nullptr; }

bool setClipDepthZeroToOne(bool zeroToOne) {
    if (!hasClipControl()) return !zeroToOne;
    glClipControl(GL_LOWER_LEFT, zeroToOne ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    return true;
}

int checkErrors(const char* where) {
    int n = 0;
    for (GLenum e = glGetError(); e != GL_NO_ERROR && n < 32; e = glGetError()) {
        ++n;
        ++g_errorCount;
        char buf[128];
        std::snprintf(buf, sizeof buf, "glGetError 0x%04X at %s", e, where);
        g_lastError = buf;
        std::fprintf(stderr, "%s\n", buf);
    }
    return n;
}

void createVec2VertexArray(GLuint* vao, GLuint* vbo) {
    glGenVertexArrays(1, vao);
    glGenBuffers(1, vbo);
    glBindVertexArray(*vao);
    glBindBuffer(GL_ARRAY_BUFFER, *vbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
}

void deleteVertexArray(GLuint vao, GLuint vbo, GLuint ibo) {
    if (ibo) glDeleteBuffers(1, &ibo);
    if (vbo) glDeleteBuffers(1, &vbo);
    if (vao) glDeleteVertexArrays(1, &vao);
}

DebugGroup::DebugGroup(const char* name) {
    if (g_hasDebug) glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}
DebugGroup::~DebugGroup() {
    if (g_hasDebug) glPopDebugGroup();
}

}  // namespace gl
}  // namespace cube
