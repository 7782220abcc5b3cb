#include "render/PrivateGl.h"

#include "fx/HostAdapter.h"

namespace fx {
namespace {

bool g_loaded = false;

GLADapiproc throughHost(void* host, const char* name) {
    return reinterpret_cast<GLADapiproc>(static_cast<HostAdapter*>(host)->getProcAddress(name));
}

GLADapiproc throughFunction(void* fn, const char* name) {
    auto getProc = reinterpret_cast<void* (*)(const char*)>(fn);
    return reinterpret_cast<GLADapiproc>(getProc(name));
}

bool finish(int version, std::string* error) {
    if (version == 0 || !fxglad_glCreateShader) {
        *error = "the host's getProcAddress gave no GL entry points (is its context current?)";
        return false;
    }
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
        *error = "the host's context offers OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) +
                 "." + std::to_string(GLAD_VERSION_MINOR(version)) + "; the plugin needs 3.3 core";
        return false;
    }
    g_loaded = true;
    return true;
}

}  // namespace

bool loadPrivateGl(HostAdapter& host, std::string* error) {
    if (g_loaded) return true;
    // Ask once before handing the function to glad: glad reads glGetString first and would
    // crash on a null entry point.
    if (!host.getProcAddress("glGetString") || !host.getProcAddress("glCreateShader")) {
        return finish(0, error);
    }
    return finish(fxgladLoadGLUserPtr(throughHost, &host), error);
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

}  // namespace fx
