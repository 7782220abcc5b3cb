// The library's C boundary (fx/fx.h): fxApiVersion, fxGetApi and the table behind it. Everything
// here turns C descriptors and callbacks into the plugin's own C++ types (compiled with the
// library's standard library, never crossing the boundary) and back.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_set>
#include <vector>

#include "fx/fx.h"
#include "CApiBridge.h"
#include "PluginImpl.h"
#include "../render/ImmediateRenderer.h"
#include "InstallParticleRenderer.h"
#include "../reactions/ReactionDesc.h"
#include "../render/PrivateGlLoader.h"
#include "WorldBasis.h"

extern "C" uint32_t fxApiVersion(void) { return FX_API_VERSION; }

struct fxPlugin {
    fx::UpAxis up;  // the host world's up axis: turned at this boundary (WorldBasis.h)
    fx::CHostAdapter host;
    std::unique_ptr<fx::PluginImpl> impl;
    // The immediate path's frame graph, target pool and depth copy (fxApi::renderView); made on
    // first use, freed (with the context current) when the plugin is destroyed.
    std::unique_ptr<fx::ImmediateRenderer> immediate;
    // The schema as C structs; its strings point into `schema`, both live as long as the plugin.
    std::vector<fx::ReactionKeyInfo> schema;
    std::vector<std::vector<const char*>> schemaChoices;

    fxPlugin(const fxHostCallbacks& callbacks, fx::UpAxis upAxis) : up(upAxis), host(callbacks, upAxis) {}
};

