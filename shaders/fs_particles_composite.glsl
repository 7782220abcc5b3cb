#version 330 core
// Quarter-res step 3: the half-resolution premultiplied particle colour onto the scene,
// blended (ONE, ONE_MINUS_SRC_ALPHA).
//
// Depth-aware upsampling, after NVIDIA's nearest-depth upsampling (Bavoil, "Opacity Mapping",
// 2011): take the four low-res texels of the bilinear footprint. Where all their depths are within
// a relative threshold of this pixel's full-res depth, blend them bilinearly. Otherwise the pixel
// sits on a depth edge: blend, with renormalised bilinear weights, only the texels on this
// pixel's side (depth within the threshold), and when there is none take the single texel whose
// depth is closest. Smoke computed for a near surface then never smears onto a far one and vice
// versa, and along an edge the result stays as smooth as bilinear. FX_COMPOSITE_BILINEAR keeps
// plain bilinear (for comparison).
// Two builds (QuarterResPrograms::CompositeVariant), not a uniform branch: a CPU rasteriser runs
// both sides of a branch, so one program with both paths paid for both paths' fetches.
uniform sampler2D uHalfColor;   // premultiplied RGBA8 (RGBA16F with spheres), half x half
uniform sampler2D uHalfDepth;   // red: min depth per 2x2 block (RG32F, green the max)
uniform sampler2D uSceneDepth;  // full-res scene depth (particles_scene_depth.glsl)
uniform float uDepthThreshold;  // relative: |low - full| > threshold * full is an edge
#include "particles_scene_depth.glsl"
#include "particles_footprint.glsl"

layout(location = 0) out vec4 oColor;

void main() {
    ivec2 base, last;
    vec2 f;
    vec2 pixel = fragmentFootprint(textureSize(uHalfColor, 0), base, f, last);
    ivec2 t0 = clamp(base, ivec2(0), last), t1 = clamp(base + ivec2(1, 0), ivec2(0), last);
    ivec2 t2 = clamp(base + ivec2(0, 1), ivec2(0), last), t3 = clamp(base + ivec2(1, 1), ivec2(0), last);
    float w0 = (1.0 - f.x) * (1.0 - f.y), w1 = f.x * (1.0 - f.y), w2 = (1.0 - f.x) * f.y, w3 = f.x * f.y;

    vec4 c0 = texelFetch(uHalfColor, t0, 0), c1 = texelFetch(uHalfColor, t1, 0);
    vec4 c2 = texelFetch(uHalfColor, t2, 0), c3 = texelFetch(uHalfColor, t3, 0);
    vec4 bilinear = vec4(0.0) + w0 * c0 + w1 * c1 + w2 * c2 + w3 * c3;
    // No smoke in the footprint (premultiplied, so additive smoke with alpha 0 still counts):
    // blending it would leave the pixel as it is, so it is not blended at all. Inside the tiles
    // many pixels are smoke-free; a GPU then skips the scene-depth fetch and the blend's
    // read-modify-write there.
    if (all(equal(c0 + c1 + c2 + c3, vec4(0.0)))) discard;

#if defined(FX_COMPOSITE_BILINEAR)
    oColor = bilinear;
#else
    // On an edge, keep the bilinear weights of the texels on this pixel's side of it (depth
    // within the threshold), renormalised; only when none is, the single nearest-depth texel
    // (the first of equal ones).
    float full = linearSceneDepth(texelFetch(uSceneDepth, sceneDepthTexel(ivec2(pixel)), 0).r);  // nothing drawn: 3.0e38
    float limit = uDepthThreshold * full;
    vec4 diff = abs(vec4(texelFetch(uHalfDepth, t0, 0).r, texelFetch(uHalfDepth, t1, 0).r,
                         texelFetch(uHalfDepth, t2, 0).r, texelFetch(uHalfDepth, t3, 0).r) - full);
    bvec4 inside = lessThanEqual(diff, vec4(limit));
    vec4 wIn = vec4(inside.x ? w0 : 0.0, inside.y ? w1 : 0.0, inside.z ? w2 : 0.0, inside.w ? w3 : 0.0);
    vec4 matched = vec4(0.0) + wIn.x * c0 + wIn.y * c1 + wIn.z * c2 + wIn.w * c3;
    float matchedWeight = 0.0 + wIn.x + wIn.y + wIn.z + wIn.w;
    vec4 nearest = c0;
    float best = diff.x;
    if (diff.y < best) { best = diff.y; nearest = c1; }
    if (diff.z < best) { best = diff.z; nearest = c2; }
    if (diff.w < best) { best = diff.w; nearest = c3; }
    oColor = all(inside) ? bilinear : (matchedWeight > 1e-3 ? matched / matchedWeight : nearest);
#endif
}
