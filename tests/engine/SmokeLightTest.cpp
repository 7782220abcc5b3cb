// The game lights the plugin's smoke with its sun, and the smoke shadows the ground.
//   - on the burnout, pixels the smoke does not cover get darker with lit smoke (its shadow on
//     the track) and never brighter; --unlit-smoke leaves every uncovered pixel as the bare frame;
//   - the lit smoke's shading follows --sun (a different sun, a different cloud);
//   - no GL error.
#include <gtest/gtest.h>

#include <cstdlib>

#include "GameTestUtil.h"
#include "gl/Gl.h"

using namespace cube;

namespace {

struct ShadowCount {
    long uncovered = 0;  ///< pixels the smoke does not cover (unlit frame == bare frame)
    long darker = 0;     ///< of those, darker by more than 8/255 in the frame under test
    long brighter = 0;   ///< of those, brighter by more than 1/255
};

ShadowCount countShadow(const ImageRGBA8& bare, const ImageRGBA8& unlit, const ImageRGBA8& test) {
    ShadowCount c;
    for (size_t i = 0; i + 3 < bare.pixels.size(); i += 4) {
        bool covered = false;
        for (int k = 0; k < 3; ++k) covered |= unlit.pixels[i + k] != bare.pixels[i + k];
        if (covered) continue;
        ++c.uncovered;
        int worstDown = 0, worstUp = 0;
        for (int k = 0; k < 3; ++k) {
            const int d = int(test.pixels[i + k]) - int(bare.pixels[i + k]);
            worstDown = std::max(worstDown, -d);
            worstUp = std::max(worstUp, d);
        }
        if (worstDown > 8) ++c.darker;
        if (worstUp > 1) ++c.brighter;
    }
    return c;
}

class SmokeLight : public ::testing::Test {
protected:
    // The burnout 1.5 s in (as docs/images), then one frame in each of the three ways.
    void SetUp() override {
        Options o = cubetest::smallOptions(240, 192);
        o.mirror = false;
        o.startTime = 4.5;
        o.mode = "soft";
        o.sunAzimuth = 300.0;
        o.sunElevation = 35.0;
        std::string err;
        ASSERT_TRUE(game.Init(o, &err)) << err;
        ASSERT_TRUE(cubetest::runFrames(game, 90));
    }
    ImageRGBA8 frame(bool effects, bool lit) {
        game.options().effects = effects;
        if (lit) {
            game.specialFX().setSceneLight(game.sun());
        } else {
            game.specialFX().plugin()->clearSceneLight();
        }
        game.captureNextFrame();
        game.Dyn(0.0f);  // the same simulated state: only the rendering changes
        return game.lastFrame();
    }
    Game game;
};

TEST_F(SmokeLight, LitSmokeShadowsTheTrackAndUnlitSmokeDoesNot) {
    const ImageRGBA8 bare = frame(false, true);
    const ImageRGBA8 unlit = frame(true, false);
    const ImageRGBA8 lit = frame(true, true);
    const ShadowCount withLight = countShadow(bare, unlit, lit);
    const ShadowCount withoutLight = countShadow(bare, unlit, unlit);
    std::printf("[ measured ] %ld uncovered pixels: %ld darker under the smoke's shadow, %ld brighter\n",
                withLight.uncovered, withLight.darker, withLight.brighter);
    ASSERT_GT(withLight.uncovered, long(bare.pixels.size() / 4 / 4)) << "the smoke covers almost everything";
    EXPECT_GT(withLight.darker, long(bare.pixels.size() / 4 / 200)) << "a shadow of at least 0.5 % of the frame";
    EXPECT_EQ(withLight.brighter, 0) << "a shadow only takes light away";
    EXPECT_EQ(withoutLight.darker, 0);
    // The smoke itself is shaded: lit and unlit differ where it covers.
    EXPECT_LT(cubetest::psnr(unlit, lit), 40.0);
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

TEST_F(SmokeLight, TheCloudFollowsTheSun) {
    const ImageRGBA8 a = frame(true, true);
    ASSERT_TRUE(game.setSun(120.0, 35.0));
    const ImageRGBA8 b = frame(true, true);
    EXPECT_LT(cubetest::psnr(a, b), 35.0) << "moving the sun relights the scene and the cloud";
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

}  // namespace