namespace fx {
namespace {

fx::PluginImpl& impl(fxPlugin* p) { return *p->impl; }
const fx::PluginImpl& impl(const fxPlugin* p) { return *p->impl; }

ErrorCode refuse(const fxPlugin* p, ErrorCode code, const char* function, const std::string& what) {
    return p->impl->apiErrors().refuse(code, function, what);
}

int code(ErrorCode c) { return static_cast<int>(c); }

// ---- live handles -------------------------------------------------------------------------------
// Every plugin create returned and destroy has not yet freed. A call with any other pointer is
// refused before it is dereferenced; a pointer that a later allocation happens to reuse for a new
// plugin cannot be told apart (fx/fx.h says so).
std::mutex g_liveMutex;

// Never destroyed: a host may destroy its last plugin from a static destructor that runs after
// this file's statics would have been.
std::unordered_set<const fxPlugin*>& liveSet() {
    static auto* live = new std::unordered_set<const fxPlugin*>();
    return *live;
}

/// Whether `p` may be used by `function`. Null, destroyed and foreign handles are refused on
/// stderr (no host can be reached through them) and counted in refusalsWithoutHost().
bool usable(const fxPlugin* p, const char* function) {
    if (!p) {
        refuseWithoutHost(ErrorCode::NullArgument, function, "plugin is null; expected a handle from create");
        return false;
    }
    {
        std::lock_guard<std::mutex> lock(g_liveMutex);
        if (liveSet().count(p)) return true;
    }
    char address[32];
    std::snprintf(address, sizeof address, "%p", static_cast<const void*>(p));
    refuseWithoutHost(ErrorCode::InvalidHandle, function,
                      std::string("plugin ") + address + " is not live (destroyed, or not made by create); nothing done");
    return false;
}

/// What a refused handle returns from a function that returns an error code.
int handleError(const fxPlugin* p) { return p ? FX_ERROR_INVALID_HANDLE : FX_ERROR_NULL_ARGUMENT; }

bool finite3(const float* v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

/// The sizes a descriptor of API 2.x may have: 2.0's (the first); later minors add theirs here.
bool knownSize(uint32_t size, size_t current) { return size == current; }

// API 2.0's fxPluginDesc ended with seed and its fxViewDesc with depthRangeFar; 2.1 appended
// upAxis and the viewport fields. A 2.0 host's descriptor is read up to its size, the rest as 0.
constexpr size_t kPluginDescSize20 = offsetof(fxPluginDesc, upAxis);
constexpr size_t kViewDescSize20 = offsetof(fxViewDesc, viewportX);
bool knownSize(uint32_t size, size_t current, size_t size20) { return size == current || size == size20; }

std::string sizeProblem(const char* type, uint32_t size, size_t current) {
    return std::string(type) + "::size = " + std::to_string(size) + "; expected " + std::to_string(current) +
           " (sizeof(" + type + ") of API " + std::to_string(FX_API_VERSION_MAJOR) + "." +
           std::to_string(FX_API_VERSION_MINOR) + ": FX_DESC_INIT sets it)";
}
std::string sizeProblem(const char* type, uint32_t size, size_t current, size_t size20) {
    return sizeProblem(type, size, current) + " or " + std::to_string(size20) + " (API 2.0)";
}

/// A descriptor of a known size (knownSize) as this library's struct: the fields past a smaller
/// (older) size read as 0, their stated default.
template <class Desc>
Desc fullDesc(const Desc& in) {
    Desc out;
    std::memset(&out, 0, sizeof out);
    std::memcpy(&out, &in, in.size < sizeof out ? in.size : sizeof out);
    return out;
}

/// Copies `s` snprintf-style; returns its length.
size_t copyOut(const std::string& s, char* buffer, size_t capacity) {
    if (buffer && capacity > 0) {
        const size_t n = s.size() < capacity - 1 ? s.size() : capacity - 1;
        std::memcpy(buffer, s.data(), n);
        buffer[n] = '\0';
    }
    return s.size();
}

void report(const Diagnostics& diags, const fxDiagnosticSink* out) {
    if (!out || !out->report) return;
    for (const Diagnostic& d : diags) {
        fxDiagnostic c{code(d.code), d.file.c_str(), d.line, d.column, d.key.c_str(), d.message.c_str()};
        out->report(out->user, &c);
    }
}

// ---- creation -----------------------------------------------------------------------------------

fxPlugin* create(const fxPluginDesc* desc, int* error) {
    // Where the refusal is logged is chosen without reading anything the refused check did not
    // vouch for: the host's log only once the descriptor's size and version and the callback
    // table's size are known and its log is set; before that, stderr.
    const fxHostCallbacks* logHost = nullptr;
    auto fail = [&](ErrorCode c, const std::string& what) -> fxPlugin* {
        if (error) *error = code(c);
        if (logHost) {
            const std::string line = std::string("fx: error[") + fxErrorCodeName(code(c)) + "] fxCreatePlugin: " + what;
            logHost->log(logHost->user, FX_LOG_ERROR, line.c_str());
        } else {
            refuseWithoutHost(c, "fxCreatePlugin", what);
        }
        return nullptr;
    };
    if (!desc) return fail(ErrorCode::NullArgument, "desc is null; expected an fxPluginDesc");
    if (!knownSize(desc->size, sizeof(fxPluginDesc), kPluginDescSize20)) {
        return fail(ErrorCode::BadDescriptor,
                    sizeProblem("fxPluginDesc", desc->size, sizeof(fxPluginDesc), kPluginDescSize20));
    }
    const fxPluginDesc full = fullDesc(*desc);
    const uint32_t want = desc->apiVersion != 0 ? desc->apiVersion : FX_API_VERSION;
    if ((want >> 16) != FX_API_VERSION_MAJOR || (want & 0xFFFFu) > FX_API_VERSION_MINOR) {
        auto str = [](uint32_t v) { return std::to_string(v >> 16) + "." + std::to_string(v & 0xFFFFu); };
        return fail(ErrorCode::VersionMismatch, "the host asks for API " + str(want) + "; this plugin offers " +
                                                    str(FX_API_VERSION) + " (same major, minor up to the plugin's)");
    }
    if (!desc->host) return fail(ErrorCode::NullArgument, "PluginImports::host is null; expected the host's HostAdapter");
    const fxHostCallbacks& h = *desc->host;
    if (!knownSize(h.size, sizeof(fxHostCallbacks))) {
        return fail(ErrorCode::BadDescriptor, sizeProblem("fxHostCallbacks", h.size, sizeof(fxHostCallbacks)));
    }
    if (h.log) logHost = &h;
    if (!h.getProcAddress || !h.log) {
        return fail(ErrorCode::NullArgument, std::string("fxHostCallbacks::") + (h.log ? "getProcAddress" : "log") +
                                                 " is null; expected a function (wheelCount, wheel, wind and "
                                                 "collisionPoint may be null)");
    }
    // Checked once the host can hear it: a wrong value here is the host's to read in its log.
    if (full.upAxis != FX_UP_Y && full.upAxis != FX_UP_Z) {
        return fail(ErrorCode::InvalidValue,
                    "fxPluginDesc::upAxis = " + std::to_string(full.upAxis) + "; expected FX_UP_Y (0) or FX_UP_Z (1)");
    }
    auto plugin = std::make_unique<fxPlugin>(h, full.upAxis == FX_UP_Z ? UpAxis::Z : UpAxis::Y);
    PluginImports imports;
    imports.apiVersion = kApiVersion;
    imports.host = &plugin->host;
    imports.shaderDir = desc->shaderDir ? desc->shaderDir : "";
    imports.dataDir = desc->dataDir ? desc->dataDir : "";
    imports.seed = desc->seed;
    plugin->impl = std::make_unique<PluginImpl>(imports);
    installParticleRenderer(*plugin->impl, imports.dataDir);
    plugin->schema = plugin->impl->reactionSchema();
    for (const ReactionKeyInfo& k : plugin->schema) {
        std::vector<const char*> choices;
        for (const std::string& c : k.choices) choices.push_back(c.c_str());
        plugin->schemaChoices.push_back(std::move(choices));
    }
    if (error) *error = FX_ERROR_NONE;
    std::lock_guard<std::mutex> lock(g_liveMutex);
    liveSet().insert(plugin.get());
    return plugin.release();
}

void destroy(fxPlugin* p) {
    if (!p) return;  // like free(NULL)
    if (!usable(p, "destroy")) return;  // destroyed twice, or never made: refused, nothing freed
    bool last = false;
    {
        std::lock_guard<std::mutex> lock(g_liveMutex);
        liveSet().erase(p);
        last = liveSet().empty();
    }
    delete p;
    // The GL table belongs to the live plugins' hosts: with none left, the next plugin loads it
    // again through its own getProcAddress (another context, another driver, a host that hands
    // out fewer functions).
    if (last) forgetPrivateGl();
}

// ---- reactions -----------------------------------------------------------------------------------

template <typename Call>
fxBool withDiagnostics(const fxDiagnosticSink* out, Call call) {
    Diagnostics diags;
    const bool ok = call(out ? &diags : nullptr);
    report(diags, out);
    return ok ? 1 : 0;
}

fxBool loadReactions(fxPlugin* p, const char* path, const fxDiagnosticSink* out) {
    if (!usable(p, "loadReactions")) return 0;
    if (!path) {
        refuse(p, ErrorCode::NullArgument, "loadReactions", "path is null; expected a .yaml file or folder");
        return 0;
    }
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).loadReactions(path, d); });
}
fxBool pollHotReload(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!usable(p, "pollHotReload")) return 0;
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).pollHotReload(d); });
}
fxBool loadReactionsFromText(fxPlugin* p, const char* file, const char* text, size_t length,
                             const fxDiagnosticSink* out) {
    if (!usable(p, "loadReactionsFromText")) return 0;
    if (!file || (!text && length > 0)) {
        refuse(p, ErrorCode::NullArgument, "loadReactionsFromText", "file or text is null");
        return 0;
    }
    if (length > kMaxFileBytes) {  // refused before a byte is copied
        refuse(p, ErrorCode::FileTooLarge, "loadReactionsFromText",
               "length = " + std::to_string(length) + "; expected at most " + std::to_string(kMaxFileBytes) + " bytes");
        return 0;
    }
    const std::string content = text ? std::string(text, length) : std::string();
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).loadReactionsFromText(file, content, d); });
}
int reactionCount(const fxPlugin* p) { return usable(p, "reactionCount") ? impl(p).reactionCount() : 0; }
size_t reactionName(const fxPlugin* p, int index, char* buffer, size_t capacity) {
    return copyOut(usable(p, "reactionName") ? impl(p).reactionName(index) : std::string(), buffer, capacity);
}
size_t reactionFile(const fxPlugin* p, int index, char* buffer, size_t capacity) {
    return copyOut(usable(p, "reactionFile") ? impl(p).reactionFile(index) : std::string(), buffer, capacity);
}
int reactionFileCount(const fxPlugin* p) {
    return usable(p, "reactionFileCount") ? int(impl(p).reactionFiles().size()) : 0;
}
size_t reactionFileAt(const fxPlugin* p, int fileIndex, char* buffer, size_t capacity) {
    if (!usable(p, "reactionFileAt")) return copyOut(std::string(), buffer, capacity);
    const std::vector<std::string> files = impl(p).reactionFiles();
    if (fileIndex < 0 || size_t(fileIndex) >= files.size()) {
        refuse(p, ErrorCode::IndexOutOfRange, "reactionFileAt",
               "file index " + std::to_string(fileIndex) + " of " + std::to_string(files.size()) + " files");
        return copyOut(std::string(), buffer, capacity);
    }
    return copyOut(files[size_t(fileIndex)], buffer, capacity);
}
size_t reactionValue(const fxPlugin* p, int index, const char* key, char* buffer, size_t capacity) {
    if (!usable(p, "reactionValue")) return copyOut(std::string(), buffer, capacity);
    if (!key) {
        refuse(p, ErrorCode::NullArgument, "reactionValue", "key is null; expected a dotted key such as render.technique");
        return copyOut(std::string(), buffer, capacity);
    }
    return copyOut(impl(p).reactionValue(index, key), buffer, capacity);
}
int reactionParticlesAlive(const fxPlugin* p, int index) {
    if (!usable(p, "reactionParticlesAlive")) return 0;
    if (index < 0 || index >= impl(p).reactionCount()) {
        refuse(p, ErrorCode::IndexOutOfRange, "reactionParticlesAlive",
               "index " + std::to_string(index) + " of " + std::to_string(impl(p).reactionCount()) + " reactions");
        return 0;
    }
    return impl(p).reactionParticlesAlive(index);
}
int reactionStats(const fxPlugin* p, int index, fxReactionStats* out) {
    if (!usable(p, "reactionStats")) return handleError(p);
    if (!out) return code(refuse(p, ErrorCode::NullArgument, "reactionStats", "out is null"));
    std::memset(out, 0, sizeof *out);
    const ReactionStats s = impl(p).reactionStats(index);
    copyOut(s.name, out->name, sizeof out->name);
    copyOut(s.technique, out->technique, sizeof out->technique);
    out->alive = s.alive;
    out->emitted = s.emitted;
    out->dropped = s.dropped;
    return s.name.empty() ? FX_ERROR_INDEX_OUT_OF_RANGE : FX_ERROR_NONE;
}
int reactionKeyCount(const fxPlugin* p) { return usable(p, "reactionKeyCount") ? int(p->schema.size()) : 0; }
int reactionKey(const fxPlugin* p, int keyIndex, fxReactionKeyInfo* out) {
    if (!usable(p, "reactionKey")) return handleError(p);
    if (!out) return code(refuse(p, ErrorCode::NullArgument, "reactionKey", "out is null"));
    if (keyIndex < 0 || size_t(keyIndex) >= p->schema.size()) {
        return code(refuse(p, ErrorCode::IndexOutOfRange, "reactionKey",
                           "key index " + std::to_string(keyIndex) + " of " + std::to_string(p->schema.size())));
    }
    const ReactionKeyInfo& k = p->schema[size_t(keyIndex)];
    const std::vector<const char*>& choices = p->schemaChoices[size_t(keyIndex)];
    out->key = k.key.c_str();
    out->kind = static_cast<int>(k.kind);
    out->min = k.min;
    out->max = k.max;
    out->choices = choices.empty() ? nullptr : choices.data();
    out->choiceCount = int(choices.size());
    out->unit = k.unit.c_str();
    out->help = k.help.c_str();
    return FX_ERROR_NONE;
}

