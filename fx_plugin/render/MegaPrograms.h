#pragma once
// The mega-particles' five programs (MegaRenderer.h) and their uniform locations: the depth
// downsample, the spheres, the blur, the blur that also shades, and the composite. The programs
// are the ProgramCache's (ProgramCache::megaKeys): a set compiles and deletes none; a shader
// reload binds a new set to the swapped cache.
#include <cstdint>
#include <string>
#include <vector>

#include "FogUniforms.h"
#include "ProgramCache.h"
#include "SceneDepthSource.h"

namespace fx {

struct MegaPrograms {
    uint32_t depth = 0, spheres = 0, blur = 0, shade = 0, composite = 0;
    int depthScene = -1, depthRatio = -1;
    SceneDepthUniforms depthDecode;
    int sView = -1, sProj = -1, sNear = -1, sFar = -1, sSlope = -1, sRamp = -1, sRampRow = -1, sMegaDepth = -1,
        sDensity = -1;
    struct Blur {
        int color = -1, density = -1, encoded = -1, direction = -1, taps = -1, tapWeights = -1, falloff = -1;
        int invView = -1, projTerms = -1, time = -1, noiseStrength = -1, noiseScale = -1, lit = -1;
        int toSun = -1, sunColor = -1, ambient = -1, scattering = -1, anisotropy = -1, absorption = -1;
    } b[2];  // [0] blur, [1] blur + shade
    int cCloud = -1, cCloudDepth = -1, cScene = -1, cSoft = -1;
    int cLowMap = -1, cInvLow = -1, cLowLast = -1;  ///< the footprint's line (fs_mega_composite.glsl)
    SceneDepthUniforms cDecode;
    FogUniforms shadeFog;  ///< the shading blur's (the cloud is fogged there, at its resolution)

    MegaPrograms() = default;
    MegaPrograms(const MegaPrograms&) = delete;
    MegaPrograms& operator=(const MegaPrograms&) = delete;

    bool ok() const { return depth && spheres && blur && shade && composite; }
    /// Takes the five programs of `programs` (0 where one is missing) and looks their uniforms
    /// up. Compiles nothing; `programs` must outlive their use (until the next bind).
    void bind(const ProgramCache& programs);
};

}  // namespace fx
