#pragma once
// The C++ layer of API 2 (included by fx/Plugin.h; not a header to include yourself). Header-only:
// every line here compiles into the HOST, with the host's compiler and standard library, and talks
// to the plugin library through the C table of fx/fx.h only. It keeps the 1.x C++ interface
// (fx::Plugin, fx::HostAdapter, fx::FrameBuilder, fx::PassContext, fxCreatePlugin) source
// compatible:
//   - HostAdapter       -> fxHostCallbacks (user pointer = the HostAdapter)
//   - FrameBuilder      -> fxFrameBuilder for the duration of one declarePasses call; each pass
//                          the plugin adds becomes a std::function the host's graph owns, whose
//                          last copy releases the plugin's pass (fxPassCallback::release)
//   - PassContext       -> fxPassContext for the duration of one pass
//   - Diagnostics*      -> fxDiagnosticSink
//   - fx::Plugin        <- CApiPlugin, forwarding every function to the table
#include <cstddef>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "fx/detail/Counters.h"
#include "fx/detail/FrameBridge.h"

namespace fx {
namespace detail {

// ---- plain data ---------------------------------------------------------------------------------

inline void copyMat(float out[16], const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out[c * 4 + r] = m[c][r];
}
inline glm::mat4 matFrom(const float in[16]) {
    glm::mat4 m(1.0f);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = in[c * 4 + r];
    return m;
}

inline fxViewDesc viewToC(const ViewInfo& v) {
    fxViewDesc c = fxDescInit_<fxViewDesc>();
    c.name = v.name;
    copyMat(c.view, v.view);
    copyMat(c.proj, v.proj);
    c.eye[0] = v.eye.x;
    c.eye[1] = v.eye.y;
    c.eye[2] = v.eye.z;
    c.fogMode = static_cast<int>(v.fog.mode);
    c.fogColor[0] = v.fog.color.x;
    c.fogColor[1] = v.fog.color.y;
    c.fogColor[2] = v.fog.color.z;
    c.fogStart = v.fog.start;
    c.fogEnd = v.fog.end;
    c.fogDensity = v.fog.density;
    c.sliceMinDistance = v.slice.minDistance;
    c.sliceMaxDistance = v.slice.maxDistance;
    c.nearPlane = v.nearPlane;
    c.farPlane = v.farPlane;
    c.width = v.width;
    c.height = v.height;
    c.depthOrder = v.depth == DepthConvention::ReversedZ ? FX_DEPTH_REVERSED_Z : FX_DEPTH_STANDARD;
    c.handedness = v.handedness == Handedness::LeftHanded ? FX_LEFT_HANDED : FX_RIGHT_HANDED;
    c.viewportX = v.x;
    c.viewportY = v.y;
    c.targetWidth = v.targetWidth;
    c.targetHeight = v.targetHeight;
    c.clipToScissor = v.clipToHostScissor ? 1 : 0;
    return c;
}

inline void depthToC(const HostDepth& d, fxViewDesc& c) {
    switch (d.source) {
    case HostDepth::Source::BoundFramebuffer: c.depthSource = FX_DEPTH_FROM_FRAMEBUFFER; break;
    case HostDepth::Source::DepthTexture: c.depthSource = FX_DEPTH_FROM_TEXTURE; break;
    case HostDepth::Source::LinearR32F: c.depthSource = FX_DEPTH_FROM_LINEAR; break;
    case HostDepth::Source::None: c.depthSource = FX_DEPTH_FROM_NOTHING; break;
    default: c.depthSource = -1; break;  // refused by the plugin (InvalidValue)
    }
    c.depthTexture = d.texture;
    c.clipDepthZeroToOne = d.clipDepthZeroToOne ? 1 : 0;
    c.depthRangeNear = d.depthRangeNear;
    c.depthRangeFar = d.depthRangeFar;
}

// ---- diagnostics --------------------------------------------------------------------------------

class DiagnosticSink {
public:
    explicit DiagnosticSink(Diagnostics* out) : out_(out) {
        sink_.user = this;
        sink_.report = &DiagnosticSink::report;
    }
    const fxDiagnosticSink* c() const { return out_ ? &sink_ : nullptr; }

private:
    static void report(void* user, const fxDiagnostic* d) {
        Diagnostic x;
        x.code = static_cast<ErrorCode>(d->code);
        x.file = d->file ? d->file : "";
        x.line = d->line;
        x.column = d->column;
        x.key = d->key ? d->key : "";
        x.message = d->message ? d->message : "";
        static_cast<DiagnosticSink*>(user)->out_->push_back(std::move(x));
    }
    Diagnostics* out_;
    fxDiagnosticSink sink_;
};

/// A string the plugin copies snprintf-style.
template <typename Fetch>
std::string fetchString(Fetch fetch) {
    char small[128];
    const size_t n = fetch(small, sizeof small);
    if (n < sizeof small) return std::string(small, n);
    std::string s(n + 1, '\0');
    fetch(&s[0], s.size());
    s.resize(n);
    return s;
}

// ---- the host's services -------------------------------------------------------------------------

struct HostTrampolines {
    static HostAdapter& host(void* user) { return *static_cast<HostAdapter*>(user); }
    static void* getProcAddress(void* user, const char* name) { return host(user).getProcAddress(name); }
    static void log(void* user, int level, const char* message) {
        host(user).log(static_cast<LogLevel>(level), message);
    }
    static int wheelCount(void* user) { return host(user).wheelCount(); }
    static void wheel(void* user, int index, fxWheelContact* out) {
        const WheelContact w = host(user).wheel(index);
        for (int k = 0; k < 3; ++k) {
            out->position[k] = w.position[k];
            out->velocity[k] = w.velocity[k];
        }
        out->slip = w.slip;
        out->surface = static_cast<int>(w.surface);
        out->grounded = w.grounded ? 1 : 0;
        out->rear = w.rear ? 1 : 0;
    }
    static void wind(void* user, float out[3]) {
        const glm::vec3 v = host(user).wind();
        out[0] = v.x, out[1] = v.y, out[2] = v.z;
    }
    static void collisionPoint(void* user, float out[3]) {
        const glm::vec3 v = host(user).collisionPoint();
        out[0] = v.x, out[1] = v.y, out[2] = v.z;
    }
    static void parallelFor(void* user, uint32_t count, void (*task)(void* data, uint32_t index), void* data) {
        host(user).parallelFor(count, task, data);
    }
    static fxHostCallbacks make(HostAdapter* host) {
        fxHostCallbacks c = fxDescInit_<fxHostCallbacks>();
        c.user = host;
        c.getProcAddress = &getProcAddress;
        c.log = &log;
        c.wheelCount = &wheelCount;
        c.wheel = &wheel;
        c.wind = &wind;
        c.collisionPoint = &collisionPoint;
        c.parallelFor = &parallelFor;
        return c;
    }
};

// ---- the plugin -------------------------------------------------------------------------------------

class CApiPlugin final : public Plugin {
public:
    CApiPlugin(const fxApi* api, fxPlugin* plugin) : api_(api), p_(plugin) {}
    ~CApiPlugin() override { api_->destroy(p_); }
    CApiPlugin(const CApiPlugin&) = delete;
    CApiPlugin& operator=(const CApiPlugin&) = delete;

