// Whole-engine tests on a headless OSMesa context: the CUBE sequence, the race scene on screen,
// legacy smoke, determinism and "leave out what the scene does not need".
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "GameTestUtil.h"
#include "gl/Gl.h"
#include "gl/Paths.h"
#include "platform/Trace.h"
#include "view/Buckets.h"

using namespace cube;
using cubetest::pixel;
using cubetest::project;

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace game_test {
namespace {

size_t indexOf(const std::vector<std::string>& calls, const std::string& name, size_t from = 0) {
    for (size_t i = from; i < calls.size(); ++i)
        if (calls[i] == name) return i;
    return std::string::npos;
}

}  // namespace

TEST(CubeSequence, InitUpdateRenderCallsHappenInTheDocumentedOrder) {
    Trace::clear();
    Trace::enable(true);
    Game game;
    std::string err;
    Options o = cubetest::smallOptions();
    ASSERT_TRUE(game.Init(o, &err)) << err;
    game.Dyn(1.0f / 60.0f);
    Trace::enable(false);
    const auto& c = Trace::calls();
    // Init sequence.
    const std::vector<std::string> init = {"Game::Init", "Game::InitProc", "SpecialFX::Init", "Reaction::Load",
                                           "cubeScene::CreateParticleSystem", "cubeParticleSystem::Initialize",
                                           "cubeParticleSystem::InitInternalParticle"};
    size_t at = 0;
    for (const std::string& name : init) {
        const size_t i = indexOf(c, name, at);
        ASSERT_NE(i, std::string::npos) << name << " missing or out of order";
        at = i + 1;
    }
    // Update then render, inside Game::Dyn.
    const std::vector<std::string> frame = {"Game::Dyn", "SpecialFX::Dyn", "Reaction::Continue", "Render::Dyn",
                                            "cubeScene::Render", "cubeView::Render", "cubeView::RenderObjects"};
    for (const std::string& name : frame) {
        const size_t i = indexOf(c, name, at);
        ASSERT_NE(i, std::string::npos) << name << " missing or out of order";
        at = i + 1;
    }
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

TEST(CubeSequence, BucketsHaveNamesAndAnExplicitOrder) {
    for (int i = 1; i < int(Bucket::Count); ++i) {
        EXPECT_LT(kBuckets[i - 1].order, kBuckets[i].order) << kBuckets[i].name;
    }
    EXPECT_STREQ(bucketInfo(Bucket::Opaque).name, "opaque");
    EXPECT_STREQ(bucketInfo(Bucket::AlphaTested).name, "alpha_tested");
    EXPECT_STREQ(bucketInfo(Bucket::Sky).name, "sky");
    EXPECT_STREQ(bucketInfo(Bucket::Particles).name, "particles");
    EXPECT_STREQ(bucketInfo(Bucket::Hud).name, "hud");
}

TEST(Render, CarAndGroundAppearWhereTheCameraSays) {
    Game game;
    std::string err;
    Options o = cubetest::smallOptions(320, 256);
    o.mirror = false;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    ASSERT_TRUE(cubetest::runFrames(game, 3));
    const ImageRGBA8& img = game.lastFrame();
    const DrivePose& pose = game.vehicle().pose();
    const glm::vec3 fwd(std::cos(pose.heading), 0.0f, -std::sin(pose.heading));
    // The car body's rear face (blue paint), which faces the chase camera.
    const glm::ivec2 car = project(game, pose.position - 2.15f * fwd + glm::vec3(0.0f, 0.5f, 0.0f));
    ASSERT_TRUE(car.x > 0 && car.x < img.width && car.y > 0 && car.y < img.height);
    const auto c = pixel(img, car.x, car.y);
    EXPECT_GT(c.b, c.r + 15) << "car paint is blue; got " << c.r << "," << c.g << "," << c.b;
    // Asphalt 4 m behind the car: dark, nearly grey.
    const glm::ivec2 road = project(game, pose.position - 4.0f * fwd + glm::vec3(0.0f, 0.02f, 0.0f));
    ASSERT_TRUE(road.y > 0 && road.y < img.height);
    const auto a = pixel(img, road.x, road.y);
    EXPECT_LT(std::max({a.r, a.g, a.b}) - std::min({a.r, a.g, a.b}), 25) << "asphalt is grey";
    EXPECT_LT(a.r, 140);
    // The sky at the top of the frame is bright blue.
    const auto s = pixel(img, img.width / 2, 2);
    EXPECT_GT(s.b, 150);
    EXPECT_GT(s.b, s.r);
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

TEST(Render, LegacySmokeAppearsOnceTheRearWheelsSlip) {
    Options o = cubetest::smallOptions(320, 256);
    o.fx = FxPath::Legacy;
    o.mirror = false;
    // `game` started at drive time `start` and run for `frames` frames.
    auto runFrom = [&](Game& game, double start, int frames) {
        std::string err;
        o.startTime = start;
        ASSERT_TRUE(game.Init(o, &err)) << err;
        ASSERT_TRUE(cubetest::runFrames(game, frames));
    };
    // Before the burnout (t = 1 s): rolling, no sprites.
    {
        Game game;
        ASSERT_NO_FATAL_FAILURE(runFrom(game, 1.0, 30));
        EXPECT_EQ(game.specialFX().particlesAlive(), 0);
        EXPECT_EQ(game.passRuns().count("chase.legacy_smoke"), 0u);
    }
    // In the donut (t = 5.5 s): sprites alive and drawn every frame once the first exist.
    Game game;
    ASSERT_NO_FATAL_FAILURE(runFrom(game, 5.5, 45));
    EXPECT_GT(game.specialFX().particlesAlive(), 10);
    ASSERT_EQ(game.passRuns().count("chase.legacy_smoke"), 1u);
    EXPECT_GE(game.passRuns().at("chase.legacy_smoke"), 44) << "drawn in every frame after the first emission";
    EXPECT_EQ(game.passCulls().count("chase.legacy_smoke"), 0u);
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

TEST(Render, SameFixedDtAndSeedGiveIdenticalPixels) {
    Options o = cubetest::smallOptions(256, 192);
    o.startTime = 5.0;
    ImageRGBA8 first;
    for (int run = 0; run < 2; ++run) {
        Game game;
        std::string err;
        ASSERT_TRUE(game.Init(o, &err)) << err;
        ASSERT_TRUE(cubetest::runFrames(game, 40));
        if (run == 0) first = game.lastFrame();
        else EXPECT_TRUE(first.pixels == game.lastFrame().pixels) << "runs differ";
    }
}

TEST(Render, NoReactionsMeansNoPrepassAndNoParticleTargets) {
    Options o = cubetest::smallOptions(256, 192);
    o.reactions = paths::reactions() + "/none.yaml";
    o.startTime = 5.0;
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    ASSERT_TRUE(cubetest::runFrames(game, 10));
    EXPECT_EQ(game.specialFX().reactionCount(), 0);
    EXPECT_EQ(game.passRuns().count("chase.depth_prepass"), 0u);
    EXPECT_EQ(game.passCulls().count("chase.depth_prepass"), 0u);  // not even declared
    // Only the two views' colour targets exist: no depth or particle target was ever allocated.
    EXPECT_EQ(game.pool().stats().totalAllocations, 2u);
    for (const auto& kv : game.passRuns()) EXPECT_EQ(kv.first.find("particles"), std::string::npos) << kv.first;
}

TEST(Render, MirrorViewAppearsWhereTheInsetIsPlaced) {
    Options o = cubetest::smallOptions(320, 256);
    o.startTime = 2.0;
    ImageRGBA8 with, without;
    for (int run = 0; run < 2; ++run) {
        Game game;
        std::string err;
        o.mirror = run == 0;
        ASSERT_TRUE(game.Init(o, &err)) << err;
        ASSERT_TRUE(cubetest::runFrames(game, 2));
        (run == 0 ? with : without) = game.lastFrame();
    }
    // Inset: 30% x 13% of the view, centred, 12 px from the top, with a 3 px dark frame.
    const int iw = int(320 * 0.30f), ih = int(256 * 0.13f);
    const int x0 = (320 - iw) / 2, y0 = 12;  // top-down rows
    int changedInside = 0, changedOutside = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 320; ++x) {
            const bool inside = x >= x0 - 3 && x < x0 + iw + 3 && y >= y0 - 3 && y < y0 + ih + 3;
            const auto a = pixel(with, x, y), b = pixel(without, x, y);
            const bool differs = a.r != b.r || a.g != b.g || a.b != b.b;
            (inside ? changedInside : changedOutside) += differs ? 1 : 0;
        }
    EXPECT_GT(changedInside, (iw * ih) / 2) << "the mirror inset is drawn in its rectangle";
    EXPECT_EQ(changedOutside, 0) << "and nowhere else";
    // The frame border is dark.
    const auto border = pixel(with, x0 - 2, y0 + ih / 2);
    EXPECT_LT(border.r + border.g + border.b, 60);
}

TEST(Scene, MissingOrCorruptSceneGivesAnErrorNamingTheFile) {
    Options o = cubetest::smallOptions(64, 64);
    o.scene = "/nonexistent/track.gltf";
    Game game;
    std::string err;
    EXPECT_FALSE(game.Init(o, &err));
    EXPECT_NE(err.find("/nonexistent/track.gltf"), std::string::npos) << err;
}

// The window's E key and --explode-at both go through Game::fireExplosionAtCar: every layer of
// reactions/explosion.yaml emits in the next step, nothing before.
TEST(Game, TheExplosionRecipeFiresAtTheCarOnDemand) {
    Options o = cubetest::smallOptions(96, 80);
    o.mirror = false;
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    fx::Plugin* plugin = game.specialFX().plugin();
    ASSERT_NE(plugin, nullptr);
    auto explosionEmitted = [&] {
        uint64_t n = 0;
        int layers = 0;
        for (int i = 0; i < plugin->reactionCount(); ++i) {
            const fx::ReactionStats s = plugin->reactionStats(i);
            if (s.name.rfind("explosion.", 0) == 0) {
                n += s.emitted;
                ++layers;
            }
        }
        return std::make_pair(layers, n);
    };
    for (int i = 0; i < 5; ++i) game.Update(1.0f / 60.0f);
    const auto before = explosionEmitted();
    ASSERT_GE(before.first, 2) << "the explosion recipe has several layers";
    EXPECT_EQ(before.second, 0u);
    ASSERT_TRUE(game.fireExplosionAtCar());
    game.Update(1.0f / 60.0f);
    EXPECT_GT(explosionEmitted().second, 0u);
}

// --explode-at at the start time (0 by default) means the first frame: the recipe fires in the
// first step, once.
TEST(Game, ExplodeAtTheStartTimeFiresInTheFirstStep) {
    Options o = cubetest::smallOptions(96, 80);
    o.mirror = false;
    o.explodeAt = o.startTime;
    Game game;
    std::string err;
    ASSERT_TRUE(game.Init(o, &err)) << err;
    ASSERT_TRUE(game.checkExplodeAt(&err)) << err;
    fx::Plugin* plugin = game.specialFX().plugin();
    ASSERT_NE(plugin, nullptr);
    auto explosionEmitted = [&] {
        uint64_t n = 0;
        for (int i = 0; i < plugin->reactionCount(); ++i) {
            const fx::ReactionStats s = plugin->reactionStats(i);
            if (s.name.rfind("explosion.", 0) == 0) n += s.emitted;
        }
        return n;
    };
    EXPECT_EQ(explosionEmitted(), 0u);
    game.Update(1.0f / 60.0f);
    const uint64_t first = explosionEmitted();
    EXPECT_GT(first, 0u);
    // Once: the steps after it emit only what the first burst's layers still let out, no second burst.
    for (int i = 0; i < 3; ++i) game.Update(1.0f / 60.0f);
    EXPECT_LT(explosionEmitted(), 2 * first);
}
}  // namespace game_test
