#version 330 core
// Spherical billboards (003 sections 2.2.7 and 3.4.3, after Umenhoffer et al.): the particle is
// a sphere of radius size/2. Each pixel's view ray is intersected with it and the chord
// [entry, exit] is clipped to [near plane, scene depth]; the pixel's opacity is the atlas/ramp
// opacity scaled by the share of the chord that survives the clipping. So a particle fades
// continuously as geometry cuts into it (no intersection line), and when the camera moves into
// it the near plane eats the chord gradually (no pop). The atlas gives the shape: it is looked
// up at the ray's closest approach to the centre, in camera right/up axes, in units of radius.
//
// Linear in the surviving share (optically thin) rather than Beer-Lambert 1-(1-a)^share: the
// exponential turns a near-opaque puff into a hard edge the moment the chord is non-zero.
// Near fade uses the depth of the middle of the visible chord, which never drops below the
// near plane, so a camera inside a large particle still sees it, fading as the chord shortens.
#include "particles_common.glsl"

in vec3 vViewPos;
flat in vec4 vRamp;
flat in float vFade;
flat in float vFrame;
flat in vec4 vSphere;
flat in float vRotation;
#ifdef FX_CLASSIFY
flat in float vInFront;
#endif
#ifdef FX_LIT
in vec3 vSunLight;
in float vPhase;
#endif

layout(location = 0) out vec4 oColor;

void main() {
    vec3 dir = normalize(vViewPos);
    float depthPerMetre = max(-dir.z, 1e-4);  // view depth gained per metre along the ray
    vec3 centre = vSphere.xyz;
    float r = vSphere.w;
    float tMid = dot(centre, dir);            // ray parameter of the closest approach
    vec3 offset = dir * tMid - centre;
    float d2 = dot(offset, offset);

    // Sampled before any discard: the atlas needs derivatives from the whole 2x2 quad.
    vec4 texel = texture(uAtlas, atlasUV(rotate2(offset.xy / r, vRotation), vFrame));
    if (d2 >= r * r) discard;

    float halfChord = sqrt(r * r - d2);
    float tNear = uNear / depthPerMetre;
#ifdef FX_CLASSIFY
    // Wholly in front of the scene in its tiles (particles_classify.glsl): the chord's exit is
    // never clipped, and the scene depth is not read.
    float tScene = 3.0e38;
    if (vInFront == 0.0) tScene = sceneDepthAt(gl_FragCoord.xy) / depthPerMetre;
#else
    float tScene = sceneDepthAt(gl_FragCoord.xy) / depthPerMetre;
#endif
    float t0 = max(tMid - halfChord, tNear);
    float t1 = min(tMid + halfChord, tScene);
    float visible = clamp((t1 - t0) / (2.0 * halfChord), 0.0, 1.0);
    float midDepth = 0.5 * (t0 + t1) * depthPerMetre;
    float coverage = texel.a * visible * nearFadeFactor(max(midDepth, uNear));
#ifdef FX_LIT
    // The sphere's normal where the visible chord starts, bent by the atlas's normal map.
    vec3 entry = dir * t0;
    vec3 bumps = atlasNormal(texel);
    vec3 n = normalize((entry - centre) / r + uNormalStrength * 0.6 * vec3(rotate2(bumps.xy, -vRotation), 0.0));
    texel.rgb = texel.bbb * smokeLight(n, texel.a, vSunLight, vPhase);
#endif
    oColor = shadeOutput(vRamp, vFade, texel, coverage);
}
