#include "ParticlePrograms.h"

#include <cmath>

#include "render/PrivateGl.h"

#include "DrawList.h"
#include "ShaderLoader.h"

namespace fx {
namespace {

struct VariantSource {
    const char* fragment;
    const char* defines;
};

constexpr VariantSource kSources[ParticlePrograms::VariantCount] = {
    {"fs_particles_hard.glsl", ""},
    {"fs_particles_hard.glsl", "#define FX_LINEAR_DEPTH_TEST 1\n"},
    {"fs_particles_soft.glsl", ""},
    {"fs_particles_spherical.glsl", "#define FX_SPHERICAL 1\n"},
    {"fs_particles_soft.glsl", "#define FX_GENERAL_POWER 1\n"},
};

ParticleProgram locate(GLuint program) {
    ParticleProgram p;
    p.program = program;
    p.view = glGetUniformLocation(program, "uView");
    p.proj = glGetUniformLocation(program, "uProj");
    p.nearPlane = glGetUniformLocation(program, "uNear");
    p.farPlane = glGetUniformLocation(program, "uFar");
    p.slopeMax = glGetUniformLocation(program, "uSlopeMax");
    p.rampRow = glGetUniformLocation(program, "uRampRow");
    p.blendMode = glGetUniformLocation(program, "uBlendMode");
    p.softScale = glGetUniformLocation(program, "uSoftScale");
    p.contrastPower = glGetUniformLocation(program, "uContrastPower");
    p.nearFade = glGetUniformLocation(program, "uNearFade");
    p.atlas = glGetUniformLocation(program, "uAtlas");
    p.ramp = glGetUniformLocation(program, "uRamp");
    p.sceneDepth = glGetUniformLocation(program, "uSceneDepth");
    p.trimmed = glGetUniformLocation(program, "uTrimmed");
    p.shapeBuckets = glGetUniformLocation(program, "uShapeBuckets");
    p.lodScale = glGetUniformLocation(program, "uLodScale");
    p.shapes = glGetUniformLocation(program, "uShapes");
    p.shapeInfo = glGetUniformLocation(program, "uShapeInfo");
    p.pixelSlope = glGetUniformLocation(program, "uPixelSlope");
    p.powerWhole = glGetUniformLocation(program, "uPowerWhole");
    p.powerHalf = glGetUniformLocation(program, "uPowerHalf");
    p.sunView = glGetUniformLocation(program, "uSunView");
    p.sunColor = glGetUniformLocation(program, "uSunColor");
    p.ambient = glGetUniformLocation(program, "uAmbient");
    p.normalStrength = glGetUniformLocation(program, "uNormalStrength");
    p.scattering = glGetUniformLocation(program, "uScattering");
    p.anisotropy = glGetUniformLocation(program, "uAnisotropy");
    p.absorption = glGetUniformLocation(program, "uAbsorption");
    p.shadowed = glGetUniformLocation(program, "uShadowed");
    p.viewToShadow = glGetUniformLocation(program, "uViewToShadow");
    p.opacity = glGetUniformLocation(program, "uOpacity");
    p.tiles = glGetUniformLocation(program, "uTiles");
    p.tilesCoarse = glGetUniformLocation(program, "uTilesCoarse");
    p.viewSize = glGetUniformLocation(program, "uViewSize");
    return p;
}

}  // namespace

ParticlePrograms::~ParticlePrograms() {
    for (auto& row : programs_) {
        for (ParticleProgram& p : row) {
            if (p.program) glDeleteProgram(p.program);
        }
    }
    for (auto& row : powered_) {
        for (ParticleProgram& p : row) {
            if (p.program) glDeleteProgram(p.program);
        }
    }
}

void ParticlePrograms::build(const std::string& shaderDir, std::vector<std::string>* errors,
                             const std::string& defines, uint32_t variants) {
    build(snapshotShaderReader(shaderReader(shaderDir)), errors, defines, variants);
}

void ParticlePrograms::build(const ShaderReader& read, std::vector<std::string>* errors, const std::string& defines,
                             uint32_t variants) {
    // One snapshot per program set: every later build of it (a power on first use) reads the
    // files this build read, never a newer, maybe broken, edit.
    if (!reader_) reader_ = read;
    defines_ = defines;
    for (int lit = 0; lit < 2; ++lit) {
        for (int v = 0; v < VariantCount; ++v) {
            if (programs_[lit][v].program || (variants & (1u << v)) == 0) continue;
            std::string error;
            const std::string all = defines + kSources[v].defines + (lit ? "#define FX_LIT 1\n" : "");
            const GLuint program = buildProgram(reader_, "vs_particles.glsl", kSources[v].fragment, all, &error);
            if (!program) {
                errors->push_back(error);
                continue;
            }
            programs_[lit][v] = locate(program);
        }
    }
}

bool ParticlePrograms::buildPower(int steps, bool lit, std::string* error) {
    poweredTried_[lit ? 1 : 0][steps] = true;
    const std::string all = defines_ + kSources[Soft].defines + "#define FX_POWER_STEPS " + std::to_string(steps) +
                            "\n" + (lit ? "#define FX_LIT 1\n" : "");
    if (!reader_) {
        *error = "fs_particles_soft.glsl:0: the soft programs were never built";
        return false;
    }
    const GLuint program = buildProgram(reader_, "vs_particles.glsl", kSources[Soft].fragment, all, error);
    if (!program) return false;
    powered_[lit ? 1 : 0][steps] = locate(program);
    return true;
}

const ParticleProgram& ParticlePrograms::get(Variant v, bool lit, float contrastPower) {
    const ParticleProgram& fallback = get(v, lit);
    int whole = 0, half = 0;
    if (v != Soft || !fallback.program || !halfWholePower(contrastPower, &whole, &half)) return fallback;
    const int steps = 2 * whole + half;
    const int l = lit ? 1 : 0;
    if (!poweredTried_[l][steps]) {
        std::string error;  // Soft keeps drawing this power; the caller reports the failure
        if (!buildPower(steps, lit, &error)) lateErrors_.push_back(error);
    }
    return powered_[l][steps].program ? powered_[l][steps] : fallback;
}

void ParticlePrograms::buildPowers(const std::vector<int>& steps, std::vector<std::string>* errors) {
    for (int s : steps) {
        if (s < 0 || s > kMaxPowerSteps) continue;
        for (bool lit : {false, true}) {
            if (poweredTried_[lit ? 1 : 0][s]) continue;
            std::string error;
            if (!buildPower(s, lit, &error)) errors->push_back(error);
        }
    }
}

std::vector<std::string> ParticlePrograms::takeErrors() {
    std::vector<std::string> taken;
    taken.swap(lateErrors_);
    return taken;
}

std::vector<int> ParticlePrograms::builtPowers() const {
    std::vector<int> steps;
    for (int s = 0; s <= kMaxPowerSteps; ++s) {
        if (powered_[0][s].program || powered_[1][s].program) steps.push_back(s);
    }
    return steps;
}

bool ParticlePrograms::halfWholePower(float contrastPower, int* whole, int* half) {
    const float twice = 2.0f * contrastPower;
    const float rounded = std::round(twice);
    if (!(std::fabs(twice - rounded) <= 1e-6f * std::fmax(1.0f, twice)) || rounded < 0.0f || rounded > 32.0f) {
        return false;
    }
    const int steps = int(rounded);
    *whole = steps / 2;
    *half = steps % 2;
    return true;
}

ParticlePrograms::Variant ParticlePrograms::variantFor(Technique technique, bool quarterRes, float contrastPower) {
    switch (technique) {
    case Technique::Hard: return quarterRes ? HardLinearDepth : HardZBuffer;
    case Technique::Spherical: return Spherical;
    case Technique::Soft:
    case Technique::Mega:  // drawn by its own renderer; soft where a billboard stands in
    case Technique::FromReaction: break;
    }
    int whole = 0, half = 0;
    return halfWholePower(contrastPower, &whole, &half) ? Soft : SoftGeneralPower;
}

uint32_t ParticlePrograms::usableTechniques(bool quarterRes) const {
    uint32_t mask = 0;
    for (Technique t : {Technique::Hard, Technique::Soft, Technique::Spherical}) {
        if (programs_[0][variantFor(t, quarterRes)].program) mask |= techniqueBit(t);
    }
    // Soft draws with either soft program (by contrast_power): both or neither.
    if (!programs_[0][SoftGeneralPower].program) mask &= ~techniqueBit(Technique::Soft);
    return mask;
}

}  // namespace fx
