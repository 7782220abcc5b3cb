#include "MegaPrograms.h"

#include "render/PrivateGl.h"

#include "ShaderLoader.h"

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
    auto loc = [](GLuint program, const char* name) { return glGetUniformLocation(program, name); };
    if (depth) {
        depthScene = loc(depth, "uSceneDepth");
        depthRatio = loc(depth, "uRatio");
    }
    if (spheres) {
        sView = loc(spheres, "uView");
        sProj = loc(spheres, "uProj");
        sNear = loc(spheres, "uNear");
        sFar = loc(spheres, "uFar");
        sSlope = loc(spheres, "uSlopeMax");
        sRamp = loc(spheres, "uRamp");
        sRampRow = loc(spheres, "uRampRow");
        sMegaDepth = loc(spheres, "uMegaDepth");
        sDensity = loc(spheres, "uDensity");
    }
    const GLuint blurs[2] = {blur, shade};
    for (int i = 0; i < 2; ++i) {
        const GLuint p = blurs[i];
        if (!p) continue;
        Blur& u = b[i];
        u.color = loc(p, "uColor");
        u.density = loc(p, "uDensity");
        u.encoded = loc(p, "uEncodedDepth");
        u.direction = loc(p, "uDirection");
        u.taps = loc(p, "uTaps");
        u.sigma = loc(p, "uSigma");
        u.falloff = loc(p, "uDepthFalloff");
        u.invView = loc(p, "uInvView");
        u.projTerms = loc(p, "uProjTerms");
        u.time = loc(p, "uTime");
        u.noiseStrength = loc(p, "uNoiseStrength");
        u.noiseScale = loc(p, "uNoiseScale");
        u.lit = loc(p, "uLit");
        u.toSun = loc(p, "uToSun");
        u.sunColor = loc(p, "uSunColor");
        u.ambient = loc(p, "uAmbient");
        u.scattering = loc(p, "uScattering");
        u.anisotropy = loc(p, "uAnisotropy");
        u.absorption = loc(p, "uAbsorption");
    }
    if (composite) {
        cCloud = loc(composite, "uCloud");
        cCloudDepth = loc(composite, "uCloudDepth");
        cScene = loc(composite, "uSceneDepth");
        cSoft = loc(composite, "uSoftScale");
    }
}

}  // namespace fx
