// RenderOptions::quarterRes draws a view at quarter res only where that costs less than full res
// (ScreenTiles.h's quarterResPays: the smoke's summed bounds against its tiles' pixels);
// quarterResAlways forces it. Light smoke at quarter res is drawn exactly as full res draws it (the
// same passes, the same bytes); heavy smoke takes the quarter-res passes, unless the tiled path
// draws the view.
#include <algorithm>
#include <string>
#include <vector>

#include "FxTestHost.h"
#include "render/QuarterResPath.h"

namespace fxtest {
namespace quarter_res_choice_test {  // named: the fx_host tests build as unity batches

constexpr int kW = 160, kH = 120;

bool ran(const std::vector<std::string>& passes, const std::string& name) {
    return std::find(passes.begin(), passes.end(), name) != passes.end();
}

class QuarterResChoiceTest : public PluginHostTest {
protected:
    QuarterResChoiceTest() : PluginHostTest(kW, kH) {}

    void setOptions(bool quarter, bool always, fx::Tiling tiling = fx::Tiling::Auto) {
        fx::RenderOptions o;
        o.techniqueOverride = fx::Technique::Soft;
        o.quarterRes = quarter;
        o.quarterResAlways = always;
        o.tiling = tiling;
        ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
        EXPECT_EQ(plugin->renderOptions().quarterResAlways, always) << "the option reads back";
        ASSERT_TRUE(plugin->prepareGl(nullptr));
    }
};

TEST_F(QuarterResChoiceTest, LightSmokeIsDrawnAtFullResUnlessForced) {
    createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");
    simulate(1.0f, 6);  // a tenth of a second: a few puffs
    const int puffs = plugin->stats().particlesAlive;
    ASSERT_GT(puffs, 0);

    setOptions(false, false);
    const Image full = render();
    ASSERT_GT(plugin->stats().particlesDrawn, 0) << "no smoke on screen: the comparison would prove nothing";
    ASSERT_TRUE(ran(graph.executed(), "particles"));

    setOptions(true, false);
    const Image chosen = render();
    // The choice waits for the passes: all four are declared, and only the full-res one draws.
    for (const char* pass : {"particles_depth_downsample", "particles_quarter", "particles_composite", "particles"}) {
        EXPECT_TRUE(graph.ran(pass)) << pass;
    }
    EXPECT_EQ(graph.drew(), std::vector<std::string>{"particles"}) << puffs << " puffs: full res is cheaper";
    EXPECT_EQ(chosen.rgba, full.rgba) << "drawn at full res: the full-res frame, byte for byte";

    setOptions(true, true);
    const Image forced = render();
    EXPECT_TRUE(graph.drewIn("particles_quarter"));
    EXPECT_TRUE(graph.drewIn("particles_composite"));
    EXPECT_FALSE(ran(graph.executed(), "particles")) << "forced: no choice to wait for, no full-res pass";
    EXPECT_GT(maxAbsDiff(forced, full), 0) << "forced: the half-res picture, not the full-res one";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(QuarterResChoiceTest, HeavySmokeTakesQuarterRes) {
    createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");
    simulate(1.0f, 240);  // four seconds of wheelspin: a bank of smoke, many layers deep
    setOptions(true, false);
    render();
    ASSERT_GT(plugin->stats().particlesDrawn, 0);
    EXPECT_EQ(graph.drew(),
              (std::vector<std::string>{"particles_depth_downsample", "particles_quarter", "particles_composite"}))
        << plugin->stats().particlesDrawn << " puffs drawn";
    EXPECT_TRUE(graph.ran("particles")) << "declared, in case full res had won; it drew nothing";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The choice is made by whichever of the view's passes runs first (QuarterResPath::settle), so a
// host graph that leaves some out still gets the frame the choice gives: light smoke drawn at full
// res with every quarter-res pass left out, heavy smoke at quarter res with the full-res pass left
// out, each byte for byte the frame of a graph that ran them all.
TEST_F(QuarterResChoiceTest, TheChoiceIsMadeByTheFirstOfTheViewsPassesToRun) {
    createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");
    auto isQuarterPass = [](const std::string& name) { return name != "particles"; };
    simulate(1.0f, 6);
    setOptions(true, false);
    const Image light = render();
    ASSERT_EQ(graph.drew(), std::vector<std::string>{"particles"});
    graph.skipPluginPass = isQuarterPass;
    const Image lightSkipped = render();
    graph.skipPluginPass = nullptr;
    EXPECT_FALSE(graph.ran("particles_depth_downsample") || graph.ran("particles_quarter") || graph.ran("particles_composite"));
    EXPECT_EQ(graph.drew(), std::vector<std::string>{"particles"});
    EXPECT_EQ(lightSkipped.rgba, light.rgba);

    simulate(1.0f, 234);
    const Image heavy = render();
    ASSERT_TRUE(graph.drewIn("particles_quarter"));
    graph.skipPluginPass = [](const std::string& name) { return name == "particles"; };
    const Image heavySkipped = render();
    graph.skipPluginPass = nullptr;
    EXPECT_TRUE(graph.drewIn("particles_composite"));
    EXPECT_EQ(heavySkipped.rgba, heavy.rgba);
    EXPECT_GT(maxAbsDiff(heavy, light), 0) << "the two frames differ: the smoke grew";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// QuarterResPath::setChoiceInPass(false) (CUBEFX_QUARTER_CHOICE_IN_PASS=0) chooses while the view
// is declared, as before 2026-11-28: one path's passes only, the same frames byte for byte.
TEST_F(QuarterResChoiceTest, ChosenWhileDeclaredWhereThePassesMayNotChoose) {
    createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");
    struct Reset {
        ~Reset() { fx::QuarterResPath::resetChoiceInPass(); }
    } reset;
    for (int steps : {6, 234}) {
        SCOPED_TRACE(steps);
        simulate(1.0f, steps);
        setOptions(true, false);
        fx::QuarterResPath::setChoiceInPass(true);
        const Image inPass = render();
        const bool quarter = graph.drewIn("particles_quarter");
        EXPECT_EQ(quarter, steps > 6) << "light smoke at full res, heavy at quarter res";
        fx::QuarterResPath::setChoiceInPass(false);
        const Image declared = render();
        EXPECT_EQ(graph.ran("particles"), !quarter);
        EXPECT_EQ(graph.ran("particles_quarter"), quarter);
        EXPECT_EQ(graph.ran("particles_depth_downsample"), quarter);
        EXPECT_EQ(declared.rgba, inPass.rgba);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Where the tiled path draws the view (Tiling::On here; Auto on a GPU) it costs less than quarter
// res: the heavy smoke above is drawn tiled, the picture the tiled one byte for byte and no
// quarter-res pass run; quarterResAlways still takes quarter res. (Auto on this software
// rasterizer does not tile: the test above.)
TEST_F(QuarterResChoiceTest, WhereTheTiledPathDrawsTheViewItTakesItOverQuarterRes) {
    createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");
    simulate(1.0f, 240);
    setOptions(false, false, fx::Tiling::On);
    const Image tiled = render();
    ASSERT_GT(plugin->stats().particlesDrawn, 0);
    ASSERT_TRUE(ran(graph.executed(), "particles_tiled"));

    setOptions(true, false, fx::Tiling::On);
    const Image chosen = render();
    EXPECT_TRUE(ran(graph.executed(), "particles_tiled"));
    for (const char* pass : {"particles_quarter", "particles_composite", "particles_depth_downsample", "particles"}) {
        EXPECT_FALSE(graph.ran(pass)) << pass << ": the tiled path's view has no choice to wait for";
    }
    EXPECT_EQ(chosen.rgba, tiled.rgba) << "the tiled frame, byte for byte";

    setOptions(true, true, fx::Tiling::On);
    const Image forced = render();
    EXPECT_TRUE(graph.drewIn("particles_quarter"));
    EXPECT_FALSE(ran(graph.executed(), "particles_tiled"));
    EXPECT_GT(maxAbsDiff(forced, tiled), 0) << "forced: the half-res picture";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace quarter_res_choice_test
}  // namespace fxtest
