// The library's C boundary (fx/fx.h): fxApiVersion, fxGetApi and the table behind it. Everything
// behind the table turns C descriptors and callbacks into the plugin's own C++ types (compiled
// with the library's standard library, never crossing the boundary) and back; CApiEntries.h says
// which file holds which entries.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_set>
#include <vector>

#include "CApiEntries.h"
#include "fx/detail/Counters.h"
#include "../reactions/ReactionDesc.h"
#include "../render/PrivateGlLoader.h"
#include "WorldBasis.h"

extern "C" uint32_t fxApiVersion(void) { return FX_API_VERSION; }

namespace fx {
namespace capi {

ErrorCode refuse(const fxPlugin* p, ErrorCode code, const char* function, const std::string& what) {
    return p->impl->apiErrors().refuse(code, function, what);
}

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

bool finite3(const float* v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

std::string sizeProblem(const char* type, uint32_t size, size_t current) {
    return std::string(type) + "::size = " + std::to_string(size) + "; expected " + std::to_string(current) +
           " (sizeof(" + type + ") of API " + std::to_string(FX_API_VERSION_MAJOR) + "." +
           std::to_string(FX_API_VERSION_MINOR) + ": FX_DESC_INIT sets it)";
}
std::string sizeProblem(const char* type, uint32_t size, size_t current, size_t size20) {
    return sizeProblem(type, size, current) + " or " + std::to_string(size20) + " (API 2.0)";
}

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

namespace {

// API 2.0's fxPluginDesc ended with seed; 2.1 appended upAxis. A 2.0 host's descriptor is read up
// to its size, the rest as 0.
constexpr size_t kPluginDescSize20 = offsetof(fxPluginDesc, upAxis);
constexpr size_t kHostCallbacksSize21 = offsetof(fxHostCallbacks, parallelFor);  // 2.0 and 2.1

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
    if (!knownSize(h.size, sizeof(fxHostCallbacks), kHostCallbacksSize21)) {
        return fail(ErrorCode::BadDescriptor,
                    sizeProblem("fxHostCallbacks", h.size, sizeof(fxHostCallbacks), kHostCallbacksSize21));
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
    auto plugin = std::make_unique<fxPlugin>(fullDesc(h), full.upAxis == FX_UP_Z ? UpAxis::Z : UpAxis::Y);
    PluginImports imports;
    imports.apiVersion = kApiVersion;
    imports.host = &plugin->host;
    imports.shaderDir = desc->shaderDir ? desc->shaderDir : "";
    imports.dataDir = desc->dataDir ? desc->dataDir : "";
    imports.seed = desc->seed;
    plugin->impl = std::make_unique<PluginImpl>(imports);
    plugin->impl->installRenderers(imports.dataDir);
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
// The ...2 entries fill this library's sized struct and copy the host's size of it; the 2.0
// entries copy the same values into the 2.0 layout, whole, as 2.0 did.
fxReactionStats2 reactionStatsOf(const fxPlugin* p, int index) {
    const ReactionStats s = impl(p).reactionStats(index);
    fxReactionStats2 c = detail::withReactionCounts(s, fxDescInit_<fxReactionStats2>());
    copyOut(s.name, c.name, sizeof c.name);
    copyOut(s.technique, c.technique, sizeof c.technique);
    return c;
}
int reactionStats(const fxPlugin* p, int index, fxReactionStats* out) {
    if (!usable(p, "reactionStats")) return handleError(p);
    if (!out) return code(refuse(p, ErrorCode::NullArgument, "reactionStats", "out is null"));
    const fxReactionStats2 c = reactionStatsOf(p, index);
    std::memset(out, 0, sizeof *out);
    std::memcpy(out->name, c.name, sizeof out->name);
    std::memcpy(out->technique, c.technique, sizeof out->technique);
    out->alive = c.alive;
    out->emitted = c.emitted;
    out->dropped = c.dropped;
    return c.name[0] == '\0' ? FX_ERROR_INDEX_OUT_OF_RANGE : FX_ERROR_NONE;
}
int reactionStats2(const fxPlugin* p, int index, fxReactionStats2* out) {
    if (!usable(p, "reactionStats2")) return handleError(p);
    int error = FX_ERROR_NONE;
    if (!outUsable(p, out, "fxReactionStats2", "reactionStats2", &error)) return error;
    const fxReactionStats2 c = reactionStatsOf(p, index);
    if (c.name[0] == '\0') return FX_ERROR_INDEX_OUT_OF_RANGE;  // refused: nothing written
    writeOut(out, c, out->size);
    return FX_ERROR_NONE;
}

int reactionKeyCount(const fxPlugin* p) { return usable(p, "reactionKeyCount") ? int(p->schema.size()) : 0; }
/// The key at `keyIndex` in *out; IndexOutOfRange (refused under `function`) outside the schema.
int reactionKeyOf(const fxPlugin* p, int keyIndex, const char* function, fxReactionKeyInfo2* out) {
    if (keyIndex < 0 || size_t(keyIndex) >= p->schema.size()) {
        return code(refuse(p, ErrorCode::IndexOutOfRange, function,
                           "key index " + std::to_string(keyIndex) + " of " + std::to_string(p->schema.size())));
    }
    const ReactionKeyInfo& k = p->schema[size_t(keyIndex)];
    const std::vector<const char*>& choices = p->schemaChoices[size_t(keyIndex)];
    std::memset(out, 0, sizeof *out);
    out->size = sizeof *out;
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
int reactionKey(const fxPlugin* p, int keyIndex, fxReactionKeyInfo* out) {
    if (!usable(p, "reactionKey")) return handleError(p);
    if (!out) return code(refuse(p, ErrorCode::NullArgument, "reactionKey", "out is null"));
    fxReactionKeyInfo2 k;
    const int error = reactionKeyOf(p, keyIndex, "reactionKey", &k);
    if (error != FX_ERROR_NONE) return error;
    *out = fxReactionKeyInfo{k.key, k.kind, k.min, k.max, k.choices, k.choiceCount, k.unit, k.help};
    return FX_ERROR_NONE;
}
int reactionKey2(const fxPlugin* p, int keyIndex, fxReactionKeyInfo2* out) {
    if (!usable(p, "reactionKey2")) return handleError(p);
    int error = FX_ERROR_NONE;
    if (!outUsable(p, out, "fxReactionKeyInfo2", "reactionKey2", &error)) return error;
    fxReactionKeyInfo2 k;
    error = reactionKeyOf(p, keyIndex, "reactionKey2", &k);
    if (error == FX_ERROR_NONE) writeOut(out, k, out->size);
    return error;
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

fxStats2 statsOf(const fxPlugin* p) { return detail::withStats(impl(p).stats(), fxDescInit_<fxStats2>()); }
void stats(const fxPlugin* p, fxStats* out) {
    if (outSet(p, out, "stats")) *out = detail::withStats(impl(p).stats(), fxStats());
}
int stats2(const fxPlugin* p, fxStats2* out) { return writeOf(p, out, "fxStats2", "stats2", statsOf); }

fxParticleCheck2 checkOf(const fxPlugin* p) {
    const ParticleCheck k = impl(p).checkParticles();
    fxParticleCheck2 c = fxDescInit_<fxParticleCheck2>();
    c.alive = k.alive;
    c.capacity = k.capacity;
    c.nonFinite = k.nonFinite;
    return c;
}
void checkParticles(const fxPlugin* p, fxParticleCheck* out) {
    if (!outSet(p, out, "checkParticles")) return;
    const fxParticleCheck2 c = checkOf(p);
    *out = fxParticleCheck{c.alive, c.capacity, c.nonFinite};
}
int checkParticles2(const fxPlugin* p, fxParticleCheck2* out) {
    return writeOf(p, out, "fxParticleCheck2", "checkParticles2", checkOf);
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
    stats2, checkParticles2, reactionStats2, reactionKey2, declareShadowPasses2,
};

}  // namespace
}  // namespace capi

PluginImpl& implOf(Plugin& plugin) {
    if (auto* c = dynamic_cast<detail::CApiPlugin*>(&plugin)) return *c->handle()->impl;
    return dynamic_cast<PluginImpl&>(plugin);
}
const PluginImpl& implOf(const Plugin& plugin) { return implOf(const_cast<Plugin&>(plugin)); }

}  // namespace fx

extern "C" const fxApi* fxGetApi(uint32_t version) {
    if ((version >> 16) != FX_API_VERSION_MAJOR || (version & 0xFFFFu) > FX_API_VERSION_MINOR) return nullptr;
    return &fx::capi::kApi;
}
