// Emission: frame-rate independence (fractional carry), staggered spawn times, the capacity
// bound, recycling, and bounded work on absurd steps.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../../fx_plugin/sim/EmissionClock.h"
#include "../../fx_plugin/sim/ReactionRuntime.h"

namespace {

fx::ReactionDesc smoke(float rate, int capacity, float lifeMin = 5.0f, float lifeMax = 5.0f) {
    fx::ReactionDesc d = fx::defaultReaction(fx::ReactionType::WheelSmoke);
    d.name = "smoke";
    d.emission.rate = rate;
    d.emission.capacity = capacity;
    d.particle.lifetimeMin = lifeMin;
    d.particle.lifetimeMax = lifeMax;
    return d;
}

fx::WheelContact spinningRearWheel(glm::vec3 velocity = glm::vec3(0.0f)) {
    fx::WheelContact w;
    w.position = glm::vec3(1.0f, 0.0f, -1.5f);
    w.velocity = velocity;
    w.slip = 1.0f;  // full strength
    w.surface = fx::Surface::Asphalt;
    w.grounded = true;
    w.rear = true;
    return w;
}

uint64_t emittedOverOneSecond(float rate, int stepsPerSecond) {
    fx::ReactionRuntime rt(smoke(rate, 100000));
    const fx::WheelContact w = spinningRearWheel();
    const float dt = 1.0f / static_cast<float>(stepsPerSecond);
    for (int i = 0; i < stepsPerSecond; ++i) rt.step(dt, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    return rt.counters().emitted;
}

TEST(Emission, SameCountAt30And300StepsPerSecond) {
    for (float rate : {137.3f, 60.0f, 7.5f, 999.9f}) {
        const double at30 = static_cast<double>(emittedOverOneSecond(rate, 30));
        const double at300 = static_cast<double>(emittedOverOneSecond(rate, 300));
        EXPECT_LE(std::abs(at30 - at300), 1.0) << rate;
        EXPECT_LE(std::abs(at30 - rate), 1.0) << rate;
        EXPECT_LE(std::abs(at300 - rate), 1.0) << rate;
    }
}

TEST(Emission, ClockCarriesTheFractionAndDatesEachParticle) {
    fx::EmissionClock clock;
    EXPECT_EQ(clock.advance(10.0, 0.25), 2);  // 2.5 due: 2 now, 0.5 carried
    EXPECT_NEAR(clock.carry(), 0.5, 1e-12);
    EXPECT_NEAR(clock.ageOf(0), 0.15, 1e-12);  // due at 0.1 s into the step
    EXPECT_NEAR(clock.ageOf(1), 0.05, 1e-12);
    EXPECT_EQ(clock.advance(10.0, 0.25), 3);  // 0.5 + 2.5
    EXPECT_NEAR(clock.ageOf(0), 0.2, 1e-12);  // the carried half fell due 0.05 s in
    EXPECT_NEAR(clock.carry(), 0.0, 1e-12);
    EXPECT_EQ(clock.advance(0.0, 1.0), 0);     // no rate: nothing, carry kept
    EXPECT_EQ(clock.advance(10.0, -1.0), 0);
    EXPECT_EQ(clock.advance(NAN, 1.0), 0);
}

TEST(Emission, ParticlesOfOneStepAreStaggeredAcrossIt) {
    fx::ReactionRuntime rt(smoke(100.0f, 1000));
    const fx::WheelContact w = spinningRearWheel();
    rt.step(0.5f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    const fx::ParticlePool& pool = rt.pool();
    ASSERT_EQ(pool.alive(), 50);
    std::vector<float> ages(pool.stream(fx::ParticlePool::Age), pool.stream(fx::ParticlePool::Age) + 50);
    std::sort(ages.begin(), ages.end());
    EXPECT_LT(ages.front(), 0.011f);
    EXPECT_GT(ages.back(), 0.48f);
    for (size_t i = 1; i < ages.size(); ++i) EXPECT_NEAR(ages[i] - ages[i - 1], 0.01f, 1e-4f);
}

TEST(Emission, TrailFollowsAMovingWheelInsteadOfBunching) {
    // At 20 m/s a 10 Hz step covers 2 m: its particles spread along those 2 m.
    fx::ReactionDesc d = smoke(200.0f, 1000);
    d.emission.jitterRadius = 0.0f;
    d.particle.spreadSpeed = 0.0f;
    d.particle.inheritVelocity = 0.0f;
    fx::ReactionRuntime rt(d);
    const fx::WheelContact w = spinningRearWheel(glm::vec3(20.0f, 0.0f, 0.0f));
    rt.step(0.1f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    const float* x = rt.pool().posX();
    const auto mm = std::minmax_element(x, x + rt.pool().alive());
    EXPECT_NEAR(*mm.second - *mm.first, 2.0f, 0.15f);
    EXPECT_LE(*mm.second, w.position.x + 1e-4f);  // none ahead of the wheel
}

TEST(Emission, CapacityIsNeverExceeded) {
    fx::ReactionRuntime rt(smoke(100000.0f, 50));
    const fx::WheelContact w = spinningRearWheel();
    for (int i = 0; i < 120; ++i) {
        rt.step(1.0f / 60.0f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
        ASSERT_LE(rt.pool().alive(), 50);
    }
    EXPECT_EQ(rt.pool().alive(), 50);
    EXPECT_EQ(rt.counters().emitted, 50u);  // lifetime 5 s: nothing died yet
    EXPECT_GT(rt.counters().dropped, 100000u);
}

TEST(Emission, DeadParticlesAreRecycled) {
    // 100/s living 0.5-1 s: at most 100 alive at once, though 6000 are emitted over 60 s.
    fx::ReactionRuntime rt(smoke(100.0f, 1000, 0.5f, 1.0f));
    const fx::WheelContact w = spinningRearWheel();
    int most = 0;
    for (int i = 0; i < 60 * 60; ++i) {
        rt.step(1.0f / 60.0f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
        most = std::max(most, rt.pool().alive());
    }
    EXPECT_LE(most, 101);
    EXPECT_GE(most, 60);
    EXPECT_NEAR(static_cast<double>(rt.counters().emitted), 6000.0, 1.0);
    EXPECT_EQ(rt.counters().dropped, 0u);
    // The live range is dense: every slot below alive() is a living particle.
    const fx::ParticlePool& pool = rt.pool();
    for (int i = 0; i < pool.alive(); ++i) {
        EXPECT_LT(pool.stream(fx::ParticlePool::Age)[i], pool.stream(fx::ParticlePool::Lifetime)[i]);
        EXPECT_GE(pool.life()[i], 0.0f);
        EXPECT_LT(pool.life()[i], 1.0f);
    }
}

TEST(Emission, AbsurdStepCostsBoundedWorkAndStaysFinite) {
    fx::ReactionRuntime rt(smoke(1000.0f, 100000, 1.0f, 2.0f));
    const fx::WheelContact w = spinningRearWheel(glm::vec3(30.0f, 0.0f, 0.0f));
    rt.step(1e6f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(3.0f, 0.0f, 0.0f));
    // Only particles due in the last lifetime_max survive: <= 2 s x 1000/s.
    EXPECT_LE(rt.pool().alive(), 2001);
    EXPECT_GT(rt.pool().alive(), 900);
    EXPECT_LE(rt.counters().emitted, 2001u);
    for (int i = 0; i < rt.pool().alive(); ++i) {
        ASSERT_TRUE(std::isfinite(rt.pool().posX()[i]));
        ASSERT_TRUE(std::isfinite(rt.pool().size()[i]));
    }
}

// A finite step whose count is past int64_t (1e30 s at 1000/s): the clock clamps before it
// converts, so the first young particle is never read as INT64_MIN (2^63 loop turns).
TEST(Emission, AStepPastInt64StaysBoundedInTheClockAndTheRuntime) {
    fx::EmissionClock clock;
    const int64_t due = clock.advance(1000.0, 1e30);
    EXPECT_EQ(due, static_cast<int64_t>(fx::EmissionClock::kMaxDue));
    const int64_t first = clock.firstYoungerThan(2.0);
    EXPECT_GE(first, due - 2001);
    EXPECT_LE(first, due);
    EXPECT_EQ(clock.firstYoungerThan(NAN), 0);
    fx::ReactionRuntime rt(smoke(1000.0f, 100000, 1.0f, 2.0f));
    const fx::WheelContact w = spinningRearWheel();
    rt.step(1e30f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    // As after any long hitch: the particles due in the last lifetime_max (2 s x 1000/s).
    EXPECT_LE(rt.counters().emitted, 2001u);
    EXPECT_GT(rt.counters().emitted, 900u);
    for (int i = 0; i < rt.pool().alive(); ++i) ASSERT_TRUE(std::isfinite(rt.pool().posX()[i]));
}

TEST(Emission, ZeroAndInvalidStepsChangeNothing) {
    fx::ReactionRuntime rt(smoke(100.0f, 1000));
    const fx::WheelContact w = spinningRearWheel();
    rt.step(0.1f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    const int alive = rt.pool().alive();
    const float x0 = rt.pool().posX()[0];
    for (float dt : {0.0f, -1.0f, NAN, INFINITY}) {
        rt.step(dt, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
        EXPECT_EQ(rt.pool().alive(), alive);
        EXPECT_EQ(rt.pool().posX()[0], x0);
    }
    // Null wheels with a count, NaN wind and NaN slip: ignored, not propagated.
    fx::WheelContact bad = w;
    bad.slip = NAN;
    rt.step(0.1f, nullptr, 4, NAN, glm::vec3(NAN), glm::vec3(NAN));
    rt.step(0.1f, &bad, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    for (int i = 0; i < rt.pool().alive(); ++i) ASSERT_TRUE(std::isfinite(rt.pool().posY()[i]));
}

}  // namespace