// ---- simulation and options -------------------------------------------------------------------

int continueReaction(fxPlugin* p, int index, float dt, float* collision) {
    if (!usable(p, "continueReaction")) return handleError(p);
    if (!(dt >= 0.0f && dt <= FX_MAX_TIME_STEP)) {  // NaN fails both
        return code(refuse(p, ErrorCode::InvalidValue, "continueReaction",
                           "dt = " + std::to_string(dt) + " s; expected 0 <= dt <= " +
                               std::to_string(int(FX_MAX_TIME_STEP)) + " (FX_MAX_TIME_STEP)"));
    }
    return code(impl(p).continueReaction(index, dt, collision));
}
int fireReaction(fxPlugin* p, const char* name, const float point[3]) {
    if (!usable(p, "fireReaction")) return handleError(p);
    if (!name || !point) return code(refuse(p, ErrorCode::NullArgument, "fireReaction", "name or point is null"));
    if (!finite3(point) || std::fabs(point[0]) > FX_MAX_WORLD_COORDINATE ||
        std::fabs(point[1]) > FX_MAX_WORLD_COORDINATE || std::fabs(point[2]) > FX_MAX_WORLD_COORDINATE) {
        // Past the bound a particle's first step already overflows to infinity.
        return code(refuse(p, ErrorCode::InvalidValue, "fireReaction",
                           "point outside the world; expected finite metres within +-1e9 (FX_MAX_WORLD_COORDINATE)"));
    }
    return code(impl(p).fireReaction(name, toPluginWorld(p->up, glm::vec3(point[0], point[1], point[2]))));
}
int setRenderOptions(fxPlugin* p, const fxRenderOptions* o) {
    if (!usable(p, "setRenderOptions")) return handleError(p);
    if (!o) return code(refuse(p, ErrorCode::NullArgument, "setRenderOptions", "options is null"));
    if (!knownSize(o->size, sizeof *o)) {
        return code(refuse(p, ErrorCode::BadDescriptor, "setRenderOptions",
                           sizeProblem("fxRenderOptions", o->size, sizeof *o)));
    }
    if (o->techniqueOverride < 0 || o->techniqueOverride > FX_TECHNIQUE_MEGA) {
        return code(refuse(p, ErrorCode::InvalidValue, "setRenderOptions",
                           "techniqueOverride = " + std::to_string(o->techniqueOverride) +
                               "; expected FromReaction, Hard, Soft, Spherical or Mega"));
    }
    RenderOptions r;
    r.techniqueOverride = static_cast<Technique>(o->techniqueOverride);
    r.quarterRes = o->quarterRes != 0;
    r.bilinearUpsample = o->bilinearUpsample != 0;
    return code(impl(p).setRenderOptions(r));
}
void getRenderOptions(const fxPlugin* p, fxRenderOptions* out) {
    if (!usable(p, "getRenderOptions")) return;
    if (!out) {
        refuse(p, ErrorCode::NullArgument, "getRenderOptions", "out is null");
        return;
    }
    const RenderOptions r = impl(p).renderOptions();
    const uint32_t size = out->size;
    std::memset(out, 0, sizeof *out);
    out->size = size;
    out->techniqueOverride = static_cast<int>(r.techniqueOverride);
    out->quarterRes = r.quarterRes ? 1 : 0;
    out->bilinearUpsample = r.bilinearUpsample ? 1 : 0;
}

