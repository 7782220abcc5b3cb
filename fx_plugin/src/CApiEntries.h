#pragma once
// The library's side of the C boundary (fx/fx.h), shared by the files that implement it: the
// handle behind fxPlugin*, the checks every entry makes before it reads through a pointer, and the
// entries each file defines for the one table in CApi.cpp.
//   CApi.cpp         live handles, creation, reactions, simulation, counters, the table
//   CApiOptions.cpp  render options and scene light
//   CApiGl.cpp       the (GL) entries: GL readiness, views, the two drawing paths
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "fx/fx.h"
#include "CApiBridge.h"
#include "PluginImpl.h"

struct fxPlugin {
    fx::UpAxis up;  // the host world's up axis: turned at this boundary (WorldBasis.h)
    fx::CHostAdapter host;
    std::unique_ptr<fx::PluginImpl> impl;
    // The schema as C structs; its strings point into `schema`, both live as long as the plugin.
    std::vector<fx::ReactionKeyInfo> schema;
    std::vector<std::vector<const char*>> schemaChoices;

    fxPlugin(const fxHostCallbacks& callbacks, fx::UpAxis upAxis) : up(upAxis), host(callbacks, upAxis) {}
};

namespace fx {
namespace capi {

inline PluginImpl& impl(fxPlugin* p) { return *p->impl; }
inline const PluginImpl& impl(const fxPlugin* p) { return *p->impl; }
inline int code(ErrorCode c) { return static_cast<int>(c); }

/// Logs and counts a refusal through the plugin's host; returns `code`.
ErrorCode refuse(const fxPlugin* p, ErrorCode code, const char* function, const std::string& what);

/// Whether `p` may be used by `function`. Null, destroyed and foreign handles are refused on
/// stderr (no host can be reached through them) and counted in refusalsWithoutHost().
bool usable(const fxPlugin* p, const char* function);

/// What a refused handle returns from a function that returns an error code.
inline int handleError(const fxPlugin* p) { return p ? FX_ERROR_INVALID_HANDLE : FX_ERROR_NULL_ARGUMENT; }

bool finite3(const float* v);

/// The sizes a descriptor of API 2.x may have: the library's own, and 2.0's where the struct has
/// grown since (`size20`).
inline bool knownSize(uint32_t size, size_t current) { return size == current; }
inline bool knownSize(uint32_t size, size_t current, size_t size20) { return size == current || size == size20; }

std::string sizeProblem(const char* type, uint32_t size, size_t current);
std::string sizeProblem(const char* type, uint32_t size, size_t current, size_t size20);

/// A descriptor of a known size (knownSize) as this library's struct: the fields past a smaller
/// (older) size read as 0, their stated default.
template <class Desc>
Desc fullDesc(const Desc& in) {
    Desc out;
    std::memset(&out, 0, sizeof out);
    std::memcpy(&out, &in, in.size < sizeof out ? in.size : sizeof out);
    return out;
}

/// The first check of an entry that writes a sized struct (fx/fx.h: the plugin writes no byte
/// past out->size): `out` is set and its size one the library knows. Else the refusal is logged
/// under `function`, its code left in *error, and nothing written.
template <class Out>
bool outUsable(const fxPlugin* p, const Out* out, const char* type, const char* function, int* error) {
    if (!out) {
        *error = code(refuse(p, ErrorCode::NullArgument, function,
                             std::string("out is null; expected an ") + type + " (FX_DESC_INIT sets its size)"));
        return false;
    }
    if (!knownSize(out->size, sizeof *out)) {
        *error = code(refuse(p, ErrorCode::BadDescriptor, function, sizeProblem(type, out->size, sizeof *out)));
        return false;
    }
    return true;
}

/// The first check of an entry that returns nothing and writes *out (the getters of 2.0):
/// `p` usable and `out` set. Else the refusal is logged under `function` and nothing written.
inline bool outSet(const fxPlugin* p, const void* out, const char* function) {
    if (!usable(p, function)) return false;
    if (!out) {
        refuse(p, ErrorCode::NullArgument, function, "out is null");
        return false;
    }
    return true;
}

/// Writes the first `bytes` of `full` (this library's struct) into the host's `out`, its size
/// kept: `bytes` is the host's size where the library knows it, so a host built against an older
/// minor gets the fields it knows and nothing past its struct.
template <class Out>
void writeOut(Out* out, const Out& full, size_t bytes) {
    const uint32_t size = out->size;
    std::memcpy(out, &full, bytes < sizeof full ? bytes : sizeof full);
    out->size = size;
}

/// A ...2 entry that cannot fail once `p` and `out` pass their checks: writes `of(p)` into
/// *out (writeOut), or returns the refusal's code.
template <class Out>
int writeOf(const fxPlugin* p, Out* out, const char* type, const char* function, Out (*of)(const fxPlugin*)) {
    if (!usable(p, function)) return handleError(p);
    int error = FX_ERROR_NONE;
    if (!outUsable(p, out, type, function, &error)) return error;
    writeOut(out, of(p), out->size);
    return FX_ERROR_NONE;
}

/// Copies `s` snprintf-style; returns its length.
size_t copyOut(const std::string& s, char* buffer, size_t capacity);

/// Hands each diagnostic to the host's sink (none when `out` or its report is null).
void report(const Diagnostics& diags, const fxDiagnosticSink* out);

/// Runs `call` with a diagnostics list when the host gave a sink, then reports them to it.
template <typename Call>
fxBool withDiagnostics(const fxDiagnosticSink* out, Call call) {
    Diagnostics diags;
    const bool ok = call(out ? &diags : nullptr);
    report(diags, out);
    return ok ? 1 : 0;
}

// ---- CApiOptions.cpp ----------------------------------------------------------------------------
int setRenderOptions(fxPlugin* p, const fxRenderOptions* o);
void getRenderOptions(const fxPlugin* p, fxRenderOptions* out);
int setParticleShape(fxPlugin* p, int s);
int particleShape(const fxPlugin* p);
int setQuarterResEdges(fxPlugin* p, int m);
int quarterResEdges(const fxPlugin* p);
int setFadeClassification(fxPlugin* p, int m);
int fadeClassification(const fxPlugin* p);
int setFadeClassCounting(fxPlugin* p, fxBool on);
void fadeClassCounts(const fxPlugin* p, fxFadeClassCounts* out);
int setSceneLight(fxPlugin* p, const fxSceneLight* l);
void clearSceneLight(fxPlugin* p);

// ---- CApiGl.cpp ---------------------------------------------------------------------------------
fxBool prepareGl(fxPlugin* p, const fxDiagnosticSink* out);
fxBool pollShaderReload(fxPlugin* p, const fxDiagnosticSink* out);
int declarePasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f);
int declareShadowPasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, fxSmokeShadow* out);
int declareShadowPasses2(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, fxSmokeShadow2* out);
int renderView(fxPlugin* p, const fxViewDesc* v);

}  // namespace capi
}  // namespace fx
