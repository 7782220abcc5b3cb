#pragma once
// Particle motion: dv/dt = -k (v - w_eff) + a, with k the drag rate (1/s), w_eff = wind *
// wind_factor and a = k * rise_speed * up the buoyancy that makes the terminal velocity
//     u = w_eff + rise_speed * up.
// So dv/dt = -k (v - u), whose exact solution over a step dt is
//     v(dt) = u + (v0 - u) e^{-k dt}
//     x(dt) = x0 + u dt + (v0 - u) (1 - e^{-k dt}) / k
// Written with expm1 so small k dt loses no precision, and with the k = 0 limit
// ((1 - e^{-k dt}) / k -> dt) taken exactly. Stiff drag (k dt = 1e4) and long hitches (dt = 2 s)
// neither blow up nor overshoot: e^{-k dt} is in [0, 1], so v moves monotonically toward u.
//
// The explicit and semi-implicit Euler steps of the same ODE are here for comparison only
// (tests and the benchmark print their error against the exact step); they are unstable for
// k dt > 2.
#include <glm/glm.hpp>

namespace fx {

/// A step length the simulation accepts: negative, NaN and infinite dt become 0 (a no-op).
float sanitizeDt(float dt);

/// The velocity particles relax to: wind * windFactor + riseSpeed * up (+Y).
glm::vec3 terminalVelocity(glm::vec3 wind, float windFactor, float riseSpeed);

/// The two coefficients of the exact step for one (k, dt); the same for every particle of a
/// reaction in one frame, so the per-particle work is two multiply-adds per component.
struct DragStep {
    float dt = 0.0f;
    float decay = 1.0f;  ///< e^{-k dt}, in [0, 1]
    float reach = 0.0f;  ///< (1 - e^{-k dt}) / k, = dt when k = 0; in [0, dt]
    float lift = 0.0f;   ///< (dt - reach) / k, = dt^2 / 2 when k = 0: how far a constant
                         ///< acceleration carries a particle against the drag; in [0, dt^2 / 2]
};

/// Coefficients for drag rate k >= 0 over dt (sanitised). Computed in double.
DragStep makeDragStep(float k, float dt);

/// Exact step with precomputed coefficients (callers skip it when s.dt is 0: with decay 1 it
/// would still round v by an ulp).
inline void applyDragStep(const DragStep& s, glm::vec3 u, glm::vec3& x, glm::vec3& v) {
    const glm::vec3 d = v - u;
    x += u * s.dt + d * s.reach;
    v = u + d * s.decay;
}

/// Exact step with a constant acceleration g besides the drag (gravity on sparks):
/// dv/dt = -k (v - u) + g, whose solution over dt is
///     v = u + (v0 - u) e^{-k dt} + g reach,   x = x0 + u dt + (v0 - u) reach + g lift,
/// which is the ballistic p0 + v0 t + g t^2 / 2 at k = 0 and stays finite for any k dt.
inline void applyDragStep(const DragStep& s, glm::vec3 u, glm::vec3 g, glm::vec3& x, glm::vec3& v) {
    const glm::vec3 d = v - u;
    x += u * s.dt + d * s.reach + g * s.lift;
    v = u + d * s.decay + g * s.reach;
}

/// lift(k, t) = (t - (1 - e^{-k t}) / k) / k in double, with the series near k t = 0.
double liftOf(double k, double t);

/// Exact (analytic) step; see the header comment.
void stepExact(glm::vec3& x, glm::vec3& v, glm::vec3 u, float k, float dt);
/// Explicit (forward) Euler: x += v dt; v += -k (v - u) dt, both from the old state.
void stepExplicitEuler(glm::vec3& x, glm::vec3& v, glm::vec3 u, float k, float dt);
/// Semi-implicit (symplectic) Euler: v first, then x with the new v.
void stepSemiImplicitEuler(glm::vec3& x, glm::vec3& v, glm::vec3 u, float k, float dt);

/// The analytic state after time t from (x0, v0), in double precision (the tests' reference).
void exactSolution(const glm::dvec3& x0, const glm::dvec3& v0, const glm::dvec3& u, double k,
                   double t, glm::dvec3* x, glm::dvec3* v);

}  // namespace fx