// An int from the C side into one of the API's uint8_t enums: a value outside 0..255 would wrap
// into a valid one, so it is clamped to 255, which every setter refuses.
template <class Enum>
Enum enumFrom(int v) {
    return static_cast<Enum>(v < 0 || v > 255 ? 255 : v);
}
int setParticleShape(fxPlugin* p, int s) {
    if (!usable(p, "setParticleShape")) return handleError(p);
    return code(impl(p).setParticleShape(enumFrom<ParticleShape>(s)));
}
int particleShape(const fxPlugin* p) { return usable(p, "particleShape") ? int(impl(p).particleShape()) : 0; }
int setQuarterResEdges(fxPlugin* p, int m) {
    if (!usable(p, "setQuarterResEdges")) return handleError(p);
    return code(impl(p).setQuarterResEdges(enumFrom<QuarterResEdges>(m)));
}
int quarterResEdges(const fxPlugin* p) { return usable(p, "quarterResEdges") ? int(impl(p).quarterResEdges()) : 0; }
int setFadeClassification(fxPlugin* p, int m) {
    if (!usable(p, "setFadeClassification")) return handleError(p);
    return code(impl(p).setFadeClassification(enumFrom<FadeClassification>(m)));
}
int fadeClassification(const fxPlugin* p) {
    return usable(p, "fadeClassification") ? int(impl(p).fadeClassification()) : 0;
}
int setFadeClassCounting(fxPlugin* p, fxBool on) {
    if (!usable(p, "setFadeClassCounting")) return handleError(p);
    return code(impl(p).setFadeClassCounting(on != 0));
}
void fadeClassCounts(const fxPlugin* p, fxFadeClassCounts* out) {
    if (!usable(p, "fadeClassCounts")) return;
    if (!out) {
        refuse(p, ErrorCode::NullArgument, "fadeClassCounts", "out is null");
        return;
    }
    const FadeClassCounts c = impl(p).fadeClassCounts();
    *out = fxFadeClassCounts{c.fadeNeeded, c.inFront, c.hidden, c.counted ? 1 : 0};
}
int setSceneLight(fxPlugin* p, const fxSceneLight* l) {
    if (!usable(p, "setSceneLight")) return handleError(p);
    if (!l) return code(refuse(p, ErrorCode::NullArgument, "setSceneLight", "light is null"));
    if (!knownSize(l->size, sizeof *l)) {
        return code(refuse(p, ErrorCode::BadDescriptor, "setSceneLight", sizeProblem("fxSceneLight", l->size, sizeof *l)));
    }
    SceneLight s;
    s.toSun = toPluginWorld(p->up, glm::vec3(l->toSun[0], l->toSun[1], l->toSun[2]));
    s.sunColor = glm::vec3(l->sunColor[0], l->sunColor[1], l->sunColor[2]);
    s.ambient = glm::vec3(l->ambient[0], l->ambient[1], l->ambient[2]);
    return code(impl(p).setSceneLight(s));
}
void clearSceneLight(fxPlugin* p) {
    if (usable(p, "clearSceneLight")) impl(p).clearSceneLight();
}

