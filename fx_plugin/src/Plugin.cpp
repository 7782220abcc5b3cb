#include <array>
#include <cassert>

#include "PluginImpl.h"
#include "../render/InstallParticleRenderer.h"

namespace fx {

PluginImpl::PluginImpl(const PluginImports& imports)
    : host_(imports.host),
      shaderDir_(imports.shaderDir),
      seed_(imports.seed != 0 ? imports.seed : ReactionRuntime::kDefaultSeed) {
    assert(host_);
}

void PluginImpl::logDiagnostics(const Diagnostics& diags, const char* what) {
    host_->log(LogLevel::Error, what);
    for (const Diagnostic& d : diags) host_->log(LogLevel::Error, d.str().c_str());
}

bool PluginImpl::loadReactions(const std::string& path, Diagnostics* out) {
    Diagnostics diags;
    if (!library_.load(path, &diags)) {
        logDiagnostics(diags, ("fx: reactions not loaded from " + path +
                               "; the running set is kept").c_str());
        if (out) out->insert(out->end(), diags.begin(), diags.end());
        return false;
    }
    adoptCurrentSet();
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

void PluginImpl::adoptCurrentSet() {
    const ReactionSet& set = library_.current();
    std::vector<ReactionRuntime> next;
    next.reserve(set.reactions.size());
    std::vector<bool> taken(runtimes_.size(), false);
    for (const ReactionDesc& desc : set.reactions) {
        bool kept = false;
        for (size_t i = 0; i < runtimes_.size() && !kept; ++i) {
            ReactionRuntime& old = runtimes_[i];
            if (!taken[i] && old.name() == desc.name &&
                old.desc().emission.capacity == desc.emission.capacity) {
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

std::string PluginImpl::reactionName(int index) const {
    if (index < 0 || index >= reactionCount()) return std::string();
    return runtimes_[static_cast<size_t>(index)].name();
}

void PluginImpl::continueReaction(int index, float dt, float* currentVehicleCollisionAmount) {
    assert(index >= 0 && index < reactionCount());
    if (index < 0 || index >= reactionCount()) return;
    std::array<WheelContact, ReactionRuntime::kMaxWheels> wheels;
    const int count = glm::clamp(host_->wheelCount(), 0, ReactionRuntime::kMaxWheels);
    for (int i = 0; i < count; ++i) wheels[static_cast<size_t>(i)] = host_->wheel(i);
    const float amount = currentVehicleCollisionAmount ? *currentVehicleCollisionAmount : 0.0f;
    runtimes_[static_cast<size_t>(index)].step(dt, wheels.data(), count, amount,
                                               host_->collisionPoint(), host_->wind());
}

void PluginImpl::declarePasses(const ViewInfo& view, FrameBuilder& frame) {
    // >>> The particle renderer (fx_plugin/render/) plugs in here, through setRenderHook(). <<<
    if (renderHook_) renderHook_(view, frame, runtimes_, options_);
}

Stats PluginImpl::stats() const {
    Stats s;
    s.reactions = reactionCount();
    for (const ReactionRuntime& r : runtimes_) s.particlesAlive += r.pool().alive();
    s.particlesDrawn = particlesDrawn_;
    s.reloads = reloads_;
    s.reloadErrors = reloadErrors_;
    return s;
}

}  // namespace fx

std::unique_ptr<fx::Plugin> fxCreatePlugin(const fx::PluginImports& imports) {
    if (imports.apiVersion != fx::kApiVersion || !imports.host) return nullptr;
    auto plugin = std::make_unique<fx::PluginImpl>(imports);
    fx::installParticleRenderer(*plugin, imports.dataDir);  // the particle renderer's hook
    return plugin;
}
