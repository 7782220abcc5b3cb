#include "InstallParticleRenderer.h"

#include <memory>
#include <vector>

#include "MegaRenderer.h"
#include "ParticleRenderer.h"
#include "StatelessRenderer.h"
#include "../src/PluginImpl.h"

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

}  // namespace

void installParticleRenderer(PluginImpl& plugin, const std::string& dataDir) {
    ParticleRendererConfig config;
    config.host = &plugin.host();
    config.shaderDir = plugin.shaderDir();
    config.dataDir = dataDir;
    config.errors = &plugin.apiErrors();
    auto renderer = std::make_shared<ParticleRenderer>(std::move(config));
    auto batches = std::make_shared<std::vector<ParticleBatch>>();
    // Stateless reactions have empty pools (the particle renderer sees nothing of them): their
    // own pass follows the other particle passes.
    auto stateless = std::make_shared<StatelessRenderer>(&plugin.host(), plugin.shaderDir());
    // ---- mega-particles: batches resolved to Mega go to MegaRenderer (the billboard renderer
    // never counts Mega among its usable techniques, so it leaves them out) ----
    auto mega = std::make_shared<MegaRenderer>(
        MegaRendererConfig{&plugin.host(), plugin.shaderDir(), &plugin.apiErrors()});
    PluginImpl* owner = &plugin;  // the hook is owned by the plugin: it never outlives it
    plugin.setRenderHook([renderer, batches, stateless, mega, owner](const ViewInfo& view, FrameBuilder& frame,
                                                    const std::vector<ReactionRuntime>& runtimes,
                                                    const RenderOptions& options) {
        batches->clear();
        for (const ReactionRuntime& r : runtimes) {
            batches->push_back(ParticleBatch{&r.pool(), &r.desc(), r.needsSorting(), float(r.time())});
        }
        renderer->setParticleShape(owner->particleShape());
        renderer->setQuarterResEdges(owner->quarterResEdges());
        renderer->setFadeClassification(owner->fadeClassification() == FadeClassification::On,
                                        owner->fadeClassCounting());
        renderer->setLight(owner->light());
        const int drawn = renderer->declarePasses(view, frame, batches->data(),
                                                  static_cast<int>(batches->size()), options);
        const int megaDrawn = mega->declarePasses(view, frame, batches->data(), static_cast<int>(batches->size()),
                                                  options, owner->light());
        owner->setParticlesDrawn(drawn + megaDrawn + stateless->declarePasses(view, frame, runtimes));
    });
    plugin.setPrepareHook([renderer, mega, owner](Diagnostics* out) {
        const bool billboards = renderer->prepare(out);
        return wantsMega(*owner) ? mega->prepare(out) && billboards : billboards;
    });
    plugin.setShadowHook([renderer, batches, owner](const ViewInfo& view, FrameBuilder& frame,
                                                    const std::vector<ReactionRuntime>& runtimes) {
        batches->clear();
        for (const ReactionRuntime& r : runtimes) {
            batches->push_back(ParticleBatch{&r.pool(), &r.desc(), r.needsSorting(), float(r.time())});
        }
        renderer->setLight(owner->light());
        return renderer->declareShadowPasses(view, frame, batches->data(), static_cast<int>(batches->size()));
    });
    plugin.setShaderReloadHook([renderer](Diagnostics* out) { return renderer->reloadShaders(out); });
    plugin.setFadeCountsHook([renderer] { return renderer->fadeClassCounts(); });
}

}  // namespace fx