// ---- GL -------------------------------------------------------------------------------------------

// The immediate path's renderer, made at its first use (prepareGl or renderView).
ImmediateRenderer& immediate(fxPlugin* p) {
    if (!p->immediate) {
        p->immediate = std::make_unique<ImmediateRenderer>(&p->host, p->impl->shaderDir());
        p->immediate->setApiErrors(&p->impl->apiErrors());
    }
    return *p->immediate;
}


/// A (GL) call's first check after its arguments: the table is loaded (through this plugin's host
/// when it is not yet) and a context is current; else NoGlContext, refused before any GL call so
/// nothing is marked tried or failed (a later call with a context goes ahead).
ErrorCode glReady(fxPlugin* p, const char* function, std::string* why = nullptr) {
    std::string error;
    if (privateGlLoaded() || loadPrivateGl(p->host, &error)) {
        if (privateGlContextCurrent()) return ErrorCode::None;
        error = "no GL context is current on the calling thread (glGetString(GL_VERSION) gave null)";
    }
    if (why) *why = error;
    return refuse(p, ErrorCode::NoGlContext, function, error);
}

fxBool prepareGl(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!usable(p, "prepareGl")) return 0;
    std::string why;
    if (glReady(p, "prepareGl", &why) != ErrorCode::None) {
        // The sink hears it too: a host that reads only diagnostics still learns why.
        report(Diagnostics{Diagnostic{ErrorCode::NoGlContext, "", 0, 0, "", why}}, out);
        return 0;
    }
    return withDiagnostics(out, [&](Diagnostics* d) {
        const bool ok = impl(p).prepareGl(d);
        // The immediate path's own program too: the first renderView then compiles nothing.
        return immediate(p).prepare(d) && ok;
    });
}
fxBool pollShaderReload(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!usable(p, "pollShaderReload")) return 0;
    if (glReady(p, "pollShaderReload") != ErrorCode::None) return 0;
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).pollShaderReload(d); });
}

