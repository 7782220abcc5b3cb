#include "render/PrivateGl.h"

#include <string>

#include "fx/HostAdapter.h"

namespace fx {
namespace {

bool g_loaded = false;

// Every entry point some path of the plugin calls, checked after each load: glad fills what the
// host hands out and leaves the rest null, and a null one would be called. Optional ones are not
// here: KHR_debug's groups and ARB_clip_control are switched off below when their functions are
// missing (the plugin labels no object). The compatibility-only ones the state guard pins in a
// compatibility context are needed only there.
struct Needed {
    const char* name;
    bool (*present)();
};
#define FX_NEEDED(f) Needed{#f, [] { return f != nullptr; }}
const Needed kCore[] = {
    FX_NEEDED(glActiveTexture), FX_NEEDED(glAttachShader), FX_NEEDED(glBindBuffer), FX_NEEDED(glBindFramebuffer),
    FX_NEEDED(glBindRenderbuffer), FX_NEEDED(glBindSampler), FX_NEEDED(glBindTexture), FX_NEEDED(glBindVertexArray),
    FX_NEEDED(glBlendColor), FX_NEEDED(glBlendEquation), FX_NEEDED(glBlendEquationSeparate), FX_NEEDED(glBlendFunc),
    FX_NEEDED(glBlendFuncSeparate), FX_NEEDED(glBlitFramebuffer), FX_NEEDED(glBufferData), FX_NEEDED(glBufferSubData),
    FX_NEEDED(glCheckFramebufferStatus), FX_NEEDED(glClampColor), FX_NEEDED(glClear), FX_NEEDED(glClearBufferfv),
    FX_NEEDED(glClearColor), FX_NEEDED(glColorMask), FX_NEEDED(glColorMaski), FX_NEEDED(glCompileShader),
    FX_NEEDED(glCopyTexSubImage2D), FX_NEEDED(glCreateProgram), FX_NEEDED(glCreateShader), FX_NEEDED(glDeleteBuffers),
    FX_NEEDED(glDeleteFramebuffers), FX_NEEDED(glDeleteProgram), FX_NEEDED(glDeleteRenderbuffers),
    FX_NEEDED(glDeleteSamplers), FX_NEEDED(glDeleteShader), FX_NEEDED(glDeleteTextures),
    FX_NEEDED(glDeleteVertexArrays), FX_NEEDED(glDepthFunc), FX_NEEDED(glDepthMask), FX_NEEDED(glDepthRange),
    FX_NEEDED(glDetachShader), FX_NEEDED(glDisable), FX_NEEDED(glDisablei), FX_NEEDED(glDrawArrays),
    FX_NEEDED(glDrawArraysInstanced), FX_NEEDED(glDrawBuffer), FX_NEEDED(glDrawBuffers), FX_NEEDED(glEnable),
    FX_NEEDED(glEnablei), FX_NEEDED(glEnableVertexAttribArray), FX_NEEDED(glFlush), FX_NEEDED(glFramebufferRenderbuffer),
    FX_NEEDED(glFramebufferTexture2D), FX_NEEDED(glGenBuffers), FX_NEEDED(glGenerateMipmap),
    FX_NEEDED(glGenFramebuffers), FX_NEEDED(glGenRenderbuffers), FX_NEEDED(glGenSamplers), FX_NEEDED(glGenTextures),
    FX_NEEDED(glGenVertexArrays), FX_NEEDED(glGetBooleani_v), FX_NEEDED(glGetBooleanv), FX_NEEDED(glGetDoublev),
    FX_NEEDED(glGetError), FX_NEEDED(glGetFloatv), FX_NEEDED(glGetFramebufferAttachmentParameteriv),
    FX_NEEDED(glGetIntegeri_v), FX_NEEDED(glGetIntegerv), FX_NEEDED(glGetProgramInfoLog), FX_NEEDED(glGetProgramiv),
    FX_NEEDED(glGetShaderInfoLog), FX_NEEDED(glGetShaderiv), FX_NEEDED(glGetString), FX_NEEDED(glGetStringi),
    FX_NEEDED(glGetTexLevelParameteriv), FX_NEEDED(glGetUniformLocation), FX_NEEDED(glHint), FX_NEEDED(glIsEnabled),
    FX_NEEDED(glIsEnabledi), FX_NEEDED(glIsTexture), FX_NEEDED(glLineWidth), FX_NEEDED(glLinkProgram),
    FX_NEEDED(glLogicOp), FX_NEEDED(glMapBufferRange), FX_NEEDED(glPixelStorei), FX_NEEDED(glPointSize), FX_NEEDED(glPolygonMode),
    FX_NEEDED(glPolygonOffset), FX_NEEDED(glPrimitiveRestartIndex), FX_NEEDED(glProvokingVertex),
    FX_NEEDED(glReadBuffer), FX_NEEDED(glReadPixels), FX_NEEDED(glRenderbufferStorage), FX_NEEDED(glSampleCoverage),
    FX_NEEDED(glSampleMaski), FX_NEEDED(glSamplerParameteri), FX_NEEDED(glScissor), FX_NEEDED(glShaderSource),
    FX_NEEDED(glStencilFuncSeparate), FX_NEEDED(glStencilMaskSeparate), FX_NEEDED(glStencilOpSeparate),
    FX_NEEDED(glTexImage2D), FX_NEEDED(glTexParameteri), FX_NEEDED(glTexSubImage2D), FX_NEEDED(glUniform1f), FX_NEEDED(glUnmapBuffer),
    FX_NEEDED(glUniform1fv), FX_NEEDED(glUniform1i), FX_NEEDED(glUniform2f), FX_NEEDED(glUniform2i),
    FX_NEEDED(glUniform3f), FX_NEEDED(glUniform4f), FX_NEEDED(glUniform4fv), FX_NEEDED(glUniform4i), FX_NEEDED(glUniformMatrix4fv),
    FX_NEEDED(glUseProgram), FX_NEEDED(glVertexAttribDivisor), FX_NEEDED(glVertexAttribPointer), FX_NEEDED(glViewport),
};
const Needed kCompatibility[] = {
    FX_NEEDED(glAlphaFunc), FX_NEEDED(glGetTexEnvfv), FX_NEEDED(glPixelTransferf), FX_NEEDED(glTexEnvf),
};
#undef FX_NEEDED

/// The needed entry points the host gave null for, as "glA, glB"; "" when none.
std::string missingNeeded() {
    std::string missing;
    auto check = [&](const Needed& n) {
        if (n.present()) return;
        if (!missing.empty()) missing += ", ";
        missing += n.name;
    };
    for (const Needed& n : kCore) check(n);
    GLint profile = 0;
    if (glGetIntegerv) glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    if (glGetIntegerv && (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
        for (const Needed& n : kCompatibility) check(n);
    }
    return missing;
}

/// Switches off the optional features whose entry points the host did not give; "" or what was
/// switched off, for one warning line.
std::string switchOffOptional() {
    std::string off;
    if (FXGLAD_GL_KHR_debug && (!glPushDebugGroup || !glPopDebugGroup)) {
        FXGLAD_GL_KHR_debug = 0;
        off += "KHR_debug (glPushDebugGroup/glPopDebugGroup null: no debug groups)";
    }
    if (FXGLAD_GL_ARB_clip_control && !glClipControl) {
        FXGLAD_GL_ARB_clip_control = 0;
        off += std::string(off.empty() ? "" : "; ") + "ARB_clip_control (glClipControl null: clip control not pinned)";
    }
    return off;
}

std::string g_switchedOff;

GLADapiproc throughHost(void* host, const char* name) {
    return reinterpret_cast<GLADapiproc>(static_cast<HostAdapter*>(host)->getProcAddress(name));
}

GLADapiproc throughFunction(void* fn, const char* name) {
    auto getProc = reinterpret_cast<void* (*)(const char*)>(fn);
    return reinterpret_cast<GLADapiproc>(getProc(name));
}

bool finish(int version, std::string* error) {
    if (version == 0 || !fxglad_glCreateShader) {
        // glad stops early when glGetStringi or glGetIntegerv is null: name what it did fill.
        const bool answered = fxglad_glGetString && fxglad_glGetString(GL_VERSION);  // a context is current
        const std::string missing = answered ? missingNeeded() : std::string();
        *error = missing.empty() ? "the host's getProcAddress gave no GL entry points (is its context current?)"
                                 : "the host's getProcAddress gave null for " + missing;
        return false;
    }
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
        *error = "the host's context offers OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) +
                 "." + std::to_string(GLAD_VERSION_MINOR(version)) + "; the plugin needs 3.3 core";
        return false;
    }
    const std::string missing = missingNeeded();
    if (!missing.empty()) {
        *error = "the host's getProcAddress gave null for " + missing + " (OpenGL " +
                 std::to_string(GLAD_VERSION_MAJOR(version)) + "." + std::to_string(GLAD_VERSION_MINOR(version)) +
                 " context); the plugin draws nothing without them";
        return false;
    }
    g_switchedOff = switchOffOptional();
    g_loaded = true;
    return true;
}

}  // namespace

bool loadPrivateGl(HostAdapter& host, std::string* error) {
    if (g_loaded) return true;
    // Ask once before handing the function to glad: glad reads glGetString first and would
    // crash on a null entry point.
    for (const char* first : {"glGetString", "glCreateShader"}) {
        if (!host.getProcAddress(first)) {
            *error = std::string("the host's getProcAddress gave null for ") + first + " (is its context current?)";
            return false;
        }
    }
    if (!finish(fxgladLoadGLUserPtr(throughHost, &host), error)) return false;
    if (!g_switchedOff.empty()) {
        host.log(LogLevel::Warning, ("fx: warning loadGl: switched off " + g_switchedOff).c_str());
    }
    return true;
}

bool loadPrivateGl(void* (*getProcAddress)(const char* name), std::string* error) {
    if (g_loaded) return true;
    if (!getProcAddress || !getProcAddress("glGetString")) return finish(0, error);
    return finish(fxgladLoadGLUserPtr(throughFunction, reinterpret_cast<void*>(getProcAddress)), error);
}

bool loadPrivateGlOrDiagnose(HostAdapter* host, Diagnostics* diagnostics, std::string* error) {
    if (host && loadPrivateGl(*host, error)) return true;
    if (error->empty()) *error = "no host to load GL entry points through";
    diagnostics->push_back(Diagnostic{ErrorCode::NoGlContext, "", 0, 0, "", *error});
    return false;
}

bool privateGlLoaded() { return g_loaded; }

bool privateGlContextCurrent() { return g_loaded && glGetString(GL_VERSION) != nullptr; }

void forgetPrivateGl() {
    g_loaded = false;
    g_switchedOff.clear();
}

const std::string& privateGlSwitchedOff() { return g_switchedOff; }

}  // namespace fx
