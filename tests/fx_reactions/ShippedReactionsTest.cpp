// The reaction files the game ships: each loads with zero diagnostics and says what its name
// promises (the tuning is data, but the type, technique and trigger are part of the contract).
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "../../fx_plugin/sim/Lifecycle.h"

#include "../../fx_plugin/reactions/ReactionLoader.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace shipped_reactions_test {
namespace {

const std::string kReactionsDir = std::string(CUBE_SOURCE_DIR) + "/reactions";

std::string dump(const fx::Diagnostics& d) {
    std::string s;
    for (const auto& x : d) s += x.str() + "\n";
    return s;
}

TEST(ShippedReactions, EveryFileLoadsWithoutDiagnostics) {
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(kReactionsDir)) {
        if (e.path().extension() != ".yaml") continue;
        ++files;
        fx::ReactionSet set;
        fx::Diagnostics diags;
        EXPECT_TRUE(fx::loadReactionFile(e.path().string(), &set, &diags)) << e.path();
        EXPECT_TRUE(diags.empty()) << dump(diags);
    }
    EXPECT_EQ(files, 7);
}

TEST(ShippedReactions, DirectoryLoadsTwelveReactionsInFileOrder) {
    fx::ReactionSet set;
    fx::Diagnostics diags;
    ASSERT_TRUE(fx::loadReactionDirectory(kReactionsDir, &set, &diags)) << dump(diags);
    EXPECT_TRUE(diags.empty());
    ASSERT_EQ(set.reactions.size(), 12u);
    // Sorted file names: barrier_burst, barrier_scrape (three layers, in file order),
    // burnout_smoke, explosion (five layers), none, offtrack_dust, tyre_steam.
    const char* names[] = {"barrier_burst", "barrier_scrape.sparks", "barrier_scrape.flash",
                           "barrier_scrape.smoke", "burnout_smoke", "explosion.flash",
                           "explosion.fireball", "explosion.smoke_shell", "explosion.sparks",
                           "explosion.debris", "offtrack_dust", "tyre_steam"};
    for (size_t i = 0; i < 12; ++i) EXPECT_EQ(set.reactions[i].name, names[i]);
    EXPECT_EQ(set.files.size(), 7u);
}

TEST(ShippedReactions, NoneIsAValidEmptySet) {
    fx::ReactionSet set;
    set.reactions.resize(2);  // must be replaced by the empty set
    fx::Diagnostics diags;
    ASSERT_TRUE(fx::loadReactionFile(kReactionsDir + "/none.yaml", &set, &diags)) << dump(diags);
    EXPECT_TRUE(set.reactions.empty());
}

TEST(ShippedReactions, BurnoutSmokeIsSoftRearWheelSmokeThatGrowsToMetres) {
    fx::ReactionSet set;
    fx::Diagnostics diags;
    ASSERT_TRUE(fx::loadReactionFile(kReactionsDir + "/burnout_smoke.yaml", &set, &diags));
    ASSERT_EQ(set.reactions.size(), 1u);
    const fx::ReactionDesc& r = set.reactions[0];
    EXPECT_EQ(r.type, fx::ReactionType::WheelSmoke);
    EXPECT_EQ(r.trigger.wheels, fx::WheelSet::Rear);
    EXPECT_EQ(r.render.technique, fx::Technique::Soft);
    EXPECT_GE(r.particle.endSize, 3.0f);  // "a few metres" next to a 4.4 m car
    EXPECT_GT(r.particle.endSize, r.particle.startSize);
    EXPECT_TRUE(r.trigger.surfaces & fx::surfaceBit(fx::Surface::Asphalt));
    // Grey-white: every stop nearly neutral and bright.
    for (const fx::ColorStop& s : r.particle.colorRamp) {
        EXPECT_GT(s.rgba.r, 0.7f);
        EXPECT_NEAR(s.rgba.r, s.rgba.b, 0.05f);
    }
    EXPECT_EQ(r.sourceLine, 7);
}

