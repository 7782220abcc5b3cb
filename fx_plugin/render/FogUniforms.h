#pragma once
// The host's fog (fx::Fog, ViewInfo::fog) as the uniforms of shaders/particles_fog.glsl, which
// every program that writes smoke colour includes: the billboard programs (hard, soft,
// spherical, at full and quarter resolution), mega's composite and the stateless sparks. One
// uniform, not a program variant: fog off (uFogMode 0, also what a program gets when nobody sets
// it) returns the colour untouched, so images without fog are the same bit for bit and no
// program is built for it.
#include "fx/Types.h"

namespace fx {

/// Uniform locations of particles_fog.glsl (-1 where a program does not use them).
struct FogUniforms {
    int mode = -1, color = -1, params = -1;
    /// Looks them up in `program`.
    static FogUniforms of(uint32_t program);
};

/// Sets `fog` on the program in use (off: only the mode).
void setFogUniforms(const FogUniforms& at, const Fog& fog);

}  // namespace fx
