// Game::captureNextSceneDepth: an application (fxbench's depth-edge mask) reads the chase view's
// scene depth from the engine's own frame; no copy of the depth prepass is drawn anywhere else.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "GameTestUtil.h"

using namespace cube;

TEST(SceneDepthCapture, TheFramesOwnSceneDepthIsReadBackOnlyWhenAsked) {
    Options o = cubetest::smallOptions(160, 128);
    o.startTime = 4.5;
    o.mirror = false;
    o.mode = "hard";  // hard particles read no scene depth: normally no prepass at all
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    for (int i = 0; i < 30; ++i) game.Update(1.0f / 60.0f);
    game.RenderFrame();
    auto ran = [&](const std::string& pass) {
        const auto& e = game.graph().report().executed;
        return std::find(e.begin(), e.end(), pass) != e.end();
    };
    EXPECT_FALSE(ran("chase.depth_prepass"));
    EXPECT_TRUE(game.lastSceneDepth().empty());

    game.captureNextSceneDepth();
    game.RenderFrame();
    EXPECT_FALSE(ran("chase.depth_prepass"));  // the opaque pass writes the depth it reads back
    EXPECT_TRUE(ran("chase.opaque"));
    EXPECT_TRUE(ran("chase.scene_depth_readback"));
    const std::vector<float>& d = game.lastSceneDepth();
    ASSERT_EQ(d.size(), size_t(160 * 128));
    // Sky at the top of the chase view is "infinitely far"; the track below is metres away.
    const size_t sky = std::count_if(d.begin(), d.end(), [](float v) { return v >= 1e29f; });
    const size_t near = std::count_if(d.begin(), d.end(), [](float v) { return v > 0.1f && v < 200.0f; });
    EXPECT_GT(sky, d.size() / 20);
    EXPECT_GT(near, d.size() / 4);
    EXPECT_EQ(sky + near + size_t(std::count_if(d.begin(), d.end(), [](float v) { return v >= 200.0f && v < 1e29f; })),
              d.size());  // every value is a depth: no NaN, nothing negative

    // One request, one frame.
    game.RenderFrame();
    EXPECT_FALSE(ran("chase.depth_prepass"));
}

// The two writers of the linear scene depth agree: the opaque pass's second render target
// (soft particles, no prepass) and the depth prepass that prepass-EQUAL keeps. Same frame, same
// values to float rounding, so soft particles fade the same either way.
TEST(SceneDepthCapture, OpaqueSecondTargetWritesWhatThePrepassWrites) {
    Options o = cubetest::smallOptions(160, 128);
    o.startTime = 4.5;
    o.mirror = false;
    o.mode = "soft";
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    for (int i = 0; i < 30; ++i) game.Update(1.0f / 60.0f);
    auto ran = [&](const std::string& pass) {
        const auto& e = game.graph().report().executed;
        return std::find(e.begin(), e.end(), pass) != e.end();
    };
    game.options().prepassEqual = false;
    game.captureNextSceneDepth();
    game.RenderFrame();
    ASSERT_FALSE(ran("chase.depth_prepass"));
    const std::vector<float> fromOpaque = game.lastSceneDepth();
    game.options().prepassEqual = true;
    game.captureNextSceneDepth();
    game.RenderFrame();
    ASSERT_TRUE(ran("chase.depth_prepass"));
    const std::vector<float> fromPrepass = game.lastSceneDepth();
    ASSERT_EQ(fromOpaque.size(), size_t(160 * 128));
    ASSERT_EQ(fromPrepass.size(), fromOpaque.size());
    size_t differing = 0, drawn = 0;
    for (size_t i = 0; i < fromOpaque.size(); ++i) {
        const float a = fromOpaque[i], b = fromPrepass[i];
        drawn += a < 1e29f;
        differing += std::fabs(a - b) > 1e-5f * std::fmax(1.0f, std::fabs(b));
    }
    EXPECT_GT(drawn, fromOpaque.size() / 2);
    EXPECT_EQ(differing, 0u);
}
