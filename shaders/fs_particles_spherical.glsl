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
#include "particles_varyings.glsl"

layout(location = 0) out vec4 oColor;

void main() {
    // The ray through this pixel, not normalised: it gains -ray.z of view depth per unit of its
    // parameter t, and the chord is worked out in view depth directly (one division).
    vec3 ray = vViewPos;
    vec3 centre = vSphere.xyz;
    float r = vSphere.w;
    float invLen2 = 1.0 / dot(ray, ray);
    float tMid = dot(centre, ray) * invLen2;  // ray parameter of the closest approach
    vec3 offset = ray * tMid - centre;
    float d2 = dot(offset, offset);

    // Sampled before any discard: the atlas needs derivatives from the whole 2x2 quad. The scene
    // depth is read there too, though the pixels off the sphere's outline (about 6 % of those the
    // bound rasterises: fxbench standard, llvmpipe count) do not need it. Read after the discard,
    // a GPU compiler need not move the fetch above it, and the two waits come one after the
    // other; here both fetches are issued before the first wait.
    vec4 texel = texture(uAtlas, atlasUV(turnBy(offset.xy, vTurn), vCell));
    float sceneZ = sceneDepthAt(gl_FragCoord.xy);
    if (d2 >= r * r) discard;

    float depthPerT = -ray.z;  // > 0: the quad lies at or past the near plane
    float halfDepth = sqrt((r * r - d2) * invLen2) * depthPerT;
    float midZ = tMid * depthPerT;
    float z0 = max(midZ - halfDepth, uNear);
    float z1 = min(midZ + halfDepth, sceneZ);
    float visible = clamp((z1 - z0) / (2.0 * halfDepth), 0.0, 1.0);
    float coverage = texel.a * visible * nearFadeFactor(max(0.5 * (z0 + z1), uNear));
    // Nothing to blend (the atlas's empty rim inside the trimmed bound, a chord wholly behind the
    // scene): 19 % of the samples in fxbench's standard frames at 1920x1080. The output would be
    // exactly 0, and blending 0 leaves the pixel as it was under every blend mode the renderer
    // sets, so discarding changes no pixel and saves those blends (and, lit, the light); this
    // shader discards already, so no early test is lost.
    if (coverage == 0.0) discard;
#ifdef FX_LIT
    // The sphere's normal where the visible chord starts, bent by the atlas's normal map.
    vec3 entry = ray * (z0 / depthPerT);
    vec3 bumps = atlasNormal(texel);
    vec3 n = normalize((entry - centre) / r + uNormalStrength * 0.6 * vec3(turnBack(bumps.xy, vTurn) * r, 0.0));
    texel.rgb = texel.bbb * smokeLight(n, texel.a, vSunLight, vPhase);
#endif
    // Fogged at the sphere's centre (particleFog): the middle of the chord through it.
    oColor = shadeOutput(vTint, vFogAdd, texel.rgb, coverage);
}
