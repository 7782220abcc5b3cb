// The motion keys: alpha_over_life / size_over_life curves, turbulence and vortex. One test
// per rule, asserting the code, the line and the key (not the wording).
#include <string>

#include <gtest/gtest.h>

#include "../../fx_plugin/reactions/ReactionLoader.h"
#include "../../fx_plugin/sim/Lifecycle.h"
#include "ReactionTextTest.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace motion_keys_test {
namespace {

using fx::ErrorCode;
using reactiontest::dump;
using reactiontest::Loaded;

// A reaction "a" of type wheel_smoke whose further keys, from line 4 on, are `body`.
std::string reaction(const std::string& body) { return "reactions:\n  - name: a\n    type: wheel_smoke\n" + body; }

Loaded load(const std::string& body) { return reactiontest::loadText(reaction(body)); }
Loaded loadRaw(const std::string& text) { return reactiontest::loadText(text); }

using reactiontest::Rejected;

class RejectedKey : public ::testing::TestWithParam<Rejected> {};

TEST_P(RejectedKey, IsTheOnlyDiagnostic) { reactiontest::expectRejected(GetParam()); }

TEST(MotionKeys, CurvesAndTurbulenceLoad) {
    Loaded r = load(
        "    particle:\n"
        "      alpha_over_life: [{t: 0, v: 0}, {t: 0.1, v: 1}, {t: 1, v: 0}]\n"
        "      size_over_life: [{t: 0, v: 0}, {t: 0.5, v: 0.9}, {t: 1, v: 1}]\n"
        "    turbulence: {strength: 1.5, scale: 3, speed: 0.4, octaves: 2}\n"
        "    vortex: {strength: -0.8, radius: 1.2}\n");
    ASSERT_TRUE(r.ok) << dump(r.diags);
    const fx::ReactionDesc& d = r.set.reactions[0];
    ASSERT_EQ(d.particle.alphaOverLife.size(), 3u);
    EXPECT_FLOAT_EQ(d.particle.alphaOverLife[1].t, 0.1f);
    EXPECT_FLOAT_EQ(fx::fadeAt(d.particle, 0.05f), 0.5f);   // halfway up the first segment
    EXPECT_FLOAT_EQ(fx::fadeAt(d.particle, 0.55f), 0.5f);   // halfway down the second
    EXPECT_FLOAT_EQ(fx::sizeAt(d.particle, 1.0f, 3.0f, 0.25f), 1.0f + 2.0f * 0.45f);
    EXPECT_FLOAT_EQ(d.turbulence.strength, 1.5f);
    EXPECT_FLOAT_EQ(d.turbulence.scale, 3.0f);
    EXPECT_FLOAT_EQ(d.turbulence.speed, 0.4f);
    EXPECT_EQ(d.turbulence.octaves, 2);
    EXPECT_FLOAT_EQ(d.vortex.strength, -0.8f);
    EXPECT_FLOAT_EQ(d.vortex.radius, 1.2f);
}

TEST(MotionKeys, DefaultsAreOffAndKeepTheOldCurves) {
    Loaded r = load("");
    ASSERT_TRUE(r.ok) << dump(r.diags);
    const fx::ReactionDesc& d = r.set.reactions[0];
    EXPECT_FALSE(d.turbulence.enabled());
    EXPECT_FALSE(d.vortex.enabled());
    EXPECT_TRUE(d.particle.alphaOverLife.empty());
    EXPECT_FLOAT_EQ(fx::fadeAt(d.particle, 0.3f), fx::fadeAt(0.3f, d.particle.fadeIn, d.particle.fadeOut));
    EXPECT_FLOAT_EQ(fx::sizeAt(d.particle, 1.0f, 3.0f, 0.3f), fx::sizeAt(1.0f, 3.0f, 0.3f));
}

const Rejected kMotionKeys[] = {
    {"CurveTimesOutOfOrderAreRejected",
     reaction("    particle:\n"
              "      alpha_over_life:\n"
              "        - {t: 0.5, v: 1}\n"
              "        - {t: 0.2, v: 0}\n"),
     ErrorCode::OutOfRange, 7, 0, "reactions[0].particle.alpha_over_life[1].t"},
    {"CurveValueOutOfRangeIsRejected",
     reaction("    particle:\n"
              "      size_over_life: [{t: 0, v: 0}, {t: 1, v: 1.5}]\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].particle.size_over_life[1].v"},
    {"CurveTimeOutsideLifeIsRejected",
     reaction("    particle:\n"
              "      size_over_life: [{t: -0.1, v: 0}]\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].particle.size_over_life[0].t"},
    {"CurvePointWithoutValueIsRejected",
     reaction("    particle:\n"
              "      alpha_over_life: [{t: 0}]\n"),
     ErrorCode::MissingKey, 5, 0, "reactions[0].particle.alpha_over_life[0].v"},
    {"EmptyCurveIsRejected",
     reaction("    particle:\n"
              "      alpha_over_life: []\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].particle.alpha_over_life"},
    {"AlphaCurveAndFadeTogetherAreRejected",
     reaction("    particle:\n"
              "      fade_out: 0.5\n"
              "      alpha_over_life: [{t: 0, v: 1}]\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].particle.fade_out"},
    {"TooManyOctavesAreRejected",
     reaction("    turbulence:\n"
              "      octaves: 7\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].turbulence.octaves"},
    {"NegativeTurbulenceStrengthIsRejected",
     reaction("    turbulence: {strength: -1}\n"),
     ErrorCode::OutOfRange, 4, 0, "reactions[0].turbulence.strength"},
    {"ZeroVortexRadiusIsRejected",
     reaction("    vortex:\n"
              "      radius: 0\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].vortex.radius"},
    {"UnknownTurbulenceKeyIsRejected",
     reaction("    turbulence:\n"
              "      strenght: 1\n"),
     ErrorCode::UnknownKey, 5, 0, "reactions[0].turbulence.strenght"},
    {"TextForANumberIsRejected",
     reaction("    vortex:\n"
              "      strength: fast\n"),
     ErrorCode::WrongType, 5, 0, "reactions[0].vortex.strength"},
};
INSTANTIATE_TEST_SUITE_P(MotionKeys, RejectedKey, ::testing::ValuesIn(kMotionKeys), reactiontest::rejectedName);

TEST(StatelessKeys, StatelessAdditiveWithGravityLoads) {
    Loaded r = load("    particle: {gravity: 9.81}\n"
                    "    render: {technique: stateless, blend: additive}\n");
    ASSERT_TRUE(r.ok) << dump(r.diags);
    const fx::ReactionDesc& d = r.set.reactions[0];
    EXPECT_TRUE(d.render.stateless);
    EXPECT_EQ(d.render.technique, fx::Technique::Hard);  // drawn as hard billboards
    EXPECT_FLOAT_EQ(d.particle.gravity, 9.81f);
}

const Rejected kStatelessKeys[] = {
    {"StatelessNeedsAdditiveBlending",
     reaction("    render:\n"
              "      technique: stateless\n"
              "      blend: alpha\n"),
     ErrorCode::OutOfRange, 6, 0, "reactions[0].render.blend"},
    {"StatelessRefusesTurbulence",
     reaction("    render: {technique: stateless, blend: additive}\n"
              "    turbulence: {strength: 1}\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].turbulence"},
    {"NegativeGravityIsRejected",
     reaction("    particle:\n"
              "      gravity: -9.81\n"),
     ErrorCode::OutOfRange, 5, 0, "reactions[0].particle.gravity"},
};
INSTANTIATE_TEST_SUITE_P(StatelessKeys, RejectedKey, ::testing::ValuesIn(kStatelessKeys), reactiontest::rejectedName);

TEST(LayerKeys, ALayeredReactionExpandsIntoOneReactionPerLayer) {
    Loaded r = loadRaw("reactions:\n"
                       "  - name: hit\n"
                       "    trigger: {collision_threshold: 0.3}\n"
                       "    layers:\n"
                       "      - {name: sparks, type: collision_scrape, render: {technique: stateless, blend: additive}}\n"
                       "      - name: flash\n"
                       "        type: collision_burst\n"
                       "        trigger: {collision_threshold: 0.7}\n");
    ASSERT_TRUE(r.ok) << dump(r.diags);
    ASSERT_EQ(r.set.reactions.size(), 2u);
    EXPECT_EQ(r.set.reactions[0].name, "hit.sparks");
    EXPECT_EQ(r.set.reactions[0].type, fx::ReactionType::CollisionScrape);
    EXPECT_TRUE(r.set.reactions[0].render.stateless);
    EXPECT_FLOAT_EQ(r.set.reactions[0].trigger.collisionThreshold, 0.3f);  // the parent's
    EXPECT_EQ(r.set.reactions[1].name, "hit.flash");
    EXPECT_FLOAT_EQ(r.set.reactions[1].trigger.collisionThreshold, 0.7f);  // its own wins
    EXPECT_EQ(r.set.reactions[1].sourceLine, 6);  // the layer's own line
}

TEST(LayerKeys, LayerNamesCollideWithOtherReactions) {
    Loaded r = loadRaw("reactions:\n"
                       "  - {name: hit.a, type: dust}\n"
                       "  - name: hit\n"
                       "    layers: [{name: a, type: dust}]\n");
    reactiontest::expectDiagnostics(r, {{ErrorCode::DuplicateName}});
}

const Rejected kLayerKeys[] = {
    {"ALayeredReactionHoldsOnlyNameTriggerAndLayers",
     "reactions:\n"
     "  - name: hit\n"
     "    type: dust\n"
     "    layers:\n"
     "      - {name: a, type: dust}\n",
     ErrorCode::OutOfRange, 3, 0, "reactions[0].type"},
    {"LayersDoNotNest",
     "reactions:\n"
     "  - name: hit\n"
     "    layers:\n"
     "      - name: a\n"
     "        layers: [{name: b, type: dust}]\n",
     ErrorCode::OutOfRange, 5, 0, "reactions[0].layers[0].layers"},
    {"ALayerNeedsAType",
     "reactions:\n"
     "  - name: hit\n"
     "    layers:\n"
     "      - name: a\n",
     ErrorCode::MissingKey, 4, 0, "reactions[0].layers[0].type"},
};
INSTANTIATE_TEST_SUITE_P(LayerKeys, RejectedKey, ::testing::ValuesIn(kLayerKeys), reactiontest::rejectedName);

}  // namespace
}  // namespace motion_keys_test
