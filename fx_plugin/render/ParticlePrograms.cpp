#include "ParticlePrograms.h"

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
    return p;
}

}  // namespace

ParticlePrograms::~ParticlePrograms() {
    for (ParticleProgram& p : programs_) {
        if (p.program) glDeleteProgram(p.program);
    }
}

void ParticlePrograms::build(const std::string& shaderDir, std::vector<std::string>* errors) {
    for (int v = 0; v < VariantCount; ++v) {
        if (programs_[v].program) continue;
        std::string error;
        const GLuint program = buildProgram(shaderDir, "vs_particles.glsl", kSources[v].fragment,
                                            kSources[v].defines, &error);
        if (!program) {
            errors->push_back(error);
            continue;
        }
        programs_[v] = locate(program);
    }
}

ParticlePrograms::Variant ParticlePrograms::variantFor(Technique technique, bool quarterRes) {
    switch (technique) {
    case Technique::Hard: return quarterRes ? HardLinearDepth : HardZBuffer;
    case Technique::Spherical: return Spherical;
    case Technique::Soft:
    case Technique::FromReaction: break;
    }
    return Soft;
}

uint32_t ParticlePrograms::usableTechniques(bool quarterRes) const {
    uint32_t mask = 0;
    for (Technique t : {Technique::Hard, Technique::Soft, Technique::Spherical}) {
        if (programs_[variantFor(t, quarterRes)].program) mask |= techniqueBit(t);
    }
    return mask;
}

}  // namespace fx
