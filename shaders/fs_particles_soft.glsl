#version 330 core
// Soft particles (000 section 2.7): the quad fades out where it approaches the scene behind it,
// fade = saturate((scene_depth - particle_depth) / softness), shaped by the contrast curve.
// Both depths are linear view-space metres, so the fade is exact at any near/far ratio (the
// billboard's depth and scale are folded into the scene depth's decode per particle: softFade). The
// renderer depth-tests soft particles only against a reversed-Z float z-buffer, which keeps that
// precision too; against a standard 24-bit one (near 0.01 and far 100 km cannot tell 1 m apart
// at 10 km) it does not, and the fade alone hides what is behind geometry.
#include "particles_common.glsl"
#include "particles_varyings.glsl"

layout(location = 0) out vec4 oColor;

void main() {
    // Outside the frame only the alpha needs masking: coverage carries it to the colour.
    vec4 texel = texture(uAtlas, vAtlasUV);  // one mip level, the nearest (ParticleDraw's atlasSampler_)
    texel.a *= insideFrame(vLocal);
    // Where the atlas alone says the output is 0 (the empty rim inside a trimmed polygon), the
    // scene-depth fetch, the pass's costliest part on a GPU, is not made.
    if (texel.a == 0.0) discard;
    float fade = softFade(sceneDepthTexelAt(gl_FragCoord.xy), vFadeLine);
    float coverage = texel.a * fade;  // the near fade is in vTint (a billboard lies at one depth)
#ifdef FX_LIT
    texel.rgb = texel.bbb * smokeLight(sunCosine(billboardNormal(texel, vTurn)), texel.a, vSunLight, vPhase);
#endif
    oColor = shadeOutput(vTint, vFogAdd, texel.rgb, coverage);
}
