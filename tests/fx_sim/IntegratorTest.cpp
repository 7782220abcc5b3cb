// The drag integrator against the analytic solution of dv/dt = -k (v - u), in double.
// Tolerances: exact step 1e-5 relative (float storage); Euler variants first order (halving dt
// halves the error, ratio 2 +- 0.3); stiff and hitch steps bounded and monotonic.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "../../fx_plugin/sim/Integrator.h"

namespace {

using Step = void (*)(glm::vec3&, glm::vec3&, glm::vec3, float, float);

const glm::vec3 kX0(1.0f, 0.2f, -3.0f);
const glm::vec3 kV0(6.0f, -2.0f, 3.0f);
const glm::vec3 kU = fx::terminalVelocity(glm::vec3(2.0f, 0.0f, 1.0f), 1.0f, 0.6f);
constexpr float kK = 1.5f;
constexpr double kT = 2.0;

double relError(glm::dvec3 got, glm::dvec3 want) {
    return glm::length(got - want) / std::max(glm::length(want), 1.0);
}

// Integrates to kT in steps of dt; returns the position error relative to the analytic one.
double positionError(Step step, double dt, glm::dvec3* vErr = nullptr) {
    glm::vec3 x = kX0, v = kV0;
    const int n = static_cast<int>(std::lround(kT / dt));
    for (int i = 0; i < n; ++i) step(x, v, kU, kK, static_cast<float>(dt));
    glm::dvec3 xa, va;
    fx::exactSolution(glm::dvec3(kX0), glm::dvec3(kV0), glm::dvec3(kU), kK, n * dt, &xa, &va);
    if (vErr) *vErr = glm::dvec3(relError(glm::dvec3(v), va));
    return relError(glm::dvec3(x), xa);
}

TEST(Integrator, TerminalVelocityIsWindPlusRise) {
    const glm::vec3 u = fx::terminalVelocity(glm::vec3(4.0f, 0.0f, -2.0f), 0.5f, 0.7f);
    EXPECT_FLOAT_EQ(u.x, 2.0f);
    EXPECT_FLOAT_EQ(u.y, 0.7f);
    EXPECT_FLOAT_EQ(u.z, -1.0f);
}

TEST(Integrator, ExactStepMatchesTheAnalyticSolutionAtEveryDt) {
    for (double dt : {1.0 / 300, 1.0 / 120, 1.0 / 60, 1.0 / 30, 0.25, 1.0, 2.0}) {
        glm::dvec3 vErr;
        EXPECT_LT(positionError(fx::stepExact, dt, &vErr), 1e-5) << "dt " << dt;
        EXPECT_LT(vErr.x, 1e-5) << "dt " << dt;
    }
}

TEST(Integrator, EulerVariantsAreFirstOrder) {
    for (Step step : {static_cast<Step>(fx::stepExplicitEuler),
                      static_cast<Step>(fx::stepSemiImplicitEuler)}) {
        const double e30 = positionError(step, 1.0 / 30);
        const double e60 = positionError(step, 1.0 / 60);
        const double e120 = positionError(step, 1.0 / 120);
        EXPECT_GT(e30, 1e-3);  // visibly wrong at 30 Hz, unlike the exact step
        EXPECT_NEAR(e30 / e60, 2.0, 0.3);
        EXPECT_NEAR(e60 / e120, 2.0, 0.3);
        EXPECT_GT(e120, 100.0 * positionError(fx::stepExact, 1.0 / 120));
    }
}

void expectBoundedMonotonicDecay(float k, float dt, int steps) {
    glm::vec3 x = kX0, v = kV0;
    const float bound = std::max(glm::length(kV0), glm::length(kU));
    float gap = glm::length(v - kU);
    for (int i = 0; i < steps; ++i) {
        const glm::vec3 x0 = x;
        fx::stepExact(x, v, kU, k, dt);
        ASSERT_TRUE(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z));
        ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        const float newGap = glm::length(v - kU);
        EXPECT_LE(newGap, gap * (1.0f + 1e-6f)) << "k " << k << " dt " << dt;  // never overshoots past u
        EXPECT_LE(glm::length(v), bound * (1.0f + 1e-6f));
        // No step travels further than u dt plus the distance drag lets v0 - u carry.
        EXPECT_LE(glm::length(x - x0), glm::length(kU) * dt + gap / std::max(k, 1e-30f) + 1e-4f);
        gap = newGap;
    }
}

