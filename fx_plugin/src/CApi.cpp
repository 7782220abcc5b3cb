// The library's C boundary (fx/fx.h): fxApiVersion, fxGetApi and the table behind it. Everything
// here turns C descriptors and callbacks into the plugin's own C++ types (compiled with the
// library's standard library, never crossing the boundary) and back.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "fx/fx.h"
#include "CApiBridge.h"
#include "PluginImpl.h"
#include "../render/ImmediateRenderer.h"
#include "InstallParticleRenderer.h"

extern "C" uint32_t fxApiVersion(void) { return FX_API_VERSION; }

struct fxPlugin {
    fx::CHostAdapter host;
    std::unique_ptr<fx::PluginImpl> impl;
    // The immediate path's frame graph, target pool and depth copy (fxApi::renderView); made on
    // first use, freed (with the context current) when the plugin is destroyed.
    std::unique_ptr<fx::ImmediateRenderer> immediate;
    // The schema as C structs; its strings point into `schema`, both live as long as the plugin.
    std::vector<fx::ReactionKeyInfo> schema;
    std::vector<std::vector<const char*>> schemaChoices;

    explicit fxPlugin(const fxHostCallbacks& callbacks) : host(callbacks) {}
};

namespace fx {
namespace {

fx::PluginImpl& impl(fxPlugin* p) { return *p->impl; }
const fx::PluginImpl& impl(const fxPlugin* p) { return *p->impl; }

ErrorCode refuse(const fxPlugin* p, ErrorCode code, const char* function, const std::string& what) {
    return p->impl->apiErrors().refuse(code, function, what);
}

int code(ErrorCode c) { return static_cast<int>(c); }

/// The sizes a descriptor of API 2.x may have: 2.0's (the first); later minors add theirs here.
bool knownSize(uint32_t size, size_t current) { return size == current; }

std::string sizeProblem(const char* type, uint32_t size, size_t current) {
    return std::string(type) + "::size = " + std::to_string(size) + "; expected " + std::to_string(current) +
           " (sizeof(" + type + ") of API " + std::to_string(FX_API_VERSION_MAJOR) + "." +
           std::to_string(FX_API_VERSION_MINOR) + ": FX_DESC_INIT sets it)";
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
    auto fail = [&](ErrorCode c, const std::string& what) -> fxPlugin* {
        if (error) *error = code(c);
        // The host's log is reached when the descriptor's own size says it holds the host pointer
        // (a wrong size may still cover it), and that callback table's size is the known one.
        const bool hostReadable = desc && desc->size >= offsetof(fxPluginDesc, host) + sizeof(desc->host) &&
                                  desc->host && knownSize(desc->host->size, sizeof(fxHostCallbacks));
        if (hostReadable && desc->host->log) {
            const std::string line = std::string("fx: error[") + fxErrorCodeName(code(c)) + "] fxCreatePlugin: " + what;
            desc->host->log(desc->host->user, FX_LOG_ERROR, line.c_str());
        }
        return nullptr;
    };
    if (!desc) return fail(ErrorCode::NullArgument, "desc is null; expected an fxPluginDesc");
    if (!knownSize(desc->size, sizeof(fxPluginDesc))) {
        return fail(ErrorCode::BadDescriptor, sizeProblem("fxPluginDesc", desc->size, sizeof(fxPluginDesc)));
    }
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
    if (!h.getProcAddress || !h.log) {
        return fail(ErrorCode::NullArgument, std::string("fxHostCallbacks::") + (h.log ? "getProcAddress" : "log") +
                                                 " is null; expected a function (wheelCount, wheel, wind and "
                                                 "collisionPoint may be null)");
    }
    if ((h.wheelCount == nullptr) != (h.wheel == nullptr)) {
        return fail(ErrorCode::NullArgument, "fxHostCallbacks: wheelCount and wheel must both be set or both null");
    }
    auto plugin = std::make_unique<fxPlugin>(h);
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
    return plugin.release();
}

void destroy(fxPlugin* p) { delete p; }

// ---- reactions -----------------------------------------------------------------------------------

template <typename Call>
fxBool withDiagnostics(const fxDiagnosticSink* out, Call call) {
    Diagnostics diags;
    const bool ok = call(out ? &diags : nullptr);
    report(diags, out);
    return ok ? 1 : 0;
}

fxBool loadReactions(fxPlugin* p, const char* path, const fxDiagnosticSink* out) {
    if (!p) return 0;
    if (!path) {
        refuse(p, ErrorCode::NullArgument, "loadReactions", "path is null; expected a .yaml file or folder");
        return 0;
    }
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).loadReactions(path, d); });
}
fxBool pollHotReload(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!p) return 0;
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).pollHotReload(d); });
}
fxBool loadReactionsFromText(fxPlugin* p, const char* file, const char* text, size_t length,
                             const fxDiagnosticSink* out) {
    if (!p) return 0;
    if (!file || (!text && length > 0)) {
        refuse(p, ErrorCode::NullArgument, "loadReactionsFromText", "file or text is null");
        return 0;
    }
    const std::string content = text ? std::string(text, length) : std::string();
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).loadReactionsFromText(file, content, d); });
}
int reactionCount(const fxPlugin* p) { return p ? impl(p).reactionCount() : 0; }
size_t reactionName(const fxPlugin* p, int index, char* buffer, size_t capacity) {
    return copyOut(p ? impl(p).reactionName(index) : std::string(), buffer, capacity);
}
size_t reactionFile(const fxPlugin* p, int index, char* buffer, size_t capacity) {
    return copyOut(p ? impl(p).reactionFile(index) : std::string(), buffer, capacity);
}
int reactionFileCount(const fxPlugin* p) { return p ? int(impl(p).reactionFiles().size()) : 0; }
size_t reactionFileAt(const fxPlugin* p, int fileIndex, char* buffer, size_t capacity) {
    if (!p) return copyOut(std::string(), buffer, capacity);
    const std::vector<std::string> files = impl(p).reactionFiles();
    if (fileIndex < 0 || size_t(fileIndex) >= files.size()) {
        refuse(p, ErrorCode::IndexOutOfRange, "reactionFileAt",
               "file index " + std::to_string(fileIndex) + " of " + std::to_string(files.size()) + " files");
        return copyOut(std::string(), buffer, capacity);
    }
    return copyOut(files[size_t(fileIndex)], buffer, capacity);
}
size_t reactionValue(const fxPlugin* p, int index, const char* key, char* buffer, size_t capacity) {
    return copyOut(p && key ? impl(p).reactionValue(index, key) : std::string(), buffer, capacity);
}
int reactionParticlesAlive(const fxPlugin* p, int index) { return p ? impl(p).reactionParticlesAlive(index) : 0; }
int reactionStats(const fxPlugin* p, int index, fxReactionStats* out) {
    if (!p || !out) return FX_ERROR_NULL_ARGUMENT;
    std::memset(out, 0, sizeof *out);
    const ReactionStats s = impl(p).reactionStats(index);
    copyOut(s.name, out->name, sizeof out->name);
    copyOut(s.technique, out->technique, sizeof out->technique);
    out->alive = s.alive;
    out->emitted = s.emitted;
    out->dropped = s.dropped;
    return s.name.empty() ? FX_ERROR_INDEX_OUT_OF_RANGE : FX_ERROR_NONE;
}
int reactionKeyCount(const fxPlugin* p) { return p ? int(p->schema.size()) : 0; }
int reactionKey(const fxPlugin* p, int keyIndex, fxReactionKeyInfo* out) {
    if (!p || !out) return FX_ERROR_NULL_ARGUMENT;
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
    return p ? code(impl(p).continueReaction(index, dt, collision)) : FX_ERROR_NULL_ARGUMENT;
}
int fireReaction(fxPlugin* p, const char* name, const float point[3]) {
    if (!p) return FX_ERROR_NULL_ARGUMENT;
    if (!name || !point) return code(refuse(p, ErrorCode::NullArgument, "fireReaction", "name or point is null"));
    return code(impl(p).fireReaction(name, glm::vec3(point[0], point[1], point[2])));
}
int setRenderOptions(fxPlugin* p, const fxRenderOptions* o) {
    if (!p) return FX_ERROR_NULL_ARGUMENT;
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
    if (!p || !out) return;
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
    return p ? code(impl(p).setParticleShape(enumFrom<ParticleShape>(s))) : FX_ERROR_NULL_ARGUMENT;
}
int particleShape(const fxPlugin* p) { return p ? int(impl(p).particleShape()) : 0; }
int setQuarterResEdges(fxPlugin* p, int m) {
    return p ? code(impl(p).setQuarterResEdges(enumFrom<QuarterResEdges>(m))) : FX_ERROR_NULL_ARGUMENT;
}
int quarterResEdges(const fxPlugin* p) { return p ? int(impl(p).quarterResEdges()) : 0; }
int setFadeClassification(fxPlugin* p, int m) {
    return p ? code(impl(p).setFadeClassification(enumFrom<FadeClassification>(m))) : FX_ERROR_NULL_ARGUMENT;
}
int fadeClassification(const fxPlugin* p) { return p ? int(impl(p).fadeClassification()) : 0; }
int setFadeClassCounting(fxPlugin* p, fxBool on) {
    return p ? code(impl(p).setFadeClassCounting(on != 0)) : FX_ERROR_NULL_ARGUMENT;
}
void fadeClassCounts(const fxPlugin* p, fxFadeClassCounts* out) {
    if (!p || !out) return;
    const FadeClassCounts c = impl(p).fadeClassCounts();
    *out = fxFadeClassCounts{c.fadeNeeded, c.inFront, c.hidden, c.counted ? 1 : 0};
}
int setSceneLight(fxPlugin* p, const fxSceneLight* l) {
    if (!p) return FX_ERROR_NULL_ARGUMENT;
    if (!l) return code(refuse(p, ErrorCode::NullArgument, "setSceneLight", "light is null"));
    if (!knownSize(l->size, sizeof *l)) {
        return code(refuse(p, ErrorCode::BadDescriptor, "setSceneLight", sizeProblem("fxSceneLight", l->size, sizeof *l)));
    }
    SceneLight s;
    s.toSun = glm::vec3(l->toSun[0], l->toSun[1], l->toSun[2]);
    s.sunColor = glm::vec3(l->sunColor[0], l->sunColor[1], l->sunColor[2]);
    s.ambient = glm::vec3(l->ambient[0], l->ambient[1], l->ambient[2]);
    return code(impl(p).setSceneLight(s));
}
void clearSceneLight(fxPlugin* p) {
    if (p) impl(p).clearSceneLight();
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


fxBool prepareGl(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!p) return 0;
    return withDiagnostics(out, [&](Diagnostics* d) {
        const bool ok = impl(p).prepareGl(d);
        // The immediate path's own program too: the first renderView then compiles nothing.
        return immediate(p).prepare(d) && ok;
    });
}
fxBool pollShaderReload(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!p) return 0;
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).pollShaderReload(d); });
}

