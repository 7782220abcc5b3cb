// The plugin driven end to end through its public entry point by the engine-free host: the
// repo's reactions/*.yaml, scripted slipping rear wheels, a fixed time step, the host's frame
// graph, read-back pixels.
#include <cmath>

#include "FxTestHost.h"

namespace fxtest {
namespace {

constexpr int kWidth = 256, kHeight = 192;
class EndToEndTest : public LoadedPluginTest {
protected:
    EndToEndTest() : LoadedPluginTest(kWidth, kHeight, {CUBE_SOURCE_DIR "/reactions"}) {}
    void SetUp() override {
        LoadedPluginTest::SetUp();
        scene.quads.push_back(
            TestScene::wallZ(-8.0f, -30.0f, 30.0f, 0.0f, 4.0f, glm::vec3(0.45f, 0.3f, 0.25f)));
    }
};

// Mean brightening (green channel, 0..1) over a window around pixel `c`.
float meanLift(const Image& with, const Image& without, glm::vec2 c, int half) {
    double sum = 0.0;
    int n = 0;
    for (int y = int(c.y) - half; y <= int(c.y) + half; ++y) {
        for (int x = int(c.x) - half; x <= int(c.x) + half; ++x) {
            if (x < 0 || y < 0 || x >= with.width || y >= with.height) continue;
            sum += with.value(x, y, 1) - without.value(x, y, 1);
            ++n;
        }
    }
    return n ? float(sum / n) : 0.0f;
}

TEST_F(EndToEndTest, SlippingRearWheelsPutSmokeBehindTheCar) {
    simulate(1.0f, 90);  // 1.5 s of full wheelspin
    const fx::Stats stats = plugin->stats();
    ASSERT_GT(stats.particlesAlive, 50);

    const Image without = render(false);
    const Image with = render(true);
    writePng("/tmp/fx_host_end_to_end.png", with);
    EXPECT_GT(plugin->stats().particlesDrawn, 50);
    EXPECT_TRUE(graph.ran("prepass")) << "burnout_smoke is soft: it reads sceneDepth";
    EXPECT_TRUE(graph.ran("opaque"));
    EXPECT_TRUE(graph.ran("particles"));
    EXPECT_EQ(graph.targetsCreated(), 0) << "full res needs no target of its own";

    // Smoke over each rear wheel (0.8 m up: the puffs rise and grow from 0.25 m): the grey
    // ground brightens by more than 0.15 on average in a 15x15 window.
    for (float x : {-0.8f, 0.8f}) {
        const glm::vec3 p = projectToPixel(view, glm::vec3(x, 0.8f, 1.3f));
        EXPECT_GT(meanLift(with, without, glm::vec2(p), 7), 0.15f) << "at wheel x = " << x;
    }
    // Far from the car (the wall's far left, the sky above it) nothing changes.
    const glm::vec3 far = projectToPixel(view, glm::vec3(-25.0f, 3.5f, -8.0f));
    EXPECT_LT(std::fabs(meanLift(with, without, glm::vec2(far), 3)), 1.0f / 255.0f);
    EXPECT_NEAR(meanLift(with, without, glm::vec2(8.0f, kHeight - 8.0f), 6), 0.0f, 1.0f / 255.0f);
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

TEST_F(EndToEndTest, NoSlipDeclaresNoPassesAndTheHostSkipsItsPrepass) {
    for (bool quarter : {false, true}) {
        fx::RenderOptions options;
        options.quarterRes = quarter;
        options.quarterResAlways = quarter;
        plugin->setRenderOptions(options);
        simulate(0.0f, 90);
        EXPECT_EQ(plugin->stats().particlesAlive, 0);
        render(true);
        EXPECT_EQ(plugin->stats().particlesDrawn, 0);
        EXPECT_EQ(graph.declared(), (std::vector<std::string>{"prepass", "opaque"}))
            << "the plugin declared passes with nothing to draw";
        EXPECT_EQ(graph.executed(), std::vector<std::string>{"opaque"});
        EXPECT_FALSE(graph.ran("prepass")) << "nobody reads sceneDepth: the prepass is culled";
        EXPECT_FALSE(graph.sceneDepthUsed());
        EXPECT_EQ(graph.targetsCreated(), 0);
        EXPECT_EQ(graph.targetsAllocated(), 0);
    }
}

TEST_F(EndToEndTest, SmokeOutOfViewDeclaresNothing) {
    simulate(1.0f, 60);
    ASSERT_GT(plugin->stats().particlesAlive, 0);
    view = makeView(glm::vec3(0.0f, 2.0f, 10.0f), glm::vec3(0.0f, 2.0f, 30.0f), kWidth, kHeight);
    render(true);
    EXPECT_EQ(plugin->stats().particlesDrawn, 0);
    EXPECT_EQ(graph.executed(), std::vector<std::string>{"opaque"});
}

TEST_F(EndToEndTest, HardParticlesDoNotMakeTheHostRunItsPrepass) {
    simulate(1.0f, 60);
    fx::RenderOptions options;
    options.techniqueOverride = fx::Technique::Hard;
    plugin->setRenderOptions(options);
    render(true);
    EXPECT_GT(plugin->stats().particlesDrawn, 0);
    EXPECT_TRUE(graph.ran("particles"));
    EXPECT_FALSE(graph.ran("prepass")) << "hard particles test the z-buffer, not sceneDepth";
}

TEST_F(EndToEndTest, QuarterResDeclaresItsThreePassesAndTwoTargets) {
    simulate(1.0f, 60);
    fx::RenderOptions options;
    options.quarterRes = true;
    options.quarterResAlways = true;
    plugin->setRenderOptions(options);
    render(true);
    EXPECT_EQ(graph.executed(),
              (std::vector<std::string>{"prepass", "opaque", "particles_depth_downsample",
                                        "particles_quarter", "particles_composite"}));
    EXPECT_EQ(graph.targetsCreated(), 2);
    EXPECT_EQ(graph.targetsAllocated(), 2);
    std::vector<std::string> names = graph.allocatedTargetNames();
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"particles_half_color", "particles_half_depth"}));
}

}  // namespace
}  // namespace fxtest