TEST(Integrator, StiffDragNeverBlowsUpOrOvershoots) {
    expectBoundedMonotonicDecay(1e4f, 1.0f, 5);          // k dt = 1e4
    expectBoundedMonotonicDecay(1000.0f, 10.0f, 3);      // k dt = 1e4, the other way round
    glm::vec3 x = kX0, v = kV0;
    fx::stepExact(x, v, kU, 1e4f, 1.0f);
    EXPECT_EQ(v, kU);  // e^{-1e4} is 0: exactly terminal
    // Explicit Euler at the same step explodes: the reason the simulation does not use it.
    glm::vec3 xe = kX0, ve = kV0;
    fx::stepExplicitEuler(xe, ve, kU, 1e4f, 1.0f);
    EXPECT_GT(glm::length(ve), 1e3f * glm::length(kV0));
}

TEST(Integrator, TwoSecondHitchIsExactAndMonotonic) {
    expectBoundedMonotonicDecay(kK, 2.0f, 4);
    glm::vec3 x = kX0, v = kV0;
    fx::stepExact(x, v, kU, kK, 2.0f);
    glm::dvec3 xa, va;
    fx::exactSolution(glm::dvec3(kX0), glm::dvec3(kV0), glm::dvec3(kU), kK, 2.0, &xa, &va);
    EXPECT_LT(relError(glm::dvec3(x), xa), 1e-6);
    for (int c = 0; c < 3; ++c) {  // each component between where it started and terminal
        EXPECT_LE(v[c], std::max(kV0[c], kU[c]) + 1e-6f);
        EXPECT_GE(v[c], std::min(kV0[c], kU[c]) - 1e-6f);
    }
}

TEST(Integrator, TinyDragMatchesTheDragFreeLimit) {
    for (float dt : {1.0f / 60.0f, 1.0f, 10.0f}) {
        const fx::DragStep tiny = fx::makeDragStep(1e-9f, dt);
        const fx::DragStep none = fx::makeDragStep(0.0f, dt);
        EXPECT_EQ(none.decay, 1.0f);
        EXPECT_EQ(none.reach, dt);  // the k -> 0 limit taken exactly
        EXPECT_NEAR(tiny.reach / none.reach, 1.0, 1e-6) << dt;
        EXPECT_NEAR(tiny.decay, 1.0, 1e-6) << dt;
        glm::vec3 xa = kX0, va = kV0, xb = kX0, vb = kV0;
        fx::stepExact(xa, va, kU, 1e-9f, dt);
        fx::stepExact(xb, vb, kU, 0.0f, dt);
        EXPECT_LT(glm::length(xa - xb) / glm::length(xb), 1e-6f) << dt;
        EXPECT_LT(glm::length(va - vb), 1e-6f) << dt;
        // k = 0: straight line at v0.
        EXPECT_LT(glm::length(xb - (kX0 + kV0 * dt)), 1e-5f * glm::length(xb));
    }
    // Double reference too: 1e-9 against 0 over 10 s.
    glm::dvec3 x1, v1, x0, v0;
    fx::exactSolution(glm::dvec3(kX0), glm::dvec3(kV0), glm::dvec3(kU), 1e-9, 10.0, &x1, &v1);
    fx::exactSolution(glm::dvec3(kX0), glm::dvec3(kV0), glm::dvec3(kU), 0.0, 10.0, &x0, &v0);
    EXPECT_LT(glm::length(x1 - x0), 1e-6);
}

TEST(Integrator, ZeroNegativeAndNonFiniteDtAreNoOps) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (float dt : {0.0f, -0.5f, nan, inf, -inf}) {
        EXPECT_EQ(fx::sanitizeDt(dt), 0.0f);
        for (Step step : {static_cast<Step>(fx::stepExact), static_cast<Step>(fx::stepExplicitEuler),
                          static_cast<Step>(fx::stepSemiImplicitEuler)}) {
            glm::vec3 x = kX0, v = kV0;
            step(x, v, kU, kK, dt);
            EXPECT_EQ(x, kX0) << dt;
            EXPECT_EQ(v, kV0) << dt;
        }
    }
    EXPECT_EQ(fx::sanitizeDt(0.25f), 0.25f);
}

}  // namespace