/// Checks a view descriptor and turns it into the plugin's right-handed, Y-up ViewInfo; None or
/// the refusal (logged under `function`). `placed`: the descriptor's viewport fields place the
/// view (declarePasses); renderView takes the host's GL viewport instead and does not read them.
ErrorCode viewFrom(const fxPlugin* p, const fxViewDesc* v, const char* function, ViewInfo* out, bool placed = true) {
    if (!v) return refuse(p, ErrorCode::NullArgument, function, "view is null; expected an fxViewDesc");
    if (!knownSize(v->size, sizeof *v, kViewDescSize20)) {
        return refuse(p, ErrorCode::BadDescriptor, function, sizeProblem("fxViewDesc", v->size, sizeof *v, kViewDescSize20));
    }
    const fxViewDesc full = fullDesc(*v);
    v = &full;
    if (v->handedness != FX_RIGHT_HANDED && v->handedness != FX_LEFT_HANDED) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "handedness " + std::to_string(v->handedness) + "; expected FX_RIGHT_HANDED or FX_LEFT_HANDED");
    }
    if (v->depthOrder != FX_DEPTH_STANDARD && v->depthOrder != FX_DEPTH_REVERSED_Z) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "depthOrder " + std::to_string(v->depthOrder) + "; expected FX_DEPTH_STANDARD or FX_DEPTH_REVERSED_Z");
    }
    if (v->width <= 0 || v->height <= 0 || v->width > FX_MAX_VIEW_SIZE || v->height > FX_MAX_VIEW_SIZE) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "size " + std::to_string(v->width) + "x" + std::to_string(v->height) + "; expected 1 .. " +
                          std::to_string(FX_MAX_VIEW_SIZE) + " (FX_MAX_VIEW_SIZE) each");
    }
    if (placed && (v->viewportX < 0 || v->viewportY < 0 || v->targetWidth < 0 || v->targetHeight < 0 ||
        (v->targetWidth > 0 && int64_t(v->viewportX) + v->width > v->targetWidth) ||
        (v->targetHeight > 0 && int64_t(v->viewportY) + v->height > v->targetHeight) ||
        ((v->viewportX > 0 || v->viewportY > 0) && (v->targetWidth == 0 || v->targetHeight == 0)))) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "viewport (" + std::to_string(v->viewportX) + ", " + std::to_string(v->viewportY) + ", " +
                          std::to_string(v->width) + ", " + std::to_string(v->height) + ") in a target of " +
                          std::to_string(v->targetWidth) + "x" + std::to_string(v->targetHeight) +
                          "; expected it inside the target (a view away from (0, 0) gives the target's size)");
    }
    bool finite = finite3(v->eye) && std::isfinite(v->nearPlane) && std::isfinite(v->farPlane) &&
                  std::isfinite(v->depthRangeNear) && std::isfinite(v->depthRangeFar);
    for (int i = 0; i < 16; ++i) finite = finite && std::isfinite(v->view[i]) && std::isfinite(v->proj[i]);
    if (!finite) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "a NaN or infinite value in view, proj, eye, the planes or the depth range; expected finite values");
    }
    if (!(v->nearPlane > 0.0f) || !(v->farPlane > v->nearPlane)) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "near " + std::to_string(v->nearPlane) + ", far " + std::to_string(v->farPlane) +
                          "; expected 0 < near < far");
    }
    *out = rightHandedView(*v, p->up);
    if (!placed) {
        out->x = out->y = 0;
        out->targetWidth = out->targetHeight = 0;
    }
    return ErrorCode::None;
}

