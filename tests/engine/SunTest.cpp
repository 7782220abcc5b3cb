// The sun is a parameter. Game::setSun relights the scene from the next frame: the
// ground follows the sun's height and the sky's sun disc sits where the sun is.
#include <gtest/gtest.h>

#include <cmath>

#include "GameTestUtil.h"
#include "gl/Gl.h"

using namespace cube;
using cubetest::pixel;
using cubetest::project;

namespace {

int brightness(const ImageRGBA8& img, glm::ivec2 p) {
    const cubetest::Rgb c = pixel(img, p.x, p.y);
    return c.r + c.g + c.b;
}

}  // namespace

TEST(Sun, SetSunValidatesAndKeepsTheLastGoodSun) {
    Options o = cubetest::smallOptions(64, 48);
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    const glm::vec3 former = glm::normalize(glm::vec3(-0.35f, 0.85f, 0.40f));
    EXPECT_LT(glm::length(game.sun().toSun - former), 1e-3f) << "the default is the former constant sun";
    EXPECT_TRUE(game.setSun(200.0, 10.0));
    const glm::vec3 set = game.sun().toSun;
    EXPECT_LT(glm::length(set - sunFromAngles(200.0, 10.0).toSun), 1e-6f);
    EXPECT_DOUBLE_EQ(game.options().sunElevation, 10.0);
    for (const auto& [az, el] : {std::pair<double, double>{0.0, 0.5}, {0.0, 91.0}, {NAN, 30.0}, {10.0, INFINITY}}) {
        EXPECT_FALSE(game.setSun(az, el)) << az << "," << el;
        EXPECT_EQ(game.sun().toSun, set) << "a refused sun changes nothing";
    }
}

// Looking along the track at the sky: the sun disc is drawn toward the sun, and the asphalt in
// front is lit less by a low sun than by a high one (Lambert: N.L = sin(elevation)).
TEST(Sun, TheSkyAndTheGroundFollowTheSun) {
    Options o = cubetest::sceneOnlyOptions(160, 120);
    const glm::vec3 eye(-100.0f, 2.0f, -3.0f);
    cubetest::fixCamera(o, eye, {-90.0f, 4.0f, -3.0f});
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    // The sun straight along the view: azimuth 0, elevation atan(2 / 10).
    const double el = glm::degrees(std::atan(0.2));
    auto frameWithSun = [&](double azimuth, double elevation) {
        EXPECT_TRUE(game.setSun(azimuth, elevation));
        EXPECT_TRUE(cubetest::runFrames(game, 1));
        return game.lastFrame();
    };
    const ImageRGBA8 ahead = frameWithSun(0.0, el), behind = frameWithSun(180.0, el);
    const glm::ivec2 centre = project(game, eye + 1000.0f * sunFromAngles(0.0, el).toSun);
    EXPECT_NEAR(centre.x, 80, 1);
    EXPECT_NEAR(centre.y, 60, 1);
    // The disc (pow(cos, 400): about 4 degrees across) over the sky's blue: near white.
    EXPECT_GT(brightness(ahead, centre), brightness(behind, centre) + 120);
    EXPECT_GT(pixel(ahead, centre.x, centre.y).b, 240);
    // Asphalt 12 m ahead on the track, lit from 60 vs 5 degrees above the horizon.
    const glm::ivec2 road = project(game, {-88.0f, 0.02f, -3.0f});
    ASSERT_TRUE(road.y > 60 && road.y < 120) << road.y;
    const ImageRGBA8 high = frameWithSun(90.0, 60.0), low = frameWithSun(90.0, 5.0);
    EXPECT_GT(brightness(high, road), brightness(low, road) + 60)
        << "high " << brightness(high, road) << ", low " << brightness(low, road);
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}
