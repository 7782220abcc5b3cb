#version 330 core
// Hard particles: the legacy look. Full resolution: the renderer depth-tests the quad against the
// host's z-buffer (LEQUAL, no depth writes), so a particle is cut where it meets geometry.
// FX_LINEAR_DEPTH_TEST (quarter-res target, which has no z-buffer): the same all-or-nothing test
// made against the half-resolution linear depth instead.
#include "particles_common.glsl"
#include "particles_varyings.glsl"

layout(location = 0) out vec4 oColor;

void main() {
    // Outside the frame only the alpha needs masking: coverage carries it to the colour.
    vec4 texel = texture(uAtlas, vAtlasUV);  // one mip level, the nearest (ParticleDraw's atlasSampler_)
    texel.a *= insideFrame(vLocal);
    float coverage = texel.a;  // the near fade is in vTint (a billboard lies at one depth)
#ifdef FX_LINEAR_DEPTH_TEST
    coverage *= -vViewPos.z <= sceneDepthAt(gl_FragCoord.xy) ? 1.0 : 0.0;
#endif
#ifdef FX_LIT
    texel.rgb = texel.bbb * smokeLight(sunCosine(billboardNormal(texel, vTurn)), texel.a, vSunLight, vPhase);
#endif
    oColor = shadeOutput(vTint, vFogAdd, texel.rgb, coverage);
}
