// What each reaction type does with the host's inputs: slip thresholds and scaling, surfaces
// and wheel sets, speed-scaled dust, edge-triggered collision bursts, and the motion (rise,
// wind) that the YAML promises.
#include <cmath>

#include <gtest/gtest.h>

#include "../../fx_plugin/sim/ReactionRuntime.h"

namespace {

const glm::vec3 kNoWind(0.0f);

fx::ReactionDesc make(fx::ReactionType type) {
    fx::ReactionDesc d = fx::defaultReaction(type);
    d.name = "r";
    d.emission.capacity = 100000;
    d.emission.rate = 100.0f;
    d.particle.lifetimeMin = d.particle.lifetimeMax = 10.0f;
    return d;
}

fx::WheelContact wheel(float slip, fx::Surface surface, float speed = 0.0f, bool rear = true) {
    fx::WheelContact w;
    w.position = glm::vec3(0.0f, 0.0f, 0.0f);
    w.velocity = glm::vec3(speed, 0.0f, 0.0f);
    w.slip = slip;
    w.surface = surface;
    w.grounded = true;
    w.rear = rear;
    return w;
}

uint64_t emittedInOneSecond(const fx::ReactionDesc& d, const fx::WheelContact& w) {
    fx::ReactionRuntime rt(d);
    for (int i = 0; i < 60; ++i) rt.step(1.0f / 60.0f, &w, 1, 0.0f, glm::vec3(0.0f), kNoWind);
    return rt.counters().emitted;
}

TEST(Behaviour, NoSmokeAtOrBelowTheSlipThreshold) {
    const fx::ReactionDesc d = make(fx::ReactionType::WheelSmoke);  // threshold 0.35
    EXPECT_EQ(emittedInOneSecond(d, wheel(0.0f, fx::Surface::Asphalt)), 0u);
    EXPECT_EQ(emittedInOneSecond(d, wheel(0.3f, fx::Surface::Asphalt)), 0u);
    EXPECT_EQ(emittedInOneSecond(d, wheel(0.35f, fx::Surface::Asphalt)), 0u);
    EXPECT_GT(emittedInOneSecond(d, wheel(0.4f, fx::Surface::Asphalt)), 0u);
}

TEST(Behaviour, MoreSmokeAtHigherSlipScaledPastTheThreshold) {
    const fx::ReactionDesc d = make(fx::ReactionType::WheelSmoke);
    const double t = d.trigger.slipThreshold;
    double previous = 0.0;
    for (float slip : {0.5f, 0.7f, 0.9f, 1.0f}) {
        const double n = static_cast<double>(emittedInOneSecond(d, wheel(slip, fx::Surface::Asphalt)));
        EXPECT_GT(n, previous) << slip;
        EXPECT_NEAR(n, 100.0 * (slip - t) / (1.0 - t), 1.0) << slip;
        previous = n;
    }
    // Beyond full slip the rate stays at full.
    EXPECT_NEAR(static_cast<double>(emittedInOneSecond(d, wheel(3.0f, fx::Surface::Asphalt))), 100.0, 1.0);
}

TEST(Behaviour, SmokeOnlyFromTheTriggerWheelsOnTheTriggerSurfaces) {
    fx::ReactionDesc d = make(fx::ReactionType::WheelSmoke);  // rear, asphalt|kerb
    EXPECT_EQ(emittedInOneSecond(d, wheel(1.0f, fx::Surface::Asphalt, 0.0f, false)), 0u);
    EXPECT_EQ(emittedInOneSecond(d, wheel(1.0f, fx::Surface::Grass)), 0u);
    EXPECT_GT(emittedInOneSecond(d, wheel(1.0f, fx::Surface::Kerb)), 0u);
    fx::WheelContact airborne = wheel(1.0f, fx::Surface::Asphalt);
    airborne.grounded = false;
    EXPECT_EQ(emittedInOneSecond(d, airborne), 0u);
    d.trigger.wheels = fx::WheelSet::Front;
    EXPECT_GT(emittedInOneSecond(d, wheel(1.0f, fx::Surface::Asphalt, 0.0f, false)), 0u);
    EXPECT_EQ(emittedInOneSecond(d, wheel(1.0f, fx::Surface::Asphalt, 0.0f, true)), 0u);
    d.trigger.minSpeed = 5.0f;
    EXPECT_EQ(emittedInOneSecond(d, wheel(1.0f, fx::Surface::Asphalt, 4.0f, false)), 0u);
}

TEST(Behaviour, DustOnlyOffTrackAndThickerWithSpeed) {
    const fx::ReactionDesc d = make(fx::ReactionType::Dust);  // min_speed 2, full rate at 17 m/s
    EXPECT_EQ(emittedInOneSecond(d, wheel(0.0f, fx::Surface::Asphalt, 20.0f)), 0u);
    EXPECT_EQ(emittedInOneSecond(d, wheel(0.0f, fx::Surface::Kerb, 20.0f)), 0u);
    EXPECT_EQ(emittedInOneSecond(d, wheel(0.0f, fx::Surface::Grass, 1.0f)), 0u);  // too slow
    for (fx::Surface s : {fx::Surface::Grass, fx::Surface::Gravel, fx::Surface::Sand}) {
        EXPECT_NEAR(static_cast<double>(emittedInOneSecond(d, wheel(0.0f, s, 20.0f))), 100.0, 1.0);
    }
    const double slow = static_cast<double>(emittedInOneSecond(d, wheel(0.0f, fx::Surface::Gravel, 5.0f)));
    const double fast = static_cast<double>(emittedInOneSecond(d, wheel(0.0f, fx::Surface::Gravel, 12.0f)));
    EXPECT_NEAR(slow, 100.0 * 3.0 / 15.0, 1.0);
    EXPECT_NEAR(fast, 100.0 * 10.0 / 15.0, 1.0);
    // Any wheel by default, front ones included.
    EXPECT_GT(emittedInOneSecond(d, wheel(0.0f, fx::Surface::Sand, 20.0f, false)), 0u);
}

TEST(Behaviour, CollisionBurstFiresOncePerRisingEdge) {
    fx::ReactionDesc d = make(fx::ReactionType::CollisionBurst);  // threshold 0.2, burst 24
    fx::ReactionRuntime rt(d);
    const glm::vec3 hit(3.0f, 0.5f, -2.0f);
    auto step = [&](float amount) { rt.step(1.0f / 60.0f, nullptr, 0, amount, hit, kNoWind); };
    step(0.0f);
    step(0.1f);  // below the threshold
    EXPECT_EQ(rt.counters().bursts, 0u);
    for (int i = 0; i < 30; ++i) step(0.8f);  // touching for half a second: one burst
    EXPECT_EQ(rt.counters().bursts, 1u);
    EXPECT_EQ(rt.counters().emitted, 19u);  // round(24 * 0.8)
    step(0.15f);                              // dips under the threshold but not under half of it
    step(0.8f);
    EXPECT_EQ(rt.counters().bursts, 1u);
    step(0.0f);
    step(1.0f);  // a new hit
    EXPECT_EQ(rt.counters().bursts, 2u);
    EXPECT_EQ(rt.counters().emitted, 19u + 24u);
    // Puffs start at the collision point (+ spawn height, within the jitter disc).
    const fx::ParticlePool& pool = rt.pool();
    const int last = pool.alive() - 1;
    const glm::vec3 p(pool.posX()[last], pool.posY()[last], pool.posZ()[last]);
    EXPECT_NEAR(p.y, hit.y + d.emission.spawnHeight, 1e-4f);  // born this step: age 0
    EXPECT_LE(std::hypot(p.x - hit.x, p.z - hit.z), d.emission.jitterRadius + 1e-4f);
}

TEST(Behaviour, WheelsDoNotFireBurstsAndBurstsIgnoreWheels) {
    fx::ReactionRuntime burst(make(fx::ReactionType::CollisionBurst));
    const fx::WheelContact w = wheel(1.0f, fx::Surface::Asphalt, 10.0f);
    for (int i = 0; i < 60; ++i) burst.step(1.0f / 60.0f, &w, 1, 0.0f, glm::vec3(0.0f), kNoWind);
    EXPECT_EQ(burst.pool().alive(), 0);
    fx::ReactionRuntime smoke(make(fx::ReactionType::WheelSmoke));
    for (int i = 0; i < 60; ++i) smoke.step(1.0f / 60.0f, nullptr, 0, 1.0f, glm::vec3(0.0f), kNoWind);
    EXPECT_EQ(smoke.pool().alive(), 0);
}

TEST(Behaviour, SmokeRisesAtRiseSpeedAndDriftsWithTheWind) {
    fx::ReactionDesc d = make(fx::ReactionType::WheelSmoke);
    d.particle.riseSpeed = 0.8f;
    d.particle.windFactor = 0.5f;
    d.particle.drag = 2.0f;
    fx::ReactionRuntime rt(d);
    const fx::WheelContact w = wheel(1.0f, fx::Surface::Asphalt);
    const glm::vec3 wind(4.0f, 0.0f, 0.0f);
    rt.step(0.05f, &w, 1, 0.0f, glm::vec3(0.0f), wind);
    for (int i = 0; i < 300; ++i) rt.step(1.0f / 60.0f, nullptr, 0, 0.0f, glm::vec3(0.0f), wind);
    const fx::ParticlePool& pool = rt.pool();
    ASSERT_GT(pool.alive(), 0);
    for (int i = 0; i < pool.alive(); ++i) {  // 5 s at k = 2: e^-10 of the start is left
        EXPECT_NEAR(pool.stream(fx::ParticlePool::VelX)[i], 2.0f, 1e-3f);
        EXPECT_NEAR(pool.stream(fx::ParticlePool::VelY)[i], 0.8f, 1e-3f);
        EXPECT_NEAR(pool.stream(fx::ParticlePool::VelZ)[i], 0.0f, 1e-3f);
        EXPECT_GT(pool.posY()[i], 3.0f);
        // Growing (ease-out) and fading as documented in sim/Lifecycle.h.
        EXPECT_GT(pool.size()[i], d.particle.startSize * (1.0f - d.particle.sizeVariation));
    }
}

}  // namespace
