// The extreme-case matrix (numerical stability on stiff and extreme inputs), run through the
// whole engine + plugin headless. For every case: no NaN or Inf in any particle stream, alive
// counts within capacity, output pixels finite-looking (the sky stays sky: a NaN vertex or a
// blown-up blend would smear it), no GL error, no crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "../engine/GameTestUtil.h"
#include "gl/Gl.h"
#include "gl/Paths.h"

using namespace cube;

namespace {

// Writes a one-reaction file: burnout smoke with the given overrides, returns its path.
std::string reactionFile(const std::string& tag, const std::string& particle, const std::string& render,
                         int capacity = 512, double rate = 120.0) {
    const std::string path = "/tmp/cube_extreme_" + std::to_string(::getpid()) + "_" + tag + ".yaml";
    std::ofstream f(path);
    f << "reactions:\n"
         "  - name: extreme\n"
         "    type: wheel_smoke\n"
         "    trigger: {slip_threshold: 0.3, surfaces: [asphalt, kerb, grass], wheels: rear}\n"
         "    emission: {rate: " << rate << ", capacity: " << capacity << "}\n"
         "    particle: {" << (particle.find("lifetime") == std::string::npos ? "lifetime: [1.0, 2.0]" : "")
      << (particle.empty() || particle.find("lifetime") != std::string::npos ? "" : ", ") << particle << "}\n"
         "    render: {technique: soft" << (render.empty() ? "" : ", " + render) << "}\n";
    return path;
}

struct Check {
    int alive = 0;
    int capacity = 0;
    bool finite = true;
};

Check checkParticles(Game& game) {
    Check c;
    fx::Plugin* plugin = game.specialFX().plugin();
    if (!plugin) {
        ADD_FAILURE() << "the game runs no fx plugin";
        c.finite = false;
        return c;
    }
    // The plugin's own health check reads every live particle's state streams.
    const fx::ParticleCheck check = plugin->checkParticles();
    c.alive = check.alive;
    c.capacity = check.capacity;
    c.finite = check.nonFinite == 0;
    return c;
}

// Runs `frames` frames at `dt` and checks state, pixels and GL errors.
// `skyVisible`: the top of the frame must still show sky (false when a particle is meant to
// cover everything); then it must still be a plausible light colour, not black or garbage.
void runAndCheck(Options o, int frames, float dt, const char* what, bool expectParticles = true,
                 bool skyVisible = true) {
    gl::resetErrorCount();
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << what << ": " << err;
    for (int i = 0; i < frames; ++i) {
        if (i + 1 == frames) game.captureNextFrame();
        game.Dyn(dt);
        const Check c = checkParticles(game);
        ASSERT_TRUE(c.finite) << what << ": non-finite particle state at frame " << i;
        ASSERT_LE(c.alive, c.capacity) << what;
    }
    if (expectParticles) {
        EXPECT_GT(checkParticles(game).alive, 0) << what;
    }
    EXPECT_TRUE(game.graph().report().error.empty()) << what << ": " << game.graph().report().error;
    const ImageRGBA8& img = game.lastFrame();
    ASSERT_EQ(img.width, o.width) << what << ": the last frame was rendered and read back";
    ASSERT_EQ(img.pixels.size(), size_t(o.width) * size_t(o.height) * 4u) << what;
    if (img.width >= 8 && img.height >= 8 && !o.fixedCamera) {
        // The top row of the chase view is sky: blue above red, not black, not white.
        const auto s = cubetest::pixel(img, img.width / 2, 0);
        if (skyVisible) {
            EXPECT_GT(s.b, s.r) << what;
            EXPECT_GT(s.b, 100) << what;
        } else {
            EXPECT_GT(std::min({s.r, s.g, s.b}), 100) << what;
        }
    }
    EXPECT_EQ(gl::errorCount(), 0) << what << ": " << gl::lastError();
}

Options base() {
    Options o = cubetest::smallOptions(96, 72);
    o.startTime = 4.6;  // the burnout: rear wheels spinning
    o.mirror = false;
    return o;
}

}  // namespace

class TimeStep : public ::testing::TestWithParam<float> {};
TEST_P(TimeStep, StaysFiniteAndBounded) {
    const float dt = GetParam();
    // Over at least a second of game time when dt allows, at most 40 frames.
    const int frames = dt > 0.0f ? std::min(40, std::max(4, int(1.0f / dt))) : 10;
    // A run shorter than ~0.1 s of game time may rightly emit nothing (rate 90/s per wheel).
    runAndCheck(base(), frames, dt, ("dt=" + std::to_string(dt)).c_str(), dt * float(frames) >= 0.1f);
}
INSTANTIATE_TEST_SUITE_P(Extreme, TimeStep, ::testing::Values(0.0f, 1e-6f, 1.0f / 240.0f, 1.0f / 30.0f, 0.5f, 2.0f, 5.0f));

