#pragma once
// The particle programs, one per technique and target kind, built from shaders/ by ShaderLoader:
//   HardZBuffer     vs_particles + fs_particles_hard                        (full res, z-buffer test)
//   HardLinearDepth vs_particles + fs_particles_hard, FX_LINEAR_DEPTH_TEST  (quarter res)
//   Soft            vs_particles + fs_particles_soft  (contrast_power whole or half-whole, <= 16:
//                                                    multiplies and a sqrt)
//   SoftGeneralPower vs_particles + fs_particles_soft, FX_GENERAL_POWER (any contrast_power: pow)
//   Spherical       vs_particles + fs_particles_spherical, FX_SPHERICAL
// Each again with FX_LIT (lit smoke: particles_common.glsl's smokeLight) for reactions drawn
// under a scene light; unlit smoke keeps the programs without a line of lighting code.
// A program that fails to build stays 0 and its technique is not drawn (the failure is reported
// by the caller); the others still work.
#include <cstdint>
#include <string>
#include <vector>

#include "fx/Plugin.h"

namespace fx {

/// Uniform locations shared by every particle program (-1 where a program does not use one).
struct ParticleProgram {
    uint32_t program = 0;
    int view = -1, proj = -1, nearPlane = -1, farPlane = -1, slopeMax = -1;
    int rampRow = -1, blendMode = -1, softScale = -1, contrastPower = -1, nearFade = -1;
    int atlas = -1, ramp = -1, sceneDepth = -1;
    int trimmed = -1, shapeBuckets = -1, lodScale = -1, shapes = -1, shapeInfo = -1, pixelSlope = -1;
    int powerWhole = -1, powerHalf = -1;
    // FX_CLASSIFY only (FadeClassifier.h).
    int tiles = -1, tilesCoarse = -1, viewSize = -1;
    // FX_LIT only.
    int sunView = -1, sunColor = -1, ambient = -1, normalStrength = -1, scattering = -1, anisotropy = -1,
        absorption = -1, shadowed = -1, viewToShadow = -1, opacity = -1;
};

class ParticlePrograms {
public:
    enum Variant : int { HardZBuffer = 0, HardLinearDepth, Soft, Spherical, SoftGeneralPower, VariantCount };

    ParticlePrograms() = default;
    ~ParticlePrograms();
    ParticlePrograms(const ParticlePrograms&) = delete;
    ParticlePrograms& operator=(const ParticlePrograms&) = delete;

    /// Builds every variant in `variants` (a mask of 1 << Variant), each with `defines` added;
    /// appends one "file:line: message" block per failed one to *errors.
    void build(const std::string& shaderDir, std::vector<std::string>* errors, const std::string& defines = "",
               uint32_t variants = ~0u);
    /// `lit`: the FX_LIT build of the variant (program 0 when it failed to build: draw unlit).
    const ParticleProgram& get(Variant v, bool lit = false) const { return programs_[lit ? 1 : 0][v]; }
    /// `contrastPower` picks between the two soft programs (see above).
    static Variant variantFor(Technique technique, bool quarterRes, float contrastPower = 1.0f);
    /// contrast_power = whole + half / 2 with whole in [0, 16], half 0 or 1: true and the split.
    static bool halfWholePower(float contrastPower, int* whole, int* half);
    /// techniqueBit() mask of the techniques drawable on a full-res or a quarter-res target.
    uint32_t usableTechniques(bool quarterRes) const;

private:
    ParticleProgram programs_[2][VariantCount];  ///< [unlit, lit]
};

}  // namespace fx
