#version 330 core
// Soft particles (000 section 2.7): the quad fades out where it approaches the scene behind it,
// fade = saturate((scene_depth - particle_depth) / softness), shaped by the contrast curve.
// Both depths are linear view-space metres, so the fade is exact at any near/far ratio; the
// renderer therefore does not depth-test soft particles (a 24-bit z-buffer with near 0.01 and
// far 100 km cannot tell 1 m apart at 10 km), the fade alone hides what is behind geometry.
#include "particles_common.glsl"

in vec3 vViewPos;
in vec2 vLocal;
flat in vec4 vRamp;
flat in float vFade;
flat in float vFrame;
flat in float vRotation;
#ifdef FX_LIT
in vec3 vSunLight;
in float vPhase;
#endif

layout(location = 0) out vec4 oColor;

void main() {
    vec4 texel = texture(uAtlas, atlasUV(vLocal, vFrame)) * insideFrame(vLocal);
    float depth = -vViewPos.z;
    float coverage = texel.a * softFade(sceneDepthAt(gl_FragCoord.xy), depth) *
                     nearFadeFactor(depth);
#ifdef FX_LIT
    texel.rgb = texel.bbb * smokeLight(billboardNormal(texel, vRotation), texel.a, vSunLight, vPhase);
#endif
    oColor = shadeOutput(vRamp, vFade, texel, coverage);
}
