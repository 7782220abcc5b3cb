#include "MegaPrograms.h"

#include "render/PrivateGl.h"

#include "Uniforms.h"

namespace fx {

void MegaPrograms::bind(const ProgramCache& programs) {
    depth = programs.passProgram(ProgramCache::MegaDepth);
    spheres = programs.passProgram(ProgramCache::MegaSpheres);
    blur = programs.passProgram(ProgramCache::MegaBlur);
    shade = programs.passProgram(ProgramCache::MegaShade);
    composite = programs.passProgram(ProgramCache::MegaComposite);
    locateUniforms(depth, {{&depthScene, "uSceneDepth"}, {&depthRatio, "uRatio"},
                           {&depthDecode.coeffs, "uDepthCoeffs"},
                           {&depthDecode.window, "uDepthWindow"}, {&depthDecode.drawOrigin, "uDrawOrigin"}});
    locateUniforms(spheres, {{&sView, "uView"}, {&sProj, "uProj"}, {&sNear, "uNear"}, {&sFar, "uFar"},
                             {&sSlope, "uSlopeMax"}, {&sRamp, "uRamp"}, {&sRampRow, "uRampRow"},
                             {&sMegaDepth, "uMegaDepth"}, {&sDensity, "uDensity"}});
    const GLuint blurs[2] = {blur, shade};
    for (int i = 0; i < 2; ++i) {
        Blur& u = b[i];
        locateUniforms(blurs[i],
                       {{&u.color, "uColor"}, {&u.density, "uDensity"}, {&u.encoded, "uEncodedDepth"},
                        {&u.direction, "uDirection"}, {&u.taps, "uTaps"}, {&u.tapWeights, "uTapWeight"},
                        {&u.falloff, "uDepthFalloff"}, {&u.invView, "uInvView"}, {&u.projTerms, "uProjTerms"},
                        {&u.time, "uTime"}, {&u.noiseStrength, "uNoiseStrength"}, {&u.noiseScale, "uNoiseScale"},
                        {&u.lit, "uLit"}, {&u.toSun, "uToSun"}, {&u.sunColor, "uSunColor"}, {&u.ambient, "uAmbient"},
                        {&u.scattering, "uScattering"}, {&u.anisotropy, "uAnisotropy"},
                        {&u.absorption, "uAbsorption"}});
    }
    locateUniforms(composite, {{&cCloud, "uCloud"}, {&cCloudDepth, "uCloudDepth"}, {&cScene, "uSceneDepth"},
                               {&cDecode.coeffs, "uDepthCoeffs"},
                               {&cDecode.window, "uDepthWindow"}, {&cDecode.drawOrigin, "uDrawOrigin"},
                               {&cSoft, "uSoftScale"}, {&cLowMap, "uLowMap"}, {&cInvLow, "uInvLow"},
                               {&cLowLast, "uLowLast"}});
    shadeFog = FogUniforms::of(shade);
}

}  // namespace fx
