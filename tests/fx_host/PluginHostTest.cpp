// PluginHostTest (FxTestHost.h): the plugin through its public entry point on the test host.
#include "FxTestHost.h"

namespace fxtest {

void PluginHostTest::createPlugin(const std::string& reactions) {
    fx::PluginImports imports;
    imports.host = &host;
    plugin = fxCreatePlugin(imports);
    ASSERT_TRUE(plugin);
    fx::Diagnostics diags;
    ASSERT_TRUE(plugin->loadReactions(reactions.c_str(), &diags))
        << (diags.empty() ? std::string() : diags.front().str());
    ASSERT_GE(plugin->reactionCount(), 1);
    scene.quads = {TestScene::ground(60.0f, glm::vec3(0.18f, 0.18f, 0.2f))};
    view = makeView(glm::vec3(5.0f, 2.2f, 7.5f), glm::vec3(0.0f, 0.9f, 1.0f), width_, height_);
}

void PluginHostTest::simulate(float slip, int steps) {
    host.setRearSlip(slip);
    for (int s = 0; s < steps; ++s) {
        for (int r = 0; r < plugin->reactionCount(); ++r) {
            float collision = 0.0f;
            plugin->continueReaction(r, kDt, &collision);
        }
    }
}

Image PluginHostTest::render(bool withPlugin) {
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& frame) {
        if (withPlugin) plugin->declarePasses(view, frame);
    });
    return graph.readColor();
}

}  // namespace fxtest
