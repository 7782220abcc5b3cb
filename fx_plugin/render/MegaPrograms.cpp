#include "MegaPrograms.h"

#include "render/PrivateGl.h"

#include "ShaderLoader.h"
#include "Uniforms.h"

namespace fx {

MegaPrograms::~MegaPrograms() {
    for (GLuint p : {depth, spheres, blur, shade, composite}) {
        if (p) glDeleteProgram(p);
    }
}

void MegaPrograms::build(const std::string& dir, std::vector<std::string>* errors) {
    auto make = [&](const char* vs, const char* fs, const char* defines) {
        std::string error;
        const GLuint p = buildProgram(dir, vs, fs, defines, &error);
        if (!p) errors->push_back(error);
        return p;
    };
    depth = make("vs_particles_fullscreen.glsl", "fs_mega_depth.glsl", "");
    spheres = make("vs_mega.glsl", "fs_mega_spheres.glsl", "");
    blur = make("vs_particles_fullscreen.glsl", "fs_mega_blur.glsl", "");
    shade = make("vs_particles_fullscreen.glsl", "fs_mega_blur.glsl", "#define FX_MEGA_SHADE 1\n");
    composite = make("vs_particles_fullscreen.glsl", "fs_mega_composite.glsl", "");
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
                        {&u.direction, "uDirection"}, {&u.taps, "uTaps"}, {&u.sigma, "uSigma"},
                        {&u.falloff, "uDepthFalloff"}, {&u.invView, "uInvView"}, {&u.projTerms, "uProjTerms"},
                        {&u.time, "uTime"}, {&u.noiseStrength, "uNoiseStrength"}, {&u.noiseScale, "uNoiseScale"},
                        {&u.lit, "uLit"}, {&u.toSun, "uToSun"}, {&u.sunColor, "uSunColor"}, {&u.ambient, "uAmbient"},
                        {&u.scattering, "uScattering"}, {&u.anisotropy, "uAnisotropy"},
                        {&u.absorption, "uAbsorption"}});
    }
    locateUniforms(composite, {{&cCloud, "uCloud"}, {&cCloudDepth, "uCloudDepth"}, {&cScene, "uSceneDepth"},
                               {&cDecode.coeffs, "uDepthCoeffs"},
                               {&cDecode.window, "uDepthWindow"}, {&cDecode.drawOrigin, "uDrawOrigin"},
                               {&cSoft, "uSoftScale"}});
    shadeFog = FogUniforms::of(shade);
}

}  // namespace fx
