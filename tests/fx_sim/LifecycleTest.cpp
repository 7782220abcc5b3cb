// Growth, fade and colour ramp over a particle's life, and the per-particle values the pool
// stores for the renderer.
#include <gtest/gtest.h>

#include "../../fx_plugin/sim/Lifecycle.h"
#include "../../fx_plugin/sim/ReactionRuntime.h"

namespace {

TEST(Lifecycle, GrowthIsEaseOutFromStartToEnd) {
    EXPECT_FLOAT_EQ(fx::growthCurve(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(fx::growthCurve(0.5f), 0.75f);
    EXPECT_FLOAT_EQ(fx::growthCurve(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(fx::growthCurve(2.0f), 1.0f);  // clamped
    float prev = -1.0f;
    for (int i = 0; i <= 100; ++i) {
        const float g = fx::growthCurve(i / 100.0f);
        EXPECT_GT(g, prev);
        prev = g;
    }
    EXPECT_FLOAT_EQ(fx::sizeAt(0.5f, 4.5f, 0.5f), 3.5f);
}

TEST(Lifecycle, FadeInAndOut) {
    EXPECT_FLOAT_EQ(fx::fadeAt(0.0f, 0.1f, 0.5f), 0.0f);
    EXPECT_FLOAT_EQ(fx::fadeAt(0.05f, 0.1f, 0.5f), 0.5f);  // smoothstep midpoint
    EXPECT_FLOAT_EQ(fx::fadeAt(0.3f, 0.1f, 0.5f), 1.0f);
    EXPECT_FLOAT_EQ(fx::fadeAt(0.75f, 0.1f, 0.5f), 0.5f);
    EXPECT_FLOAT_EQ(fx::fadeAt(1.0f, 0.1f, 0.5f), 0.0f);
    EXPECT_FLOAT_EQ(fx::fadeAt(0.0f, 0.0f, 0.0f), 1.0f);  // no fade at all
    EXPECT_FLOAT_EQ(fx::fadeAt(1.0f, 0.0f, 0.0f), 1.0f);
}

TEST(Lifecycle, ColourRampIsPiecewiseLinear) {
    const std::vector<fx::ColorStop> ramp = {
        {0.2f, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)},
        {0.6f, glm::vec4(0.0f, 1.0f, 0.0f, 0.5f)},
        {0.6f, glm::vec4(0.0f, 0.0f, 1.0f, 0.5f)},  // hard step at 0.6
        {1.0f, glm::vec4(0.0f, 0.0f, 0.0f, 0.0f)},
    };
    const auto near = [](glm::vec4 a, glm::vec4 b) { return glm::length(a - b) < 1e-6f; };
    EXPECT_TRUE(near(fx::evalColorRamp(ramp, 0.0f), ramp[0].rgba));  // before the first stop
    EXPECT_TRUE(near(fx::evalColorRamp(ramp, 0.4f), glm::vec4(0.5f, 0.5f, 0.0f, 0.75f)));
    EXPECT_TRUE(near(fx::evalColorRamp(ramp, 0.6f), ramp[1].rgba));
    EXPECT_LT(glm::length(fx::evalColorRamp(ramp, 0.6001f) - ramp[2].rgba), 1e-3f);  // past the step
    EXPECT_TRUE(near(fx::evalColorRamp(ramp, 0.8f), glm::vec4(0.0f, 0.0f, 0.5f, 0.25f)));
    EXPECT_TRUE(near(fx::evalColorRamp(ramp, 1.5f), ramp[3].rgba));  // after the last
    EXPECT_TRUE(near(fx::evalColorRamp(nullptr, 0, 0.5f), glm::vec4(1.0f)));
    float baked[4 * 6];
    fx::bakeColorRamp(ramp, 6, baked);  // t = 0, 0.2, ..., 1
    EXPECT_FLOAT_EQ(baked[4 * 2 + 0], 0.5f);  // t = 0.4: red half way
    EXPECT_FLOAT_EQ(baked[4 * 5 + 3], 0.0f);
}

TEST(Lifecycle, PoolHoldsWhatTheRendererReads) {
    fx::ReactionDesc d = fx::defaultReaction(fx::ReactionType::WheelSmoke);
    d.name = "smoke";
    d.particle.atlasFirst = 1;
    d.particle.atlasCount = 2;
    fx::ReactionRuntime rt(d);
    fx::WheelContact w;
    w.grounded = w.rear = true;
    w.slip = 1.0f;
    for (int i = 0; i < 90; ++i) rt.step(1.0f / 60.0f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    const fx::ParticlePool& pool = rt.pool();
    ASSERT_GT(pool.alive(), 50);
    for (int i = 0; i < pool.alive(); ++i) {
        const float age = pool.stream(fx::ParticlePool::Age)[i];
        const float lifetime = pool.stream(fx::ParticlePool::Lifetime)[i];
        const float f = age / lifetime;
        EXPECT_FLOAT_EQ(pool.life()[i], f);
        EXPECT_FLOAT_EQ(pool.size()[i], fx::sizeAt(pool.stream(fx::ParticlePool::StartSize)[i],
                                                   pool.stream(fx::ParticlePool::EndSize)[i], f));
        EXPECT_FLOAT_EQ(pool.fade()[i], fx::fadeAt(f, d.particle.fadeIn, d.particle.fadeOut));
        EXPECT_GE(pool.rotation()[i], -3.1416f);
        EXPECT_LE(pool.rotation()[i], 3.1416f);
        EXPECT_GE(pool.frame()[i], 1);
        EXPECT_LE(pool.frame()[i], 2);
        EXPECT_GE(lifetime, d.particle.lifetimeMin);
        EXPECT_LE(lifetime, d.particle.lifetimeMax);
    }
}

}  // namespace