class StiffDrag : public ::testing::TestWithParam<std::pair<double, float>> {};
TEST_P(StiffDrag, NoBlowUp) {
    const double k = GetParam().first;
    const float dt = GetParam().second;
    Options o = base();
    char particle[64];
    // Lifetimes longer than the 2 s step, so particles survive a hitch and can be checked.
    std::snprintf(particle, sizeof particle, "drag: %g, lifetime: [4, 6]", k);
    o.reactions = reactionFile("drag", particle, "");
    runAndCheck(o, 12, dt, ("k*dt=" + std::to_string(k * dt)).c_str());
}
INSTANTIATE_TEST_SUITE_P(Extreme, StiffDrag,
                         ::testing::Values(std::make_pair(6.0e5, 1.0f / 60.0f),  // k dt = 1e4
                                           std::make_pair(5.0e3, 2.0f),          // k dt = 1e4, 2 s hitch
                                           std::make_pair(0.0, 0.5f),            // no drag at all
                                           std::make_pair(1.0e-9, 1.0f / 60.0f)));

TEST(Extreme, ParticleCountsZeroOneAndCapacity) {
    Options o = base();
    o.reactions = paths::reactions() + "/none.yaml";
    runAndCheck(o, 5, 1.0f / 60.0f, "no reactions", false);
    o.reactions = reactionFile("one", "", "", 1, 1000.0);
    runAndCheck(o, 20, 1.0f / 60.0f, "capacity 1");
    o.reactions = reactionFile("full", "", "", 64, 100000.0);
    gl::resetErrorCount();
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    for (int i = 0; i < 20; ++i) game.Dyn(1.0f / 60.0f);
    EXPECT_EQ(checkParticles(game).alive, 64) << "a pool under a flood stays exactly full";
    EXPECT_EQ(gl::errorCount(), 0);
}

TEST(Extreme, ParticleSizesZeroAndHuge) {
    Options o = base();
    o.reactions = reactionFile("size0", "start_size: 0, end_size: 0, size_variation: 0", "");
    runAndCheck(o, 20, 1.0f / 60.0f, "size 0");
    o.reactions = reactionFile("size1e4", "start_size: 10000, end_size: 10000", "");
    for (const char* mode : {"hard", "soft", "spherical"}) {
        o.mode = mode;
        runAndCheck(o, 8, 1.0f / 60.0f, (std::string("size 1e4, ") + mode).c_str(), true, false);
    }
}

TEST(Extreme, SoftnessScaleZeroAndHuge) {
    Options o = base();
    o.mode = "soft";
    o.reactions = reactionFile("soft_inf", "", "softness: 1000000");  // scale 1e-6 ~ 0
    runAndCheck(o, 20, 1.0f / 60.0f, "softness scale ~0");
    o.reactions = reactionFile("soft_hard", "", "softness: 0.000001");  // scale 1e6
    runAndCheck(o, 20, 1.0f / 60.0f, "softness scale 1e6");
}

TEST(Extreme, ClipPlanes) {
    for (auto planes : {std::make_pair(0.01f, 1e5f), std::make_pair(1.0f, 1e7f)}) {
        Options o = base();
        o.nearPlane = planes.first;
        o.farPlane = planes.second;
        for (const char* mode : {"hard", "soft", "spherical"}) {
            o.mode = mode;
            o.quarterRes = std::string(mode) != "hard";
            o.quarterResAlways = std::string(mode) != "hard";
            runAndCheck(o, 10, 1.0f / 60.0f, (std::to_string(planes.first) + "/" + std::to_string(planes.second) + " " + mode).c_str());
        }
    }
}

TEST(Extreme, CameraInsideTheSmoke) {
    Options o = base();
    o.startTime = 5.5;
    // Eye in the donut cloud, 1 m up, looking across it.
    cubetest::fixCamera(o, {-6.5f, 1.0f, 3.0f}, {0.0f, 0.8f, 4.0f});
    for (const char* mode : {"hard", "soft", "spherical"}) {
        o.mode = mode;
        runAndCheck(o, 45, 1.0f / 60.0f, (std::string("camera inside, ") + mode).c_str());
    }
}

TEST(Extreme, StationaryCarBurnout) {
    Options o = base();
    o.stationaryCar = true;
    runAndCheck(o, 60, 1.0f / 60.0f, "stationary car");
}

TEST(Extreme, OnePixelView) {
    Options o = base();
    o.width = o.height = 1;
    o.quarterRes = true;
    o.quarterResAlways = true;
    runAndCheck(o, 10, 1.0f / 60.0f, "1x1 view");
}

TEST(Extreme, MinimisedViewDrawsAndAllocatesNothingThenRecovers) {
    gl::resetErrorCount();
    Options o = base();
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    game.Dyn(1.0f / 60.0f);
    const auto before = game.pool().stats();
    game.platform().resize(0, 0);
    for (int i = 0; i < 10; ++i) game.Dyn(1.0f / 60.0f);
    EXPECT_EQ(game.pool().stats().totalAllocations, before.totalAllocations);
    EXPECT_TRUE(checkParticles(game).finite);
    game.platform().resize(96, 72);
    game.captureNextFrame();
    game.Dyn(1.0f / 60.0f);
    EXPECT_EQ(game.lastFrame().width, 96);
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}
