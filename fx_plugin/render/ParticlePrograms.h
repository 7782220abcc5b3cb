#pragma once
// The particle programs, one per technique and target kind, built from shaders/ by ShaderLoader:
//   HardZBuffer     vs_particles + fs_particles_hard                        (full res, z-buffer test)
//   HardLinearDepth vs_particles + fs_particles_hard, FX_LINEAR_DEPTH_TEST  (quarter res)
//   Soft            vs_particles + fs_particles_soft  (contrast_power whole or half-whole, <= 16:
//                                                    multiplies and a sqrt)
//   SoftGeneralPower vs_particles + fs_particles_soft, FX_GENERAL_POWER (any contrast_power: pow)
//   Soft for one power  vs_particles + fs_particles_soft, FX_POWER_STEPS = 2 contrast_power: built on
//                   first use for each whole or half-whole power a reaction draws with (the curve's
//                   multiplies folded; power 1 draws no curve at all); Soft stands in until then
//                   and wherever that build fails.
//   Spherical       vs_particles + fs_particles_spherical, FX_SPHERICAL
// Each again with FX_LIT (lit smoke: particles_common.glsl's smokeLight) for reactions drawn
// under a scene light; unlit smoke keeps the programs without a line of lighting code.
// A program that fails to build stays 0 and its technique is not drawn (the failure is reported
// by the caller); the others still work.
#include <cstdint>
#include <string>
#include <vector>

#include "fx/Plugin.h"
#include "base/TextIo.h"

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
    /// appends one "file:line: message" block per failed one to *errors. The files are read once
    /// per ParticlePrograms (the first build) and kept: a later build of this set, a contrast
    /// power's included, uses the same text, so a rejected edit never reaches a running set.
    void build(const std::string& shaderDir, std::vector<std::string>* errors, const std::string& defines = "",
               uint32_t variants = ~0u);
    /// The same from `read` (kept for the later builds; a snapshot, see ShaderLoader.h).
    void build(const ShaderReader& read, std::vector<std::string>* errors, const std::string& defines = "",
               uint32_t variants = ~0u);
    /// `lit`: the FX_LIT build of the variant (program 0 when it failed to build: draw unlit).
    const ParticleProgram& get(Variant v, bool lit = false) const { return programs_[lit ? 1 : 0][v]; }
    /// The program that draws a batch of `v` with `contrastPower`: for Soft with a whole or
    /// half-whole power, that power's own build (compiled here the first time it is asked for;
    /// changes no bound GL state), else get(v, lit). Falls back to get(v, lit) where the power's
    /// build failed (its messages wait in takeErrors()).
    const ParticleProgram& get(Variant v, bool lit, float contrastPower);
    /// The messages of get()'s builds that failed since the last call, for the caller to report.
    std::vector<std::string> takeErrors();
    /// Builds the soft programs for the powers in `steps` (2 contrast_power each) now, lit and
    /// unlit, appending failures to *errors: a shader reload checks the powers in use with it.
    void buildPowers(const std::vector<int>& steps, std::vector<std::string>* errors);
    /// The powers (as 2 contrast_power) whose soft programs have been built.
    std::vector<int> builtPowers() const;
    /// `contrastPower` picks between the two soft programs (see above).
    static Variant variantFor(Technique technique, bool quarterRes, float contrastPower = 1.0f);
    /// contrast_power = whole + half / 2 with whole in [0, 16], half 0 or 1: true and the split.
    static bool halfWholePower(float contrastPower, int* whole, int* half);
    /// techniqueBit() mask of the techniques drawable on a full-res or a quarter-res target.
    uint32_t usableTechniques(bool quarterRes) const;

    static constexpr int kMaxPowerSteps = 32;  ///< contrast_power 16

private:
    bool buildPower(int steps, bool lit, std::string* error);

    ParticleProgram programs_[2][VariantCount];  ///< [unlit, lit]
    ParticleProgram powered_[2][kMaxPowerSteps + 1];  ///< Soft for one power: [unlit, lit][2 power]
    bool poweredTried_[2][kMaxPowerSteps + 1] = {};
    ShaderReader reader_;                     ///< build()'s files (a snapshot), for the powers' later builds
    std::string defines_;                     ///< build()'s, for the same
    std::vector<std::string> lateErrors_;     ///< get()'s failed builds, not yet taken
};

}  // namespace fx
