#pragma once
// The engine's single way to see GL: glad's 3.3 core loader (with KHR_debug, ARB_timer_query,
// ARB_clip_control).
#include <glad/gl.h>

#include <string>

namespace cube::gl {

/// GL errors and KHR_debug messages of severity HIGH/MEDIUM seen since start-up. Tests assert
/// this stays 0; debug builds also print each message.
int errorCount();
/// Last such message (empty if none).
std::string lastError();
/// Drains glGetError() and adds what it finds to errorCount(); returns how many were pending.
int checkErrors(const char* where);
void resetErrorCount();
/// True when the context has KHR_debug (groups, labels, callback).
bool hasDebug();
/// Waits for every GL command issued so far (frame timing with a CPU clock).
void finish();
/// True when the context can map clip z to [0, 1] (GL 4.5 or ARB_clip_control): what
/// reversed-Z in a float depth buffer needs to keep its precision.
bool hasClipControl();
/// Sets the context's clip-space depth range: [0, 1] (`zeroToOne`, for reversed-Z) or GL's
/// default [-1, 1]. False (nothing changed) when zeroToOne is asked of a context without
/// clip control.
bool setClipDepthZeroToOne(bool zeroToOne);

/// Creates a vertex array and an array buffer whose attribute 0 reads tightly packed vec2s (2D
/// positions), and leaves both bound.
void createVec2VertexArray(GLuint* vao, GLuint* vbo);
/// Deletes a vertex array and the buffers it reads (an index buffer `ibo` too); 0s are skipped.
void deleteVertexArray(GLuint vao, GLuint vbo, GLuint ibo = 0);

/// Base of the classes that own GL objects or GL state (a program, buffers, a pushed debug
/// group): a copy would delete or pop them twice, so none of them can be copied (nor moved).
class NonCopyable {
public:
    NonCopyable(const NonCopyable&) = delete;
    NonCopyable& operator=(const NonCopyable&) = delete;

protected:
    NonCopyable() = default;
    ~NonCopyable() = default;
};

/// RAII GL debug group: the pass, bucket or view name shows in debuggers (RenderDoc, apitrace).
class DebugGroup : NonCopyable {
public:
    explicit DebugGroup(const char* name);
    ~DebugGroup();
};

}  // namespace cube::gl