TEST(ShippedReactions, DustIsOffTrackOnlyOnAnyWheel) {
    fx::ReactionSet set;
    ASSERT_TRUE(fx::loadReactionFile(kReactionsDir + "/offtrack_dust.yaml", &set, nullptr));
    const fx::ReactionDesc& r = set.reactions.at(0);
    EXPECT_EQ(r.type, fx::ReactionType::Dust);
    EXPECT_EQ(r.trigger.wheels, fx::WheelSet::All);
    const uint32_t offTrack = fx::surfaceBit(fx::Surface::Grass) |
                              fx::surfaceBit(fx::Surface::Gravel) | fx::surfaceBit(fx::Surface::Sand);
    EXPECT_EQ(r.trigger.surfaces, offTrack);
    // Brownish: red above blue.
    EXPECT_GT(r.particle.colorRamp.front().rgba.r, r.particle.colorRamp.front().rgba.b + 0.1f);
}

TEST(ShippedReactions, BarrierBurstFitsItsBurstInItsPool) {
    fx::ReactionSet set;
    ASSERT_TRUE(fx::loadReactionFile(kReactionsDir + "/barrier_burst.yaml", &set, nullptr));
    const fx::ReactionDesc& r = set.reactions.at(0);
    EXPECT_EQ(r.type, fx::ReactionType::CollisionBurst);
    EXPECT_GT(r.emission.burst, 0);
    EXPECT_LE(r.emission.burst, r.emission.capacity);
}

fx::ReactionDesc shipped(const char* file) {
    fx::ReactionSet set;
    fx::Diagnostics diags;
    EXPECT_TRUE(fx::loadReactionFile(kReactionsDir + "/" + file, &set, &diags)) << dump(diags);
    return set.reactions.empty() ? fx::ReactionDesc{} : set.reactions[0];
}

// Opacity of a particle `seconds` after birth (mean lifetime): ramp alpha x alpha profile.
float alphaAfter(const fx::ReactionDesc& r, float seconds) {
    const float life = 0.5f * (r.particle.lifetimeMin + r.particle.lifetimeMax);
    const float f = std::min(seconds / life, 1.0f);
    return fx::evalColorRamp(r.particle.colorRamp, f).a * fx::fadeAt(r.particle, f);
}

TEST(ShippedReactions, SmokeLingersWhereSteamThinsOut) {
    const fx::ReactionDesc smoke = shipped("burnout_smoke.yaml");
    const fx::ReactionDesc steam = shipped("tyre_steam.yaml");
    ASSERT_FALSE(steam.particle.alphaOverLife.empty());
    // Both start dense (within their first 0.1 s) ...
    EXPECT_GT(alphaAfter(smoke, 0.3f), 0.5f);
    EXPECT_GT(alphaAfter(steam, 0.08f), 0.5f);
    // ... but 0.6 s on the steam is under a third of the smoke's opacity, and after 1.5 s gone
    // while the smoke still shows.
    EXPECT_LT(alphaAfter(steam, 0.6f), alphaAfter(smoke, 0.6f) / 3.0f);
    EXPECT_EQ(alphaAfter(steam, 1.5f), 0.0f);
    EXPECT_GT(alphaAfter(smoke, 1.5f), 0.4f);
    // Steam is white and rises faster; smoke lives several times longer.
    EXPECT_GT(steam.particle.colorRamp.front().rgba.b, 0.9f);
    EXPECT_GT(steam.particle.riseSpeed, 2.0f * smoke.particle.riseSpeed);
    EXPECT_GT(smoke.particle.lifetimeMin, 2.0f * steam.particle.lifetimeMax);
}

TEST(ShippedReactions, SmokeAndSteamCurlInTurbulence) {
    EXPECT_TRUE(shipped("burnout_smoke.yaml").turbulence.enabled());
    EXPECT_TRUE(shipped("burnout_smoke.yaml").vortex.enabled());
    EXPECT_TRUE(shipped("tyre_steam.yaml").turbulence.enabled());
    // Steam's eddies are smaller than smoke's: it tears into wisps.
    EXPECT_LT(shipped("tyre_steam.yaml").turbulence.scale, shipped("burnout_smoke.yaml").turbulence.scale);
}

}  // namespace
}  // namespace shipped_reactions_test
