#pragma once
// Stateless particles (004): a particle is its birth record, and its state at any later time is a
// closed form of its age, so nothing updates it per frame; the vertex shader evaluates the same
// expressions (shaders/stateless_particles.glsl ports this file line by line).
//
// Motion: dv/dt = -k (v - u) + g, u the terminal velocity (wind * wind_factor + rise_speed * up)
// and g a constant acceleration (gravity on sparks). Its exact solution from (p0, v0) at age t:
//     v(t) = u + (v0 - u) e^{-k t} + g R(t)
//     p(t) = p0 + u t + (v0 - u) R(t) + g L(t)
//     R(t) = (1 - e^{-k t}) / k,   L(t) = (t - R(t)) / k
// which is 004's p0 + v0 t + a t^2 / 2 at k = 0. In float, 1 - e^{-kt} and t - R cancel for small
// k t, so below k t = 0.5 both come from their Taylor series (8 terms, truncation < 3e-8
// relative); above it from the exponential, where nothing cancels (R / t <= 0.79). For k t = 1e4
// e^{-kt} is 0 and R = 1/k, L = (t - 1/k)/k: finite and exact.
//
// Ground bounce has no closed form with drag (the bounce time solves t + c e^{-kt} = d, a
// Lambert-W equation, and each bounce restarts the form): stateless particles do not bounce; a
// reaction that wants bouncing debris uses a CPU technique. Documented in reactions/README.md.
#include <cmath>

#include <glm/glm.hpp>

namespace fx {

/// R(t) and L(t) above, in float, the way the shader computes them. k >= 0, t >= 0.
struct StatelessCoefficients {
    float reach = 0.0f;
    float lift = 0.0f;
    float decay = 1.0f;
};

inline StatelessCoefficients statelessCoefficients(float k, float t) {
    StatelessCoefficients c;
    const float kt = k * t;
    c.decay = std::exp(-kt);
    if (kt < 0.5f) {
        // Horner: R = t * sum (-kt)^n / (n+1)!, L = t^2 * sum (-kt)^n / (n+2)!, n = 0..7.
        const float x = -kt;
        float r = 1.0f / 40320.0f, l = 1.0f / 362880.0f;
        const float rc[7] = {1.0f / 5040.0f, 1.0f / 720.0f, 1.0f / 120.0f, 1.0f / 24.0f,
                             1.0f / 6.0f, 0.5f, 1.0f};
        const float lc[7] = {1.0f / 40320.0f, 1.0f / 5040.0f, 1.0f / 720.0f, 1.0f / 120.0f,
                             1.0f / 24.0f, 1.0f / 6.0f, 0.5f};
        for (int i = 0; i < 7; ++i) {
            r = r * x + rc[i];
            l = l * x + lc[i];
        }
        c.reach = t * r;
        c.lift = t * t * l;
    } else {
        c.reach = (1.0f - c.decay) / k;
        c.lift = (t - c.reach) / k;
    }
    return c;
}

/// Position at age t of a particle born at p0 with v0.
inline glm::vec3 statelessPosition(glm::vec3 p0, glm::vec3 v0, glm::vec3 u, glm::vec3 g, float k,
                                   float t) {
    const StatelessCoefficients c = statelessCoefficients(k, t);
    return p0 + u * t + (v0 - u) * c.reach + g * c.lift;
}

/// Velocity at age t (for motion-stretched sparks).
inline glm::vec3 statelessVelocity(glm::vec3 v0, glm::vec3 u, glm::vec3 g, float k, float t) {
    const StatelessCoefficients c = statelessCoefficients(k, t);
    return u + (v0 - u) * c.decay + g * c.reach;
}

}  // namespace fx
