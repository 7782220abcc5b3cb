// cube_game --fog: the track and the sky are fogged by GL's fixed-function formula, and the
// views hand the same fog to the plugin (fx::ViewInfo::fog), so the smoke fades with the track.
// Off by default: the golden frames are drawn without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "GameTestUtil.h"
#include "game/Options.h"
#include "gl/Gl.h"

using namespace cube;
using cubetest::pixel;
using cubetest::project;

namespace scene_fog {  // named: the engine tests build as unity batches
bool parseFog(std::vector<const char*> args, Options* o, std::string* err) {
    args.insert(args.begin(), "cube_game");
    return parseOptions(int(args.size()), args.data(), o, err);
}
}  // namespace scene_fog
using scene_fog::parseFog;

TEST(SceneFog, TheFogOptionParsesEachModeAndRefusesBadValues) {
    Options o;
    std::string err;
    EXPECT_FALSE(o.fog.on()) << "fog is off by default";
    ASSERT_TRUE(parseFog({"--fog", "5,60"}, &o, &err)) << err;
    EXPECT_EQ(o.fog.mode, SceneFog::Mode::Linear);
    EXPECT_FLOAT_EQ(o.fog.start, 5.0f);
    EXPECT_FLOAT_EQ(o.fog.end, 60.0f);
    ASSERT_TRUE(parseFog({"--fog", "exp,0.02"}, &o, &err)) << err;
    EXPECT_EQ(o.fog.mode, SceneFog::Mode::Exp);
    EXPECT_FLOAT_EQ(o.fog.density, 0.02f);
    ASSERT_TRUE(parseFog({"--fog", "exp2,0.01"}, &o, &err)) << err;
    EXPECT_EQ(o.fog.mode, SceneFog::Mode::Exp2);
    for (const char* bad : {"60,5", "5,5", "-1,4", "exp,-0.1", "exp3,0.1", "5", "exp,x", "1,2,3"}) {
        Options b;
        EXPECT_FALSE(parseFog({"--fog", bad}, &b, &err)) << bad;
        EXPECT_EQ(err.rfind("--fog: expected", 0), 0u) << bad << ": " << err;
        EXPECT_FALSE(b.fog.on()) << bad;
    }
    EXPECT_NE(usage().find("--fog START,END"), std::string::npos);
}

// Looking along the track: a point of asphalt is fogged as f clear + (1 - f) fogColour, with f
// GL's linear factor at its eye-space |z|; the sky (past any fog) is the fog colour; the plugin's
// view carries the same fog.
TEST(SceneFog, TheTrackIsFoggedByGlsFormulaAndThePluginGetsTheSameFog) {
    Options o = cubetest::sceneOnlyOptions(160, 120);
    const glm::vec3 eye(-100.0f, 2.0f, -3.0f);
    cubetest::fixCamera(o, eye, {-90.0f, 1.0f, -3.0f});
    auto frame = [&](const Options& opts, fx::ViewInfo* info) {
        Game game;
        std::string err;
        EXPECT_TRUE(game.Init(opts, &err)) << err;
        EXPECT_TRUE(cubetest::runFrames(game, 1));
        if (info) *info = game.chaseView().pluginView();
        EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
        return game.lastFrame();
    };
    fx::ViewInfo clearView, fogView;
    const ImageRGBA8 clear = frame(o, &clearView);
    Options f = o;
    f.fog.mode = SceneFog::Mode::Linear;
    f.fog.start = 4.0f;
    f.fog.end = 30.0f;
    const ImageRGBA8 fogged = frame(f, &fogView);
    EXPECT_FALSE(clearView.fog.on());
    EXPECT_EQ(fogView.fog.mode, fx::Fog::Mode::Linear);
    EXPECT_EQ(fogView.fog.start, 4.0f);
    EXPECT_EQ(fogView.fog.end, 30.0f);
    EXPECT_EQ(fogView.fog.color, f.fog.color);

    // Each pixel's own eye-space distance: the chase view's linear depth, read back.
    Game probe;
    std::string err;
    ASSERT_TRUE(probe.Init(o, &err)) << err;
    probe.captureNextSceneDepth();
    ASSERT_TRUE(cubetest::runFrames(probe, 1));
    const std::vector<float>& depth = probe.lastSceneDepth();
    ASSERT_EQ(depth.size(), size_t(160 * 120));
    int checked = 0;
    for (float ahead : {6.0f, 12.0f, 20.0f}) {
        const glm::vec3 p(-100.0f + ahead, 0.02f, -3.0f);
        const glm::ivec2 px = project(probe, p);
        ASSERT_TRUE(px.y > 0 && px.y < 120) << ahead;
        const float c = depth[size_t(px.y) * 160u + size_t(px.x)];  // rows as lastFrame()
        ASSERT_NEAR(c, std::fabs((clearView.view * glm::vec4(p, 1.0f)).z), 0.15f * ahead) << ahead;
        const float fog = std::clamp((30.0f - c) / (30.0f - 4.0f), 0.0f, 1.0f);
        const cubetest::Rgb a = pixel(clear, px.x, px.y), b = pixel(fogged, px.x, px.y);
        const int want[3] = {int(std::lround(fog * a.r + (1.0f - fog) * 255.0f * f.fog.color.r)),
                             int(std::lround(fog * a.g + (1.0f - fog) * 255.0f * f.fog.color.g)),
                             int(std::lround(fog * a.b + (1.0f - fog) * 255.0f * f.fog.color.b))};
        const int got[3] = {b.r, b.g, b.b};
        for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(got[k] - want[k]), 2) << ahead << " m, channel " << k;
        ++checked;
    }
    EXPECT_EQ(checked, 3);
    // The sky at the top of the picture: the fog colour.
    const cubetest::Rgb sky = pixel(fogged, 80, 2);
    EXPECT_NEAR(sky.r, 255.0f * f.fog.color.r, 1.0f);
    EXPECT_NEAR(sky.g, 255.0f * f.fog.color.g, 1.0f);
    EXPECT_NEAR(sky.b, 255.0f * f.fog.color.b, 1.0f);
}
