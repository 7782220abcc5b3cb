// Stateless particles (technique: stateless): the closed form the vertex shader evaluates equals
// the CPU's exact steps of the same particle over its whole life, stiff and long cases included;
// the ring recycles the oldest records and nothing updates a record after its birth.
#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "../../fx_plugin/sim/ReactionRuntime.h"
#include "../../fx_plugin/sim/StatelessParticle.h"

namespace {

fx::ReactionDesc sparks(float drag, float life, float gravity) {
    fx::ReactionDesc d = fx::defaultReaction(fx::ReactionType::CollisionBurst);
    d.name = "sparks";
    d.emission.burst = 32;
    d.emission.capacity = 64;
    d.particle.lifetimeMin = d.particle.lifetimeMax = life;
    d.particle.drag = drag;
    d.particle.gravity = gravity;
    d.particle.spreadSpeed = 12.0f;
    d.particle.riseSpeed = 0.0f;
    d.render.blend = fx::BlendMode::Additive;
    return d;
}

glm::vec3 closedForm(const fx::ReactionRuntime& rt, const fx::StatelessRecord& r, glm::vec3 wind) {
    const fx::ParticleDesc& p = rt.desc().particle;
    const glm::vec3 u = fx::terminalVelocity(wind, p.windFactor, p.riseSpeed);
    const float age = static_cast<float>(rt.time() - static_cast<double>(r.birth));
    return fx::statelessPosition(glm::vec3(r.p0[0], r.p0[1], r.p0[2]), glm::vec3(r.v0[0], r.v0[1], r.v0[2]),
                                 u, glm::vec3(0.0f, -p.gravity, 0.0f), p.drag, age);
}

struct Case {
    const char* what;
    float drag, life, gravity, dt;
};

// The same burst through both techniques; at every step each CPU particle's position is compared
// with the closed form of the matching record (same seed, same draws, same order: one lifetime,
// so no particle dies before the others and the pool is not reordered).
TEST(Stateless, ClosedFormEqualsTheCpuStepsOverTheWholeLife) {
    const Case cases[] = {
        {"burnout-like drag", 1.2f, 3.0f, 9.81f, 1.0f / 60.0f},
        {"ballistic, k = 0", 0.0f, 2.0f, 9.81f, 1.0f / 60.0f},
        {"stiff, k dt = 1e4", 3.0e5f, 1.0f, 9.81f, 1.0f / 30.0f},
        {"long life, 60 s at 30 Hz", 0.05f, 60.0f, 0.5f, 1.0f / 30.0f},
        {"tiny dt", 2.0f, 0.5f, 9.81f, 1.0e-4f},
    };
    const glm::vec3 wind(1.5f, 0.0f, -0.5f);
    for (const Case& c : cases) {
        fx::ReactionDesc cpuDesc = sparks(c.drag, c.life, c.gravity);
        fx::ReactionDesc gpuDesc = cpuDesc;
        gpuDesc.render.stateless = true;
        fx::ReactionRuntime cpu(cpuDesc, 9), gpu(gpuDesc, 9);
        for (fx::ReactionRuntime* rt : {&cpu, &gpu}) rt->step(c.dt, nullptr, 0, 1.0f, glm::vec3(2.0f, 0.5f, 1.0f), wind);
        ASSERT_EQ(cpu.pool().alive(), 32) << c.what;
        ASSERT_EQ(gpu.alive(), 32) << c.what;
        ASSERT_EQ(gpu.pool().alive(), 0) << c.what;  // nothing in the CPU pool
        const int steps = static_cast<int>(c.life / c.dt) - 2;
        double worst = 0.0, worstRel = 0.0;
        for (int n = 0; n < steps; ++n) {
            for (fx::ReactionRuntime* rt : {&cpu, &gpu}) rt->step(c.dt, nullptr, 0, 0.0f, glm::vec3(0.0f), wind);
            const fx::ParticlePool& p = cpu.pool();
            ASSERT_EQ(p.alive(), 32) << c.what << " step " << n;
            for (int i = 0; i < 32; ++i) {
                const glm::vec3 x(p.posX()[i], p.posY()[i], p.posZ()[i]);
                const fx::StatelessRecord& r = gpu.ring().data()[i];
                const glm::vec3 y = closedForm(gpu, r, wind);
                const float travelled = glm::length(x - glm::vec3(r.p0[0], r.p0[1], r.p0[2]));
                const double e = glm::length(x - y);
                worst = std::max(worst, e);
                worstRel = std::max(worstRel, e / (1.0 + travelled));
                // Float tolerance: the CPU rounds once per step, the closed form once; both are
                // exact solutions. 2e-6 per step of the distance travelled, at most 2e-4 (4e-3
                // of a metre over 60 s), plus 1e-5 m.
                const double tol = std::min(2e-6 * (n + 1), 2e-4) * (1.0 + travelled) + 1e-5;
                ASSERT_LE(e, tol) << c.what << ": particle " << i << " step " << n << " age "
                                  << gpu.time() - r.birth;
            }
        }
        std::printf("  %-26s steps %6d  max |cpu - closed form| %.3g m (%.3g of 1 m + distance)\n",
                    c.what, steps, worst, worstRel);
    }
}

TEST(Stateless, FloatCoefficientsMatchTheDoubleReference) {
    // The shader's R and L (series below k t = 0.5, exponential above) against the double
    // expressions of the CPU step, from k t = 1e-8 to 1e4.
    for (double kt = 1e-8; kt <= 1e4; kt *= 1.7) {
        for (float t : {0.01f, 1.0f, 30.0f}) {
            const float k = static_cast<float>(kt / t);
            const fx::StatelessCoefficients c = fx::statelessCoefficients(k, t);
            const double K = static_cast<double>(k), T = static_cast<double>(t);
            const double reach = -std::expm1(-K * T) / K;
            const double lift = fx::liftOf(K, T);
            EXPECT_NEAR(c.reach, reach, 2e-6 * reach) << "k t " << kt << " t " << t;
            EXPECT_NEAR(c.lift, lift, 2e-6 * lift) << "k t " << kt << " t " << t;
        }
    }
    const fx::StatelessCoefficients zero = fx::statelessCoefficients(0.0f, 2.0f);
    EXPECT_FLOAT_EQ(zero.reach, 2.0f);
    EXPECT_FLOAT_EQ(zero.lift, 2.0f);  // t^2 / 2: p0 + v0 t + g t^2 / 2
}

TEST(Stateless, RecordsAreNeverUpdatedAfterBirth) {
    fx::ReactionDesc d = sparks(1.2f, 3.0f, 9.81f);
    d.render.stateless = true;
    fx::ReactionRuntime rt(d, 9);
    rt.step(1.0f / 60.0f, nullptr, 0, 1.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    std::vector<fx::StatelessRecord> before(rt.ring().data(), rt.ring().data() + rt.ring().capacity());
    for (int n = 0; n < 100; ++n) rt.step(1.0f / 60.0f, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(std::memcmp(before.data(), rt.ring().data(), before.size() * sizeof(fx::StatelessRecord)), 0);
    EXPECT_EQ(rt.alive(), 32);  // alive from the clock alone
    for (int n = 0; n < 90; ++n) rt.step(1.0f / 60.0f, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    EXPECT_EQ(rt.alive(), 0);   // 3.18 s > 3 s life
}

TEST(Stateless, TheRingRecyclesTheOldestAndCountsLiveOnesRecycledEarly) {
    fx::ReactionDesc d = sparks(1.2f, 10.0f, 9.81f);
    d.render.stateless = true;
    d.emission.capacity = 48;
    fx::ReactionRuntime rt(d, 9);
    rt.step(0.1f, nullptr, 0, 1.0f, glm::vec3(0.0f), glm::vec3(0.0f));  // 32 records
    rt.step(0.1f, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));  // re-arm
    rt.step(0.1f, nullptr, 0, 1.0f, glm::vec3(0.0f), glm::vec3(0.0f));  // 32 more into 48 slots
    EXPECT_EQ(rt.ring().written(), 64u);
    EXPECT_EQ(rt.counters().emitted, 64u);
    EXPECT_EQ(rt.counters().dropped, 16u);  // 16 live ones overwritten (10 s lives)
    EXPECT_EQ(rt.alive(), 48);
    // With lives shorter than the gap between bursts, the slots are free again: nothing dropped.
    fx::ReactionDesc shortLived = d;
    shortLived.particle.lifetimeMin = shortLived.particle.lifetimeMax = 0.05f;
    fx::ReactionRuntime rt2(shortLived, 9);
    for (int hit = 0; hit < 5; ++hit) {
        rt2.step(0.1f, nullptr, 0, 1.0f, glm::vec3(0.0f), glm::vec3(0.0f));
        rt2.step(0.1f, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    }
    EXPECT_EQ(rt2.ring().written(), 160u);
    EXPECT_EQ(rt2.counters().dropped, 0u);
}

}  // namespace