/// Checks a view descriptor and turns it into the plugin's right-handed ViewInfo; None or the
/// refusal (logged under `function`).
ErrorCode viewFrom(const fxPlugin* p, const fxViewDesc* v, const char* function, ViewInfo* out) {
    if (!v) return refuse(p, ErrorCode::NullArgument, function, "view is null; expected an fxViewDesc");
    if (!knownViewDescSize(v->size)) return refuse(p, ErrorCode::BadDescriptor, function, viewDescSizeProblem(v->size));
    if (v->handedness != FX_RIGHT_HANDED && v->handedness != FX_LEFT_HANDED) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "handedness " + std::to_string(v->handedness) + "; expected FX_RIGHT_HANDED or FX_LEFT_HANDED");
    }
    if (v->depthOrder != FX_DEPTH_STANDARD && v->depthOrder != FX_DEPTH_REVERSED_Z) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "depthOrder " + std::to_string(v->depthOrder) + "; expected FX_DEPTH_STANDARD or FX_DEPTH_REVERSED_Z");
    }
    *out = rightHandedView(*v);
    return ErrorCode::None;
}

/// The view and the frame builder of a declare call, checked (the refusal logged under `function`).
ErrorCode viewAndFrame(const fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, const char* function,
                       ViewInfo* view) {
    const ErrorCode bad = viewFrom(p, v, function, view);
    if (bad != ErrorCode::None) return bad;
    const std::string frameBad = frameBuilderProblem(f);
    if (frameBad.empty()) return ErrorCode::None;
    return refuse(p, f && knownSize(f->size, sizeof *f) ? ErrorCode::NullArgument : ErrorCode::BadDescriptor,
                  function, frameBad);
}

int declarePasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f) {
    if (!p) return FX_ERROR_NULL_ARGUMENT;
    ViewInfo view;
    const ErrorCode bad = viewAndFrame(p, v, f, "declarePasses", &view);
    if (bad != ErrorCode::None) return code(bad);
    CFrameBuilder frame(*f, p->impl->apiErrors());
    return code(impl(p).declarePasses(view, frame));
}

int declareShadowPasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, fxSmokeShadow* out) {
    if (!p) return FX_ERROR_NULL_ARGUMENT;
    if (out) std::memset(out, 0, sizeof *out);
    ViewInfo view;
    const ErrorCode bad = viewAndFrame(p, v, f, "declareShadowPasses", &view);
    if (bad != ErrorCode::None) return code(bad);
    CFrameBuilder frame(*f, p->impl->apiErrors());
    const SmokeShadow s = impl(p).declareShadowPasses(view, frame);
    if (out && s.valid()) {
        out->opacity = s.opacity.id;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) out->worldToShadow[c * 4 + r] = s.worldToShadow[c][r];
    }
    return FX_ERROR_NONE;
}

int renderView(fxPlugin* p, const fxViewDesc* v) {
    if (!p) return FX_ERROR_NULL_ARGUMENT;
    ViewInfo view;
    const ErrorCode bad = viewFrom(p, v, "renderView", &view);
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
    return code(immediate(p).render(*p->impl, iv));
}

void stats(const fxPlugin* p, fxStats* out) {
    if (!p || !out) return;
    const Stats s = impl(p).stats();
    *out = fxStats{s.reactions, s.particlesAlive, s.particleCapacity, s.particlesDrawn, s.reloads, s.reloadErrors, s.apiErrors};
}
void checkParticles(const fxPlugin* p, fxParticleCheck* out) {
    if (!p || !out) return;
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