/// The view and the frame builder of a declare call, checked (the refusal logged under `function`).
ErrorCode viewAndFrame(const fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, const char* function,
                       ViewInfo* view) {
    const ErrorCode bad = viewFrom(p, v, function, view);
    if (bad != ErrorCode::None) return bad;
    const std::string frameBad = frameBuilderProblem(f);
    if (frameBad.empty()) return ErrorCode::None;
    return refuse(p, f && knownSize(f->size, sizeof *f, offsetof(fxFrameBuilder, sceneZBuffer)) ? ErrorCode::NullArgument
                                                                                                : ErrorCode::BadDescriptor,
                  function, frameBad);
}

int declarePasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f) {
    if (!usable(p, "declarePasses")) return handleError(p);
    ViewInfo view;
    const ErrorCode bad = viewAndFrame(p, v, f, "declarePasses", &view);
    if (bad != ErrorCode::None) return code(bad);
    const ErrorCode noGl = glReady(p, "declarePasses");
    if (noGl != ErrorCode::None) return code(noGl);
    CFrameBuilder frame(*f, p->impl->apiErrors());
    return code(impl(p).declarePasses(view, frame));
}

int declareShadowPasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, fxSmokeShadow* out) {
    if (!usable(p, "declareShadowPasses")) return handleError(p);
    if (!out) {
        return code(refuse(p, ErrorCode::NullArgument, "declareShadowPasses",
                           "out is null; expected an fxSmokeShadow for the opacity map"));
    }
    std::memset(out, 0, sizeof *out);
    ViewInfo view;
    const ErrorCode bad = viewAndFrame(p, v, f, "declareShadowPasses", &view);
    if (bad != ErrorCode::None) return code(bad);
    const ErrorCode noGl = glReady(p, "declareShadowPasses");
    if (noGl != ErrorCode::None) return code(noGl);
    CFrameBuilder frame(*f, p->impl->apiErrors());
    const SmokeShadow s = impl(p).declareShadowPasses(view, frame);
    if (s.valid()) {
        out->opacity = s.opacity.id;
        const glm::mat4 hostWorldToShadow = fromHostWorld(p->up, s.worldToShadow);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) out->worldToShadow[c * 4 + r] = hostWorldToShadow[c][r];
    }
    return FX_ERROR_NONE;
}

