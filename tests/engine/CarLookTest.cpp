// A car that reads as a car. Its wheels are seen whole: from the side the rim (bright,
// metallic grey) shows at the hub, and from the chase camera the rear tyres show beside the
// tail instead of being hidden inside the body.
#include <gtest/gtest.h>

#include "GameTestUtil.h"
#include "gl/Gl.h"

using namespace cube;
using cubetest::pixel;
using cubetest::project;

namespace {

Options carOptions() { return cubetest::sceneOnlyOptions(320, 256); }

}  // namespace

TEST(CarLook, FromTheSideTheRimsShowAtTheHubs) {
    Options o = carOptions();
    o.startTime = 4.0;  // stopped at (-7.5, 0, 4), heading +X, before the donut
    o.stationaryCar = true;
    cubetest::fixCamera(o, {-7.5f, 0.5f, -3.0f}, {-7.5f, 0.4f, 4.0f});  // from the left
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    ASSERT_TRUE(cubetest::runFrames(game, 1));
    const glm::mat4 car = game.vehicle().transform();
    for (const glm::vec3 hub : {glm::vec3(1.35f, 0.33f, -0.8f), glm::vec3(-1.35f, 0.33f, -0.8f)}) {
        // The hub cap's outer face (z = -0.91 in the car) and the tyre 0.29 m below the hub.
        const glm::ivec2 cap = project(game, glm::vec3(car * glm::vec4(hub + glm::vec3(0, 0, -0.115f), 1.0f)));
        const glm::ivec2 tread = project(game, glm::vec3(car * glm::vec4(hub + glm::vec3(0, -0.29f, -0.12f), 1.0f)));
        const cubetest::Rgb c = pixel(game.lastFrame(), cap.x, cap.y), t = pixel(game.lastFrame(), tread.x, tread.y);
        // The left side is in shade (ambient only): the rim is a mid grey there, the tyre near black.
        EXPECT_GT(c.r + c.g + c.b, 180) << "rim at x = " << hub.x << ": " << c.r << "," << c.g << "," << c.b;
        EXPECT_LT(std::abs(c.b - c.r), 30) << "rim is grey, not paint";
        EXPECT_LT(t.r + t.g + t.b, 90) << "tyre at x = " << hub.x << ": " << t.r << "," << t.g << "," << t.b;
    }
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

TEST(CarLook, FromTheChaseCameraTheRearTyresShowBesideTheTail) {
    Options o = carOptions();
    o.startTime = 1.0;
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    ASSERT_TRUE(cubetest::runFrames(game, 2));
    const glm::mat4 car = game.vehicle().transform();
    for (float side : {-1.0f, 1.0f}) {
        // The back of each rear tyre, low and outboard: behind it a body as wide as the track
        // would show blue paint.
        const glm::vec3 p(-1.35f - 0.28f, 0.16f, side * 0.85f);
        const glm::ivec2 px = project(game, glm::vec3(car * glm::vec4(p, 1.0f)));
        const cubetest::Rgb c = pixel(game.lastFrame(), px.x, px.y);
        EXPECT_LT(c.r + c.g + c.b, 120) << "rear tyre, side " << side << ": " << c.r << "," << c.g << "," << c.b;
        EXPECT_LT(c.b, c.r + 20) << "not paint";
    }
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}
