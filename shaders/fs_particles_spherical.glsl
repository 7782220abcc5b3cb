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
    // The ray through this pixel, scaled to one metre of view depth: the quad lies at one depth,
    // so its slope is what the vertices hand over, and the ray's parameter is view depth itself.
    // The closest approach's offset is worked out explicitly (not as |c|^2 - (c.ray)^2 / |ray|^2,
    // which cancels catastrophically for a small sphere far away).
    vec2 slope = vSlope;
    vec3 centre = vSphere.xyz;
    float r2 = vSphere.w;  // the radius squared
    float invLen2 = 1.0 / (1.0 + slope.x * slope.x + slope.y * slope.y);
    float tMid = (centre.x * slope.x + centre.y * slope.y - centre.z) * invLen2;  // depth of the closest approach
    vec2 offset = vec2(slope.x * tMid - centre.x, slope.y * tMid - centre.y);  // the closest approach minus the centre (x, y)
    float offsetZ = tMid + centre.z;  // and its z, negated: only its square is used
    float d2 = offset.x * offset.x + offset.y * offset.y + offsetZ * offsetZ;

    // Sampled before any discard: the atlas needs derivatives from the whole 2x2 quad. The scene
    // depth is read there too, though the pixels off the sphere's outline (about 6 % of those the
    // bound rasterises: fxbench standard, llvmpipe count) do not need it. Read after the discard,
    // a GPU compiler need not move the fetch above it, and the two waits come one after the
    // other; here both fetches are issued before the first wait.
    vec2 uv = vec2(vAtlasBase.x + offset.x * vAtlasMap.x + offset.y * vAtlasMap.y,
                   vAtlasBase.y + offset.x * vAtlasMap.z + offset.y * vAtlasMap.w);  // sphereAtlasMap
    vec4 texel = texture(uAtlas, uv);
    float sceneZ = sceneDepthAt(gl_FragCoord.xy);
    if (d2 >= r2) discard;

    float halfDepth = sqrt((r2 - d2) * invLen2);
    float z0 = max(tMid - halfDepth, uNear);
    float z1 = min(tMid + halfDepth, sceneZ);
    float visible = clamp((z1 - z0) / (2.0 * halfDepth), 0.0, 1.0);
    // The middle of the visible chord lies past the near plane wherever the chord is visible
    // (z0 >= near); where it is not, visible is 0 and the near fade is in [0, 1] all the same.
    float coverage = texel.a * visible * nearFadeFactor(0.5 * (z0 + z1));
    // Nothing to blend (the atlas's empty rim inside the trimmed bound, a chord wholly behind the
    // scene): 19 % of the samples in fxbench's standard frames at 1920x1080. The output would be
    // exactly 0, and blending 0 leaves the pixel as it was under every blend mode the renderer
    // sets, so discarding changes no pixel and saves those blends (and, lit, the light); this
    // shader discards already, so no early test is lost.
    if (coverage == 0.0) discard;
#ifdef FX_LIT
    // The sphere's normal where the visible chord starts, bent by the atlas's normal map:
    // (entry - centre) / r + 0.6 s (turned bumps, 0), times r (sunCosine takes any length), with
    // vTurn the angle's (cos, sin) times 0.6 s r (the vertex shader's, in lit programs).
    vec3 bumps = atlasNormal(texel);
    vec2 bent = turnBack(bumps.xy, vTurn);
    vec3 m = vec3(slope.x * z0 - centre.x + bent.x, slope.y * z0 - centre.y + bent.y, -z0 - centre.z);
    texel.rgb = texel.bbb * smokeLight(sunCosine(m), texel.a, vSunLight, vPhase);
#endif
    // Fogged at the sphere's centre (particleFog): the middle of the chord through it.
    oColor = shadeOutput(vTint, vFogAdd, texel.rgb, coverage);
}
