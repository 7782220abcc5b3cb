#include "InstallParticleRenderer.h"

#include <memory>
#include <vector>

#include "ParticleRenderer.h"
#include "StatelessRenderer.h"
#include "../src/PluginImpl.h"

namespace fx {

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
    PluginImpl* owner = &plugin;  // the hook is owned by the plugin: it never outlives it
    plugin.setRenderHook([renderer, batches, stateless, owner](const ViewInfo& view, FrameBuilder& frame,
                                                    const std::vector<ReactionRuntime>& runtimes,
                                                    const RenderOptions& options) {
        batches->clear();
        for (const ReactionRuntime& r : runtimes) {
            batches->push_back(ParticleBatch{&r.pool(), &r.desc(), r.needsSorting()});
        }
        renderer->setParticleShape(owner->particleShape());
        renderer->setLight(owner->light());
        const int drawn = renderer->declarePasses(view, frame, batches->data(),
                                                  static_cast<int>(batches->size()), options);
        owner->setParticlesDrawn(drawn + stateless->declarePasses(view, frame, runtimes));
    });
    plugin.setShadowHook([renderer, batches, owner](const ViewInfo&, FrameBuilder& frame,
                                                    const std::vector<ReactionRuntime>& runtimes) {
        batches->clear();
        for (const ReactionRuntime& r : runtimes) {
            batches->push_back(ParticleBatch{&r.pool(), &r.desc(), r.needsSorting()});
        }
        renderer->setLight(owner->light());
        return renderer->declareShadowPasses(frame, batches->data(), static_cast<int>(batches->size()));
    });
    plugin.setPrepareHook([renderer](Diagnostics* out) { return renderer->prepare(out); });
    plugin.setShaderReloadHook([renderer](Diagnostics* out) { return renderer->reloadShaders(out); });
}

}  // namespace fx
