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

void PluginHostTest::setMode(const RenderMode& m) {
    fx::RenderOptions o;
    o.techniqueOverride = m.technique;
    o.quarterRes = m.quarter;
    o.quarterResAlways = m.quarter;
    o.tiling = m.tiled ? fx::Tiling::On : fx::Tiling::Off;  // the mode's path on any context
    ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
    if (m.lit) {
        ASSERT_EQ(plugin->setSceneLight(fx::SceneLight{}), fx::ErrorCode::None);
    } else {
        plugin->clearSceneLight();
    }
}

void PluginHostTest::useWallScene() {
    scene.quads = {TestScene::ground(40.0f, glm::vec3(0.2f)),
                   TestScene::wallZ(-5.0f, -20.0f, 20.0f, 0.0f, 3.0f, glm::vec3(0.4f, 0.3f, 0.3f))};
    view = makeView(glm::vec3(4.0f, 2.0f, 7.0f), glm::vec3(0.0f, 0.8f, 1.0f), width_, height_);
}

Image PluginHostTest::renderChecked(const fx::ViewInfo& v, bool dirty, std::string* mismatches) {
    graph.checkPluginState = dirty;
    graph.beforePluginPass = dirty ? std::function<void()>(applyDirtyHostState) : nullptr;
    renderFrame(graph, scene, v, [&](fx::FrameBuilder& f) {
        if (!dirty) {
            plugin->declarePasses(v, f);
            return;
        }
        applyDirtyHostState();
        const GlStateSnapshot before = captureGlState();
        plugin->declarePasses(v, f);
        const std::string d = before.diff(captureGlState());
        if (!d.empty()) *mismatches += "declarePasses: " + d + "\n";
    });
    for (const std::string& m : graph.stateMismatches()) *mismatches += m + "\n";
    return graph.readColor();
}

}  // namespace fxtest
