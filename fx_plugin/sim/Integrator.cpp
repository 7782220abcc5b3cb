#include "Integrator.h"

#include <cmath>

namespace fx {

float sanitizeDt(float dt) { return (std::isfinite(dt) && dt > 0.0f) ? dt : 0.0f; }

glm::vec3 terminalVelocity(glm::vec3 wind, float windFactor, float riseSpeed) {
    return wind * windFactor + glm::vec3(0.0f, riseSpeed, 0.0f);
}

namespace {

// (1 - e^{-k t}) / k, exact in the limit k -> 0 and without cancellation for small k t.
double reachOf(double k, double t) { return k > 0.0 ? -std::expm1(-k * t) / k : t; }

}  // namespace

double liftOf(double k, double t) {
    const double kt = k * t;
    // Below 1e-3 the difference t - reach cancels; the series' next term is (kt)^3 / 60 t^2.
    if (kt < 1e-3) return t * t * (0.5 - kt / 6.0 + kt * kt / 24.0);
    return (t - reachOf(k, t)) / k;
}

DragStep makeDragStep(float k, float dt) {
    DragStep s;
    s.dt = sanitizeDt(dt);
    const double kd = (std::isfinite(k) && k > 0.0f) ? static_cast<double>(k) : 0.0;
    s.decay = static_cast<float>(std::exp(-kd * s.dt));
    s.reach = static_cast<float>(reachOf(kd, s.dt));
    s.lift = static_cast<float>(liftOf(kd, s.dt));
    return s;
}

void stepExact(glm::vec3& x, glm::vec3& v, glm::vec3 u, float k, float dt) {
    const DragStep s = makeDragStep(k, dt);
    if (s.dt == 0.0f) return;  // exactly a no-op (u + (v - u) * 1 would round v)
    applyDragStep(s, u, x, v);
}

void stepExplicitEuler(glm::vec3& x, glm::vec3& v, glm::vec3 u, float k, float dt) {
    dt = sanitizeDt(dt);
    const glm::vec3 accel = -k * (v - u);
    x += v * dt;
    v += accel * dt;
}

void stepSemiImplicitEuler(glm::vec3& x, glm::vec3& v, glm::vec3 u, float k, float dt) {
    dt = sanitizeDt(dt);
    v += -k * (v - u) * dt;
    x += v * dt;
}

void exactSolution(const glm::dvec3& x0, const glm::dvec3& v0, const glm::dvec3& u, double k,
                   double t, glm::dvec3* x, glm::dvec3* v) {
    const double decay = std::exp(-k * t);
    const double reach = reachOf(k, t);
    *x = x0 + u * t + (v0 - u) * reach;
    *v = u + (v0 - u) * decay;
}

}  // namespace fx
