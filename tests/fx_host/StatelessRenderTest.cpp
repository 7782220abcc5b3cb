// Stateless particles drawn through the plugin's public entry point in the engine-free host:
// the records go to the GPU and the vertex shader draws them (the sparks light up the picture
// where the closed form puts them), the pass restores every GL state it touches, its picture does
// not depend on host state, and no pass is declared once every record is dead.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include "FxTestHost.h"

namespace fxtest {
// Named so that the test files of one unity translation unit keep their helpers apart.
namespace stateless_render_test {

constexpr int kW = 192, kH = 144;

class StatelessRenderTest : public FxHostTest {
protected:
    void SetUp() override {
        FxHostTest::SetUp();
        file = "/tmp/fx_stateless_" + std::to_string(::getpid()) + ".yaml";
        std::ofstream(file) << "reactions:\n"
                               "  - name: sparks\n"
                               "    type: on_demand\n"
                               "    emission: {burst: 400, capacity: 400, spawn_height: 0.0, jitter_radius: 0.0}\n"
                               "    particle:\n"
                               "      lifetime: 1.0\n"
                               "      start_size: 0.3\n"
                               "      end_size: 0.3\n"
                               "      rise_speed: 0.0\n"
                               "      gravity: 9.81\n"
                               "      drag: 0.5\n"
                               "      spread_speed: 4.0\n"
                               "      inherit_velocity: 0.0\n"
                               "      fade_in: 0.0\n"
                               "      fade_out: 0.0\n"
                               "      colour_ramp: [{t: 0, rgba: [1.0, 0.8, 0.3, 1.0]}]\n"
                               "    render: {technique: stateless, blend: additive}\n";
        fx::PluginImports imports;
        imports.host = &host;
        plugin = fxCreatePlugin(imports);
        ASSERT_TRUE(plugin);
        fx::Diagnostics diags;
        ASSERT_TRUE(plugin->loadReactions(file, &diags)) << (diags.empty() ? "" : diags.front().str());
        scene.quads = {TestScene::ground(40.0f, glm::vec3(0.1f))};
    }
    void TearDown() override {
        std::remove(file.c_str());
        FxHostTest::TearDown();
    }

    void step(int steps) {
        for (int s = 0; s < steps; ++s) plugin->continueReaction(0, 1.0f / 60.0f, nullptr);
    }

    Image frame(bool withPlugin, bool dirty, std::string* mismatches) {
        graph.checkPluginState = dirty;
        graph.beforePluginPass = dirty ? std::function<void()>(applyDirtyHostState) : nullptr;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            if (withPlugin) plugin->declarePasses(view, f);
        });
        for (const std::string& m : graph.stateMismatches()) *mismatches += m + "\n";
        return graph.readColor();
    }

    std::string file;
    TestHostAdapter host;
    std::unique_ptr<fx::Plugin> plugin;
    TestScene scene;
    fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.0f, 8.0f), glm::vec3(0.0f, 1.0f, 0.0f), kW, kH);
    TestFrameGraph graph{kW, kH};
};

TEST_F(StatelessRenderTest, SparksAreDrawnFromTheirRecordsAndRestoreTheHostState) {
    ASSERT_EQ(plugin->fireReaction("sparks", glm::vec3(0.0f, 1.5f, 0.0f)), fx::ErrorCode::None);
    step(12);  // 0.2 s: a shell of sparks about 0.7 m out from the centre
    ASSERT_EQ(plugin->reactionStats(0).alive, 400);
    std::string mismatches;
    const Image without = frame(false, false, &mismatches);
    const Image dirty = frame(true, true, &mismatches);
    EXPECT_TRUE(mismatches.empty()) << mismatches;
    EXPECT_TRUE(graph.ran("particles_stateless"));
    const Image clean = frame(true, false, &mismatches);
    EXPECT_EQ(maxAbsDiff(dirty, clean), 0) << "the picture depends on host state";
    writePng("/tmp/fx_host_stateless.png", clean);

    // Lit pixels (red lifted by > 0.2) cluster around the burst's projected centre, within the
    // projected radius the closed form allows (4 m/s for 0.2 s plus the streak: < 1.2 m).
    const glm::vec3 c = projectToPixel(view, glm::vec3(0.0f, 1.5f, 0.0f));
    const glm::vec3 edge = projectToPixel(view, glm::vec3(1.2f, 1.5f, 0.0f));
    const float radius = std::fabs(edge.x - c.x) + 3.0f;
    int lit = 0, outside = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if (clean.value(x, y, 0) - without.value(x, y, 0) <= 0.2f) continue;
            ++lit;
            if (std::hypot(float(x) - c.x, float(y) - c.y) > radius) ++outside;
        }
    }
    EXPECT_GT(lit, 100) << "sparks drawn";
    EXPECT_EQ(outside, 0) << "a spark outside the reach of the closed form";
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

TEST_F(StatelessRenderTest, NoPassOnceEveryRecordIsDead) {
    ASSERT_EQ(plugin->fireReaction("sparks", glm::vec3(0.0f, 1.5f, 0.0f)), fx::ErrorCode::None);
    step(70);  // 1.17 s > the 1 s life
    EXPECT_EQ(plugin->reactionStats(0).alive, 0);
    std::string mismatches;
    frame(true, false, &mismatches);
    EXPECT_FALSE(graph.ran("particles_stateless"));
    EXPECT_EQ(graph.executed(), std::vector<std::string>{"opaque"});
}

}  // namespace stateless_render_test
}  // namespace fxtest
