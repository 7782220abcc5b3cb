#pragma once
// Turbulent air for smoke: a divergence-free velocity field, the curl of a vector potential made
// of lattice gradient noise (several octaves), plus an optional Rankine vortex (a spiral) around
// a vertical axis. 002 moves its particles with a spiral field plus lattice noise; taking the
// curl of a noise potential instead of the noise itself keeps the flow incompressible, so puffs
// swirl and stretch instead of bunching into sinks or thinning out of sources.
//
// Field (p = x / scale, t in seconds):
//     psi_c(p, t) = sum_o 2^{-2o} N_c(2^o p + t * speed / scale * d_o),   c = x, y, z
//     turbulence(x, t) = strength / norm * curl_p psi
// N_c are three gradient-noise functions on one lattice (quintic fade, so C2 and their analytic
// gradients are exact; each picks its lattice gradients from its own byte of the corner hash), d_o a fixed unit drift direction per octave (the pattern evolves instead
// of sliding as one piece), norm = sum_o 2^{-o} so `strength` is the field's scale in m/s
// whatever the octave count. The curl is taken in p; the 1/scale factor is absorbed into
// `strength`, so a larger scale gives larger eddies at the same speed. Every octave is the curl of
// a smooth potential, so div = 0 exactly; numerically (central differences) it is O(h^2).
//
// Vortex around the axis through `axis` (vertical): tangential speed s * r / R inside radius R and
// s * R / r outside (a Rankine vortex), counter-clockwise seen from above. Purely azimuthal and
// a function of r only, so it is divergence-free too.
#include <cstdint>

#include <glm/glm.hpp>

#include "reactions/AirFieldDesc.h"  // TurbulenceDesc, VortexDesc

namespace fx {

/// One gradient-noise sample: value and its analytic gradient. Noise in about [-1, 1].
struct NoiseSample {
    float value = 0.0f;
    glm::vec3 gradient{0.0f};
};

/// 3D gradient (Perlin-style) noise with quintic fade, lattice hashed from `seed` (no tables).
NoiseSample gradientNoise(glm::vec3 p, uint32_t seed);

/// curl of the noise potential at x (world, m), time t (s). Zero when desc is off.
glm::vec3 curlNoise(const TurbulenceDesc& desc, glm::vec3 x, double t);

/// The vortex's velocity at x around the vertical axis through `axis` (only x and z of it count).
glm::vec3 vortexVelocity(const VortexDesc& desc, glm::vec3 x, glm::vec3 axis);

}  // namespace fx