    /// The C handle (for code that mixes the C++ layer with the C table).
    fxPlugin* handle() const { return p_; }
    const fxApi* api() const { return api_; }

    bool loadReactions(const std::string& path, Diagnostics* out) override {
        DiagnosticSink sink(out);
        return api_->loadReactions(p_, path.c_str(), sink.c()) != 0;
    }
    bool pollHotReload(Diagnostics* out) override {
        DiagnosticSink sink(out);
        return api_->pollHotReload(p_, sink.c()) != 0;
    }
    int reactionCount() const override { return api_->reactionCount(p_); }
    std::string reactionName(int index) const override {
        return fetchString([&](char* b, size_t n) { return api_->reactionName(p_, index, b, n); });
    }
    ErrorCode continueReaction(int index, float dt, float* collision) override {
        return static_cast<ErrorCode>(api_->continueReaction(p_, index, dt, collision));
    }
    ErrorCode setRenderOptions(const RenderOptions& o) override {
        // RenderOptions has no shape (setParticleShape sets it): the running one is sent back.
        fxRenderOptions c = fxDescInit_<fxRenderOptions>();
        api_->getRenderOptions(p_, &c);
        c.techniqueOverride = static_cast<int>(o.techniqueOverride);
        c.quarterRes = o.quarterRes ? 1 : 0;
        c.bilinearUpsample = o.bilinearUpsample ? 1 : 0;
        c.quarterResAlways = o.quarterResAlways ? 1 : 0;
        c.tiled = o.tiled ? 1 : 0;
        c.tiling = static_cast<int>(o.tiling);
        return static_cast<ErrorCode>(api_->setRenderOptions(p_, &c));
    }
    RenderOptions renderOptions() const override {
        fxRenderOptions c = fxDescInit_<fxRenderOptions>();
        api_->getRenderOptions(p_, &c);
        RenderOptions o;
        o.techniqueOverride = static_cast<Technique>(c.techniqueOverride);
        o.quarterRes = c.quarterRes != 0;
        o.bilinearUpsample = c.bilinearUpsample != 0;
        o.quarterResAlways = c.quarterResAlways != 0;
        o.tiled = c.tiled != 0;
        o.tiling = static_cast<Tiling>(c.tiling);
        return o;
    }
    bool prepareGl(Diagnostics* out) override {
        DiagnosticSink sink(out);
        return api_->prepareGl(p_, sink.c()) != 0;
    }
    ErrorCode declarePasses(const ViewInfo& view, FrameBuilder& frame) override {
        const fxViewDesc v = viewToC(view);
        FrameBridge bridge(frame);
        return static_cast<ErrorCode>(api_->declarePasses(p_, &v, bridge.c()));
    }
    Stats stats() const override { return withStats(fetch(api_->stats2), Stats()); }
    ParticleCheck checkParticles() const override {
        const fxParticleCheck2 c = fetch(api_->checkParticles2);
        ParticleCheck k;
        k.alive = c.alive;
        k.capacity = c.capacity;
        k.nonFinite = c.nonFinite;
        return k;
    }
    bool pollShaderReload(Diagnostics* out) override {
        DiagnosticSink sink(out);
        return api_->pollShaderReload(p_, sink.c()) != 0;
    }
    std::vector<ReactionKeyInfo> reactionSchema() const override {
        std::vector<ReactionKeyInfo> keys;
        const int n = api_->reactionKeyCount(p_);
        keys.reserve(size_t(n > 0 ? n : 0));
        for (int i = 0; i < n; ++i) {
            fxReactionKeyInfo2 c = fxDescInit_<fxReactionKeyInfo2>();
            if (api_->reactionKey2(p_, i, &c) != FX_ERROR_NONE) continue;
            ReactionKeyInfo k;
            k.key = c.key ? c.key : "";
            k.kind = static_cast<ReactionKeyInfo::Kind>(c.kind);
            k.min = c.min;
            k.max = c.max;
            for (int j = 0; j < c.choiceCount; ++j) k.choices.emplace_back(c.choices[j]);
            k.unit = c.unit ? c.unit : "";
            k.help = c.help ? c.help : "";
            keys.push_back(std::move(k));
        }
        return keys;
    }
    std::vector<std::string> reactionFiles() const override {
        std::vector<std::string> files;
        const int n = api_->reactionFileCount(p_);
        for (int i = 0; i < n; ++i) {
            files.push_back(fetchString([&](char* b, size_t m) { return api_->reactionFileAt(p_, i, b, m); }));
        }
        return files;
    }
    std::string reactionFile(int index) const override {
        return fetchString([&](char* b, size_t n) { return api_->reactionFile(p_, index, b, n); });
    }
    std::string reactionValue(int index, const std::string& key) const override {
        return fetchString([&](char* b, size_t n) { return api_->reactionValue(p_, index, key.c_str(), b, n); });
    }
    int reactionParticlesAlive(int index) const override { return api_->reactionParticlesAlive(p_, index); }
    bool loadReactionsFromText(const std::string& file, const std::string& text, Diagnostics* out) override {
        DiagnosticSink sink(out);
        return api_->loadReactionsFromText(p_, file.c_str(), text.data(), text.size(), sink.c()) != 0;
    }
    // The shape is a field of fxRenderOptions since API 2.1: set with the other options as they are.
    ErrorCode setParticleShape(ParticleShape shape) override {
        fxRenderOptions c = fxDescInit_<fxRenderOptions>();
        api_->getRenderOptions(p_, &c);
        c.particleShape = static_cast<int>(shape);
        return static_cast<ErrorCode>(api_->setRenderOptions(p_, &c));
    }
    ParticleShape particleShape() const override {
        fxRenderOptions c = fxDescInit_<fxRenderOptions>();
        api_->getRenderOptions(p_, &c);
        return static_cast<ParticleShape>(c.particleShape);
    }
    ReactionStats reactionStats(int index) const override {
        fxReactionStats2 c = fxDescInit_<fxReactionStats2>();
        api_->reactionStats2(p_, index, &c);
        ReactionStats s = withReactionCounts(c, ReactionStats());
        s.name = c.name;
        s.technique = c.technique;
        return s;
    }
    ErrorCode fireReaction(const std::string& name, const glm::vec3& point) override {
        const float p[3] = {point.x, point.y, point.z};
        return static_cast<ErrorCode>(api_->fireReaction(p_, name.c_str(), p));
    }
    ErrorCode setSceneLight(const SceneLight& light) override {
        fxSceneLight c = fxDescInit_<fxSceneLight>();
        for (int k = 0; k < 3; ++k) {
            c.toSun[k] = light.toSun[k];
            c.sunColor[k] = light.sunColor[k];
            c.ambient[k] = light.ambient[k];
        }
        return static_cast<ErrorCode>(api_->setSceneLight(p_, &c));
    }
    void clearSceneLight() override { api_->clearSceneLight(p_); }
    SmokeShadow declareShadowPasses(const ViewInfo& view, FrameBuilder& frame) override {
        const fxViewDesc v = viewToC(view);
        FrameBridge bridge(frame);
        fxSmokeShadow2 c = fxDescInit_<fxSmokeShadow2>();
        SmokeShadow s;
        if (api_->declareShadowPasses2(p_, &v, bridge.c(), &c) == FX_ERROR_NONE && c.opacity != 0) {
            s.opacity = targetFrom(c.opacity);
            s.worldToShadow = matFrom(c.worldToShadow);
        }
        return s;
    }
    ErrorCode setQuarterResEdges(QuarterResEdges mode) override {
        return static_cast<ErrorCode>(api_->setQuarterResEdges(p_, static_cast<int>(mode)));
    }
    QuarterResEdges quarterResEdges() const override {
        return static_cast<QuarterResEdges>(api_->quarterResEdges(p_));
    }
    ErrorCode setFadeClassification(FadeClassification mode) override {
        return static_cast<ErrorCode>(api_->setFadeClassification(p_, static_cast<int>(mode)));
    }
    FadeClassification fadeClassification() const override {
        return static_cast<FadeClassification>(api_->fadeClassification(p_));
    }
    ErrorCode setFadeClassCounting(bool on) override {
        return static_cast<ErrorCode>(api_->setFadeClassCounting(p_, on ? 1 : 0));
    }
    FadeClassCounts fadeClassCounts() const override {
        fxFadeClassCounts c{};
        api_->fadeClassCounts(p_, &c);
        FadeClassCounts k;
        k.fadeNeeded = c.fadeNeeded;
        k.inFront = c.inFront;
        k.hidden = c.hidden;
        k.counted = c.counted != 0;
        return k;
    }
    ErrorCode renderView(const ViewInfo& view, const HostDepth& depth) override {
        fxViewDesc v = viewToC(view);
        depthToC(depth, v);
        return static_cast<ErrorCode>(api_->renderView(p_, &v));
    }

private:
    /// The sized struct one of the table's ...2 getters writes.
    template <class Out>
    Out fetch(int (*get)(const fxPlugin*, Out*)) const {
        Out c = fxDescInit_<Out>();
        get(p_, &c);
        return c;
    }

