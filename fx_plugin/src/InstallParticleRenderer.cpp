#include "InstallParticleRenderer.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "../render/MegaRenderer.h"
#include "../render/ParticleRenderer.h"
#include "../render/StatelessRenderer.h"
#include "PluginImpl.h"

namespace fx {
namespace {

// Mega-particles are wanted when a reaction asks for them or the run-time override does.
bool wantsMega(const PluginImpl& plugin) {
    if (plugin.renderOptions().techniqueOverride == Technique::Mega) return true;
    for (const ReactionRuntime& r : plugin.runtimes()) {
        if (!r.stateless() && r.desc().render.technique == Technique::Mega) return true;
    }
    return false;
}

bool wantsStateless(const PluginImpl& plugin) {
    for (const ReactionRuntime& r : plugin.runtimes()) {
        if (r.stateless()) return true;
    }
    return false;
}

// The soft programs' contrast powers (2 contrast_power) the loaded reactions can draw with: a
// soft reaction's own, and every billboard reaction's under a Soft override.
std::vector<int> softPowerSteps(const PluginImpl& plugin) {
    const Technique override = plugin.renderOptions().techniqueOverride;
    std::vector<int> steps;
    for (const ReactionRuntime& r : plugin.runtimes()) {
        if (r.stateless()) continue;
        const Technique t = override == Technique::FromReaction ? r.desc().render.technique : override;
        int whole = 0, half = 0;
        if (t != Technique::Soft || !ProgramCache::halfWholePower(r.desc().render.contrastPower, &whole, &half)) {
            continue;
        }
        const int s = 2 * whole + half;
        if (std::find(steps.begin(), steps.end(), s) == steps.end()) steps.push_back(s);
    }
    return steps;
}

}  // namespace

void installParticleRenderer(PluginImpl& plugin, const std::string& dataDir) {
    RendererConfig config;
    config.host = &plugin.host();
    config.shaderDir = plugin.shaderDir();
    config.dataDir = dataDir;
    config.errors = &plugin.apiErrors();
    auto renderer = std::make_shared<ParticleRenderer>(config);
    auto batches = std::make_shared<std::vector<ParticleBatch>>();
    // Stateless reactions have empty pools (the particle renderer sees nothing of them): their
    // own pass follows the other particle passes.
    auto stateless = std::make_shared<StatelessRenderer>(&plugin.host(), plugin.shaderDir());
    // ---- mega-particles: batches resolved to Mega go to MegaRenderer (the billboard renderer
    // never counts Mega among its usable techniques, so it leaves them out) ----
    auto mega = std::make_shared<MegaRenderer>(config);
    PluginImpl* owner = &plugin;  // the hook is owned by the plugin: it never outlives it
    plugin.setRenderHook([renderer, batches, stateless, mega, owner](const ViewInfo& view, FrameBuilder& frame,
                                                    const std::vector<ReactionRuntime>& runtimes,
                                                    const RenderOptions& options) {
        batches->clear();
        for (const ReactionRuntime& r : runtimes) {
            batches->push_back(ParticleBatch{&r.pool(), &r.desc(), r.needsSorting(), float(r.time())});
        }
        // The plugin's switches, read once for this frame: every path draws with this value.
        FrameSettings settings;
        settings.options = options;
        settings.shape = owner->particleShape();
        settings.light = owner->light();
        const int count = static_cast<int>(batches->size());
        const int drawn = renderer->declarePasses(view, frame, batches->data(), count, settings);
        const int megaDrawn = mega->declarePasses(view, frame, batches->data(), count, settings);
        owner->setParticlesDrawn(drawn + megaDrawn + stateless->declarePasses(view, frame, runtimes));
    });
    // Every program the loaded reactions and the options can draw with is built here (a broken
    // shader of any technique stops start-up), each technique's failures reported once.
    plugin.setPrepareHook([renderer, mega, stateless, owner](Diagnostics* out) {
        bool ok = renderer->prepare(out, softPowerSteps(*owner));
        if (wantsMega(*owner)) ok = mega->prepare(out) && ok;
        if (wantsStateless(*owner)) ok = stateless->prepare(out) && ok;
        return ok;
    });
    plugin.setShadowHook([renderer, batches, owner](const ViewInfo& view, FrameBuilder& frame,
                                                    const std::vector<ReactionRuntime>& runtimes) {
        batches->clear();
        for (const ReactionRuntime& r : runtimes) {
            batches->push_back(ParticleBatch{&r.pool(), &r.desc(), r.needsSorting(), float(r.time())});
        }
        return renderer->declareShadowPasses(view, frame, batches->data(), static_cast<int>(batches->size()),
                                             owner->light());
    });
    // One edit, one transaction over every technique's programs, one line.
    plugin.setShaderReloadHook([renderer, mega, stateless](Diagnostics* out) {
        return renderer->reloadShaders(
            out, {[mega](ShaderErrorLog* e) { return mega->rebuildShaders(e); },
                  [stateless](ShaderErrorLog* e) { return stateless->rebuildShaders(e); }});
    });
}

}  // namespace fx