int renderView(fxPlugin* p, const fxViewDesc* v) {
    if (!usable(p, "renderView")) return handleError(p);
    ViewInfo view;
    const ErrorCode bad = viewFrom(p, v, "renderView", &view, false);
    if (bad != ErrorCode::None) return code(bad);
    ImmediateView iv;
    iv.view = view;
    switch (v->depthSource) {
    case FX_DEPTH_FROM_FRAMEBUFFER: iv.depthSource = ImmediateView::DepthSource::BoundFramebuffer; break;
    case FX_DEPTH_FROM_TEXTURE: iv.depthSource = ImmediateView::DepthSource::DepthTexture; break;
    case FX_DEPTH_FROM_LINEAR: iv.depthSource = ImmediateView::DepthSource::LinearR32F; break;
    case FX_DEPTH_FROM_NOTHING: iv.depthSource = ImmediateView::DepthSource::None; break;
    default:
        return code(refuse(p, ErrorCode::InvalidValue, "renderView",
                           "depthSource " + std::to_string(v->depthSource) + "; expected an FX_DEPTH_FROM_* value"));
    }
    iv.depthTexture = v->depthTexture;
    iv.mapping.clipZeroToOne = v->clipDepthZeroToOne != 0;
    const bool defaultRange = v->depthRangeNear == 0.0f && v->depthRangeFar == 0.0f;
    iv.mapping.rangeNear = defaultRange ? 0.0f : v->depthRangeNear;
    iv.mapping.rangeFar = defaultRange ? 1.0f : v->depthRangeFar;
    const ErrorCode noGl = glReady(p, "renderView");
    if (noGl != ErrorCode::None) return code(noGl);
    return code(immediate(p).render(*p->impl, iv));
}

void stats(const fxPlugin* p, fxStats* out) {
    if (!usable(p, "stats")) return;
    if (!out) {
        refuse(p, ErrorCode::NullArgument, "stats", "out is null");
        return;
    }
    const Stats s = impl(p).stats();
    *out = fxStats{s.reactions, s.particlesAlive, s.particleCapacity, s.particlesDrawn, s.reloads, s.reloadErrors, s.apiErrors};
}
void checkParticles(const fxPlugin* p, fxParticleCheck* out) {
    if (!usable(p, "checkParticles")) return;
    if (!out) {
        refuse(p, ErrorCode::NullArgument, "checkParticles", "out is null");
        return;
    }
    const ParticleCheck c = impl(p).checkParticles();
    *out = fxParticleCheck{c.alive, c.capacity, c.nonFinite};
}

const fxApi kApi = {
    sizeof(fxApi), FX_API_VERSION,
    create, destroy,
    loadReactions, pollHotReload, loadReactionsFromText, reactionCount, reactionName, reactionFile,
    reactionFileCount, reactionFileAt, reactionValue, reactionParticlesAlive, reactionStats,
    reactionKeyCount, reactionKey,
    continueReaction, fireReaction,
    setRenderOptions, getRenderOptions, setParticleShape, particleShape, setQuarterResEdges,
    quarterResEdges, setFadeClassification, fadeClassification, setFadeClassCounting, fadeClassCounts,
    setSceneLight, clearSceneLight,
    prepareGl, pollShaderReload, declarePasses, declareShadowPasses, renderView,
    stats, checkParticles,
};

}  // namespace

PluginImpl& implOf(Plugin& plugin) {
    if (auto* c = dynamic_cast<detail::CApiPlugin*>(&plugin)) return *c->handle()->impl;
    return dynamic_cast<PluginImpl&>(plugin);
}
const PluginImpl& implOf(const Plugin& plugin) { return implOf(const_cast<Plugin&>(plugin)); }

}  // namespace fx

extern "C" const fxApi* fxGetApi(uint32_t version) {
    if ((version >> 16) != FX_API_VERSION_MAJOR || (version & 0xFFFFu) > FX_API_VERSION_MINOR) return nullptr;
    return &fx::kApi;
}