    const fxApi* api_;
    fxPlugin* p_;
};

}  // namespace detail
}  // namespace fx

inline std::unique_ptr<fx::Plugin> fxCreatePlugin(const fx::PluginImports& imports, fx::ErrorCode* error) {
    using fx::ErrorCode;
    const fxApi* api = fxGetApi(fx::kApiVersion);
    if (!api) {
        // The library is older than these headers: nothing to create the plugin with.
        if (error) *error = ErrorCode::VersionMismatch;
        if (imports.host) {
            const uint32_t lib = fxApiVersion();
            const std::string line =
                "fx: error[VersionMismatch] fxCreatePlugin: the plugin library offers API " +
                std::to_string(fx::apiVersionMajor(lib)) + "." + std::to_string(fx::apiVersionMinor(lib)) +
                "; these headers need " + std::to_string(FX_API_VERSION_MAJOR) + "." +
                std::to_string(FX_API_VERSION_MINOR);
            imports.host->log(fx::LogLevel::Error, line.c_str());
        }
        return nullptr;
    }
    // A host written against 1.x gets the 2.0 table: this layer serves every 1.x function.
    uint32_t want = imports.apiVersion;
    if (fx::apiVersionMajor(want) == 1 && want <= fx::kLastApiVersion1) want = fx::kApiVersion;
    fxHostCallbacks callbacks = fx::detail::HostTrampolines::make(imports.host);
    fxPluginDesc desc = fxDescInit_<fxPluginDesc>();
    desc.apiVersion = want;
    desc.host = imports.host ? &callbacks : nullptr;
    desc.shaderDir = imports.shaderDir.c_str();
    desc.dataDir = imports.dataDir.c_str();
    desc.seed = imports.seed;
    desc.upAxis = imports.upAxis == fx::UpAxis::Z ? FX_UP_Z : FX_UP_Y;
    int code = FX_ERROR_NONE;
    fxPlugin* handle = api->create(&desc, &code);
    if (error) *error = static_cast<ErrorCode>(code);
    if (code == FX_ERROR_VERSION_MISMATCH && imports.host) {
        // The library does not read a descriptor of a version it refused, so its line went to
        // stderr; this layer holds the host itself and tells it too.
        const std::string line = "fx: error[VersionMismatch] fxCreatePlugin: the host asks for API " +
                                 std::to_string(fx::apiVersionMajor(want)) + "." +
                                 std::to_string(fx::apiVersionMinor(want)) + "; this plugin offers " +
                                 std::to_string(FX_API_VERSION_MAJOR) + "." + std::to_string(FX_API_VERSION_MINOR) +
                                 " (same major, minor up to the plugin's)";
        imports.host->log(fx::LogLevel::Error, line.c_str());
    }
    if (!handle) return nullptr;
    return std::unique_ptr<fx::Plugin>(new fx::detail::CApiPlugin(api, handle));
}
