// Stateless particles drawn through the plugin's public entry point in the engine-free host:
// the records go to the GPU and the vertex shader draws them (the sparks light up the picture
// where the closed form puts them), the pass restores every GL state it touches, its picture does
// not depend on host state, and no pass is declared once every record is dead.
#include <algorithm>
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

// The host's fog dims the sparks as light (f rgb, no fog colour: the white fog here would show in
// the sum), and a distance slice keeps each spark in exactly one of two complementary slices.
TEST_F(StatelessRenderTest, SparksAreFoggedAsLightAndEachLiesInOneSlice) {
    ASSERT_EQ(plugin->fireReaction("sparks", glm::vec3(0.0f, 1.5f, 0.0f)), fx::ErrorCode::None);
    step(12);
    const fx::ViewInfo plain = view;
    auto draw = [&](const fx::ViewInfo& v) {
        renderFrame(graph, scene, v, [&](fx::FrameBuilder& f) { plugin->declarePasses(v, f); });
        return graph.readColor();
    };
    std::string none;
    const Image without = frame(false, false, &none);
    const Image all = draw(plain);
    // The burst's centre lies about 8 m along the view axis: linear fog from 0 to 16 m gives
    // f = 0.5 there and 0.425 .. 0.575 over the sparks' reach (1.2 m).
    fx::ViewInfo fogged = plain;
    fogged.fog.mode = fx::Fog::Mode::Linear;
    fogged.fog.start = 0.0f;
    fogged.fog.end = 16.0f;
    fogged.fog.color = glm::vec3(1.0f);
    const Image dimmed = draw(fogged);
    double added = 0.0, addedFogged = 0.0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if (all.at(x, y)[0] >= 250) continue;  // clamped (sparks add up): no ratio there
            added += all.at(x, y)[2] - without.at(x, y)[2];
            addedFogged += dimmed.at(x, y)[2] - without.at(x, y)[2];
        }
    }
    ASSERT_GT(added, 1000.0);
    const double ratio = addedFogged / added;
    std::printf("[ measured ] sparks under linear fog 0..16 m: %.3f of their light (expected 0.425 .. 0.575)\n", ratio);
    EXPECT_GT(ratio, 0.40);
    EXPECT_LT(ratio, 0.60);

    fx::ViewInfo nearSlice = plain, farSlice = plain, empty = plain;
    nearSlice.slice = fx::DistanceSlice{0.0f, 8.0f};
    farSlice.slice = fx::DistanceSlice{8.0f, 0.0f};
    empty.slice = fx::DistanceSlice{20.0f, 0.0f};
    const Image nearImg = draw(nearSlice), farImg = draw(farSlice);
    EXPECT_EQ(maxAbsDiff(draw(empty), without), 0) << "no spark 20 m away or more";
    EXPECT_GT(maxAbsDiff(nearImg, without), 40) << "the near slice holds sparks";
    EXPECT_GT(maxAbsDiff(farImg, without), 40) << "the far slice holds sparks";
    // Light adds up: near + far - background = all, within rounding, where nothing clamped.
    int worst = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            for (int c = 0; c < 3; ++c) {
                if (all.at(x, y)[c] >= 250) continue;
                const int sum = nearImg.at(x, y)[c] + farImg.at(x, y)[c] - without.at(x, y)[c];
                worst = std::max(worst, std::abs(sum - int(all.at(x, y)[c])));
            }
        }
    }
    EXPECT_LE(worst, 2);
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
