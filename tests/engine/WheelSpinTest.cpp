// The wheels turn with the drive. After the car has rolled N metres a wheel node has
// turned N / r radians about its axle (the car's side axis, +Z), and nothing else about it moved.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "GameTestUtil.h"
#include "gl/Gl.h"

using namespace cube;

namespace {

// The wheel node's transform in the car's frame (the car root sits at the origin unmoved; the
// game applies the drive as a separate transform).
glm::mat4 wheelInCar(Game& game, int i) {
    const int node = game.vehicle().wheelNode(i);
    return game.scene().data().nodes[size_t(node)].world;
}

}  // namespace

TEST(WheelSpin, WheelsTurnByTheDistanceRolledOverTheRadiusAboutTheirAxle) {
    Options o = cubetest::smallOptions(64, 48);
    o.startTime = 0.2;  // on the opening straight at 15 m/s, changing lane
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    const float r = game.vehicle().wheelRadius();
    EXPECT_NEAR(r, 0.33f, 1e-3f) << "wheel_FL's box is 0.66 m tall";
    for (int i = 0; i < 4; ++i) ASSERT_GE(game.vehicle().wheelNode(i), 0) << Vehicle::kWheelNames[i];

    // 2.4 s in steps of 1/120 s (12.5 cm, 0.38 rad: well inside half a turn, so the step's angle
    // is read without ambiguity). The distance comes from the contact patches the game reports.
    constexpr int kSteps = 288;
    constexpr float kDt = 1.0f / 120.0f;
    std::array<double, 4> rolled{}, turned{};
    std::array<glm::mat4, 4> before;
    std::array<glm::vec3, 4> contact;
    for (int i = 0; i < 4; ++i) {
        before[size_t(i)] = wheelInCar(game, i);
        contact[size_t(i)] = game.vehicle().wheels()[size_t(i)].contact;
    }
    // The axle: the line through the left and right front hubs (the car's +Z).
    const glm::vec3 axle = glm::normalize(glm::vec3(before[1][3]) - glm::vec3(before[0][3]));
    EXPECT_NEAR(axle.z, 1.0f, 1e-5f);
    float heading = game.vehicle().pose().heading;
    for (int s = 0; s < kSteps; ++s) {
        game.Update(kDt);
        const float h = 0.5f * (heading + game.vehicle().pose().heading);
        heading = game.vehicle().pose().heading;
        const glm::vec3 fwd(std::cos(h), 0.0f, -std::sin(h));
        for (int i = 0; i < 4; ++i) {
            const size_t w = size_t(i);
            const glm::vec3 c = game.vehicle().wheels()[w].contact;
            rolled[w] += double(glm::dot(c - contact[w], fwd));
            contact[w] = c;
            const glm::mat4 now = wheelInCar(game, i);
            // This step's turn in the car's frame: about the axle, through the unmoved hub.
            const glm::mat3 turn = glm::mat3(now) * glm::transpose(glm::mat3(before[w]));
            ASSERT_LT(glm::length(turn * axle - axle), 1e-4f)
                << Vehicle::kWheelNames[i] << " turns about its axle, step " << s;
            ASSERT_LT(glm::length(glm::vec3(now[3]) - glm::vec3(before[w][3])), 1e-5f)
                << Vehicle::kWheelNames[i] << ": the hub stays put, step " << s;
            before[w] = now;
            turned[w] += double(std::atan2(turn[0][1], turn[0][0]));  // about +Z, right-handed
        }
    }
    for (int i = 0; i < 4; ++i) {
        const size_t w = size_t(i);
        EXPECT_GT(rolled[w], 30.0) << "the car drove about 36 m";
        // Rolling forward turns the tyre's top toward +X: negative about +Z. Tolerance 0.01 rad
        // (3 mm of tread over 36 m): the engine's tabulation and this test's sampling together.
        EXPECT_NEAR(turned[w], -rolled[w] / double(r), 0.01) << Vehicle::kWheelNames[i];
    }
    EXPECT_EQ(gl::errorCount(), 0);
}
