#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include "PluginImpl.h"
#include "../reactions/ReactionKeyTable.h"
#include "../reactions/TechniqueTable.h"
#include "../render/Renderers.h"
#include "../render/ViewCheck.h"

namespace fx {

PluginImpl::PluginImpl(const PluginImports& imports)
    : host_(imports.host),
      shaderDir_(imports.shaderDir),
      seed_(imports.seed != 0 ? imports.seed : ReactionRuntime::kDefaultSeed),
      errors_(imports.host) {
    assert(host_);
}

PluginImpl::~PluginImpl() = default;

void PluginImpl::installRenderers(const std::string& dataDir) {
    RendererConfig config;
    config.host = host_;
    config.shaderDir = shaderDir_;
    config.dataDir = dataDir;
    config.errors = &errors_;
    config.jobs = Jobs(host_);
    renderers_ = std::make_unique<Renderers>(config);
}

void PluginImpl::logDiagnostics(const Diagnostics& diags, const char* what) {
    host_->log(LogLevel::Error, what);
    for (const Diagnostic& d : diags) host_->log(LogLevel::Error, d.str().c_str());
}

bool PluginImpl::loadReactions(const std::string& path, Diagnostics* out) {
    Diagnostics diags;
    if (!library_.load(path, &diags)) {
        // "Kept" only when there is something to keep: at start-up nothing is running yet.
        logDiagnostics(diags, ("fx: reactions not loaded from " + path +
                               (everLoaded_ ? "; the running set is kept" : "")).c_str());
        if (out) out->insert(out->end(), diags.begin(), diags.end());
        return false;
    }
    adoptCurrentSet();
    everLoaded_ = true;
    host_->log(LogLevel::Info, ("fx: " + std::to_string(runtimes_.size()) +
                                " reactions loaded from " + path).c_str());
    return true;
}

bool PluginImpl::pollHotReload(Diagnostics* out) {
    Diagnostics diags;
    switch (library_.poll(&diags)) {
    case ReactionLibrary::PollResult::Unchanged:
        return false;
    case ReactionLibrary::PollResult::Rejected:
        ++reloadErrors_;
        logDiagnostics(diags, "fx: reaction files changed but do not validate; the running set is kept");
        if (out) out->insert(out->end(), diags.begin(), diags.end());
        return false;
    case ReactionLibrary::PollResult::Reloaded:
        break;
    }
    ++reloads_;
    adoptCurrentSet();
    host_->log(LogLevel::Info, ("fx: reactions reloaded (" + std::to_string(runtimes_.size()) +
                                " reactions)").c_str());
    return true;
}

bool PluginImpl::loadReactionsFromText(const std::string& file, const std::string& text, Diagnostics* out) {
    Diagnostics diags;
    if (!library_.loadOverride(file, text, &diags)) {
        // An editor's rejected value is the editor's to show; the log gets it once, as for a
        // rejected hot reload.
        logDiagnostics(diags, ("fx: edited text of " + file + " does not validate; the running set is kept").c_str());
        if (out) out->insert(out->end(), diags.begin(), diags.end());
        return false;
    }
    adoptCurrentSet();
    return true;
}

std::vector<ReactionKeyInfo> PluginImpl::reactionSchema() const { return reactionKeyTable(); }

std::string PluginImpl::reactionFile(int index) const {
    if (index < 0 || index >= reactionCount()) {
        errors_.refuse(ErrorCode::IndexOutOfRange, "reactionFile", "index " + std::to_string(index) +
                       " is outside the " + std::to_string(reactionCount()) + " loaded reactions");
        return std::string();
    }
    return runtimes_[size_t(index)].desc().sourceFile;
}

std::string PluginImpl::reactionValue(int index, const std::string& key) const {
    if (index < 0 || index >= reactionCount()) {
        errors_.refuse(ErrorCode::IndexOutOfRange, "reactionValue", "index " + std::to_string(index) +
                       " is outside the " + std::to_string(reactionCount()) + " loaded reactions");
        return std::string();
    }
    return reactionValueText(runtimes_[size_t(index)].desc(), key);
}

int PluginImpl::reactionParticlesAlive(int index) const {
    if (index < 0 || index >= reactionCount()) return 0;
    return runtimes_[size_t(index)].pool().alive();
}

void PluginImpl::settleDrawLists() {
    if (renderers_) renderers_->settleLists();
}

void PluginImpl::adoptCurrentSet() {
    settleDrawLists();  // the runtimes move, and some go
    const ReactionSet& set = library_.current();
    std::vector<ReactionRuntime> next;
    next.reserve(set.reactions.size());
    std::vector<bool> taken(runtimes_.size(), false);
    for (const ReactionDesc& desc : set.reactions) {
        bool kept = false;
        for (size_t i = 0; i < runtimes_.size() && !kept; ++i) {
            ReactionRuntime& old = runtimes_[i];
            // A switch between a pool and a stateless ring is a new runtime (other storage).
            if (!taken[i] && old.name() == desc.name &&
                old.desc().emission.capacity == desc.emission.capacity &&
                old.stateless() == (desc.render.stateless)) {
                old.setDesc(desc);
                next.push_back(std::move(old));
                taken[i] = kept = true;
            }
        }
        if (!kept) next.emplace_back(desc, seed_);
    }
    runtimes_ = std::move(next);
    ++runtimeGeneration_;
}

namespace {

std::string indexRange(int index, int count) {
    return "index " + std::to_string(index) + (count > 0 ? " is outside 0.." + std::to_string(count - 1)
                                                         : std::string(" given, but no reaction is loaded")) +
           " (" + std::to_string(count) + " reactions loaded)";
}

// The API's enum switches: `value` past `last` is refused (InvalidValue, `*field` unchanged) with
// "<what> = <n>; expected <names>", else stored.
template <class Enum>
ErrorCode setSwitch(ApiErrors& errors, Enum value, Enum last, Enum* field, const char* function, const char* what,
                    const char* names) {
    const auto v = static_cast<uint8_t>(value);
    if (v > static_cast<uint8_t>(last)) {
        return errors.refuse(ErrorCode::InvalidValue, function,
                             std::string(what) + " = " + std::to_string(v) + "; expected " + names);
    }
    *field = value;
    return ErrorCode::None;
}

}  // namespace

std::string PluginImpl::reactionName(int index) const {
    if (index < 0 || index >= reactionCount()) {
        errors_.refuse(ErrorCode::IndexOutOfRange, "reactionName", indexRange(index, reactionCount()));
        return std::string();
    }
    return runtimes_[static_cast<size_t>(index)].name();
}

ErrorCode PluginImpl::continueReaction(int index, float dt, float* currentVehicleCollisionAmount) {
    if (index < 0 || index >= reactionCount()) {
        return errors_.refuse(ErrorCode::IndexOutOfRange, "continueReaction", indexRange(index, reactionCount()));
    }
    if (!std::isfinite(dt) || dt < 0.0f) {
        return errors_.refuse(ErrorCode::InvalidValue, "continueReaction",
                              "dt = " + std::to_string(dt) + " s; expected a finite value >= 0");
    }
    settleDrawLists();
    std::array<WheelContact, ReactionRuntime::kMaxWheels> wheels;
    const int count = glm::clamp(host_->wheelCount(), 0, ReactionRuntime::kMaxWheels);
    for (int i = 0; i < count; ++i) wheels[static_cast<size_t>(i)] = host_->wheel(i);
    const float amount = currentVehicleCollisionAmount ? *currentVehicleCollisionAmount : 0.0f;
    runtimes_[static_cast<size_t>(index)].step(dt, wheels.data(), count, amount,
                                               host_->collisionPoint(), host_->wind(), Jobs(host_));
    return ErrorCode::None;
}

ErrorCode PluginImpl::setRenderOptions(const RenderOptions& options) {
    const auto t = static_cast<uint8_t>(options.techniqueOverride);
    if (t > static_cast<uint8_t>(Technique::Mega)) {
        return errors_.refuse(ErrorCode::InvalidValue, "setRenderOptions",
                              "techniqueOverride = " + std::to_string(t) +
                                  "; expected FromReaction, Hard, Soft, Spherical or Mega");
    }
    if (static_cast<uint8_t>(options.tiling) > static_cast<uint8_t>(Tiling::On)) {
        return errors_.refuse(ErrorCode::InvalidValue, "setRenderOptions",
                              "tiling = " + std::to_string(static_cast<int>(options.tiling)) + "; expected Auto, Off or On");
    }
    settings_.options = options;
    return ErrorCode::None;
}

ErrorCode PluginImpl::setParticleShape(ParticleShape shape) {
    return setSwitch(errors_, shape, ParticleShape::Quad, &settings_.shape, "setParticleShape", "shape", "Trimmed or Quad");
}

ErrorCode PluginImpl::setQuarterResEdges(QuarterResEdges mode) {
    return setSwitch(errors_, mode, QuarterResEdges::MixedResolution, &edges_, "setQuarterResEdges", "mode",
                     "DepthAware or MixedResolution");
}

ErrorCode PluginImpl::setFadeClassification(FadeClassification mode) {
    return setSwitch(errors_, mode, FadeClassification::On, &classification_, "setFadeClassification", "mode",
                     "Off or On");
}

bool PluginImpl::prepareGl(Diagnostics* out) {
    return renderers_ ? renderers_->prepare(runtimes_, settings_, out) : true;
}

bool PluginImpl::pollShaderReload(Diagnostics* out) {
    return renderers_ ? renderers_->reload(out) : false;
}

ErrorCode PluginImpl::setSceneLight(const SceneLight& light) {
    auto finite3 = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    auto nonNegative = [](const glm::vec3& v) { return v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; };
    if (!finite3(light.toSun) || !finite3(light.sunColor) || !finite3(light.ambient)) {
        return errors_.refuse(ErrorCode::InvalidValue, "setSceneLight", "non-finite value; expected finite vectors");
    }
    const float len = glm::length(light.toSun);
    if (!(len > 1e-6f) || !std::isfinite(len)) {
        return errors_.refuse(ErrorCode::InvalidValue, "setSceneLight",
                              "toSun has length " + std::to_string(len) + "; expected a non-zero direction");
    }
    if (!nonNegative(light.sunColor) || !nonNegative(light.ambient)) {
        return errors_.refuse(ErrorCode::InvalidValue, "setSceneLight",
                              "negative colour; expected sunColor and ambient >= 0");
    }
    settings_.light.on = true;
    settings_.light.toSun = light.toSun / len;
    settings_.light.sunColor = light.sunColor;
    settings_.light.ambient = light.ambient;
    return ErrorCode::None;
}

SmokeShadow PluginImpl::declareShadowPasses(const ViewInfo& view, FrameBuilder& frame) {
    const std::string bad = viewProblem(view);
    if (!bad.empty()) {
        errors_.refuse(ErrorCode::InvalidView, "declareShadowPasses", bad);
        return SmokeShadow{};
    }
    return renderers_ ? renderers_->declareShadow(view, frame, runtimes_, settings_) : SmokeShadow{};
}

ErrorCode PluginImpl::declarePasses(const ViewInfo& view, FrameBuilder& frame) {
    if (renderers_) return renderers_->declare(view, frame, runtimes_, settings_, &particlesDrawn_);
    const std::string bad = viewProblem(view);
    if (bad.empty()) return ErrorCode::None;
    particlesDrawn_ = 0;
    return errors_.refuse(ErrorCode::InvalidView, "declarePasses", bad);
}

ErrorCode PluginImpl::renderImmediate(const ImmediateView& view, ImmediateRenderer* through) {
    if (!renderers_) return ErrorCode::None;
    ImmediateRenderer& immediate = through ? *through : renderers_->immediate();
    return immediate.render(*renderers_, runtimes_, settings_, view, &particlesDrawn_);
}

Stats PluginImpl::stats() const {
    Stats s;
    s.reactions = reactionCount();
    for (const ReactionRuntime& r : runtimes_) s.particlesAlive += r.alive();
    s.particlesDrawn = particlesDrawn_;
    s.reloads = reloads_;
    s.reloadErrors = reloadErrors_;
    s.apiErrors = errors_.count();
    for (const ReactionRuntime& r : runtimes_) s.particleCapacity += r.capacity();
    return s;
}

ReactionStats PluginImpl::reactionStats(int index) const {
    ReactionStats s;
    if (index < 0 || index >= reactionCount()) {
        errors_.refuse(ErrorCode::IndexOutOfRange, "reactionStats", indexRange(index, reactionCount()));
        return s;
    }
    const ReactionRuntime& r = runtimes_[static_cast<size_t>(index)];
    s.name = r.name();
    s.technique = techniqueRow(r.desc().render.technique, r.stateless()).word;
    s.alive = r.alive();
    s.emitted = r.counters().emitted;
    s.dropped = r.counters().dropped;
    return s;
}

ErrorCode PluginImpl::fireReaction(const std::string& name, const glm::vec3& point) {
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) {
        return errors_.refuse(ErrorCode::InvalidValue, "fireReaction", "non-finite point; expected world metres");
    }
    settleDrawLists();
    int fired = 0;
    for (ReactionRuntime& r : runtimes_) {
        const std::string& n = r.name();
        const bool match = n == name || (n.size() > name.size() && n.compare(0, name.size(), name) == 0 &&
                                         n[name.size()] == '.');
        if (match && r.desc().type == ReactionType::OnDemand) {
            r.fire(point);
            ++fired;
        }
    }
    if (fired == 0) {
        return errors_.refuse(ErrorCode::InvalidValue, "fireReaction",
                              "no on_demand reaction named '" + name + "' (or '" + name + ".<layer>') is loaded");
    }
    return ErrorCode::None;
}

ParticleCheck PluginImpl::checkParticles() const {
    ParticleCheck c;
    for (const ReactionRuntime& r : runtimes_) {
        const ParticlePool& pool = r.pool();
        c.alive += pool.alive();
        c.capacity += pool.capacity();
        // Stateless: the birth records written so far.
        const StatelessRing& ring = r.ring();
        const uint64_t records = std::min<uint64_t>(ring.written(), static_cast<uint64_t>(ring.capacity()));
        c.alive += r.stateless() ? r.alive() : 0;
        c.capacity += ring.capacity();
        for (uint64_t i = 0; i < records; ++i) {
            const float* f = &ring.data()[i].p0[0];
            for (int k = 0; k < 16; ++k) {
                if (!std::isfinite(f[k])) ++c.nonFinite;
            }
        }
        for (int s = 0; s < ParticlePool::StreamCount; ++s) {
            const float* v = pool.stream(ParticlePool::Stream(s));
            for (int i = 0; i < pool.alive(); ++i) {
                if (!std::isfinite(v[i])) ++c.nonFinite;
            }
        }
    }
    return c;
}

}  // namespace fx
