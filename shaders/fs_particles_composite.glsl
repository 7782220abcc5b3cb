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
//
// Fetches per pixel, the sampler's bilinear filter doing the weighting (uHalfColor is sampled
// LINEAR, clamped to its edge, which is what clamping the taps to the last texel did):
//   - no smoke in the footprint: 1, the bilinear colour; the pixel is discarded.
//   - smoke, no depth edge: 3, the bilinear colour, the pixel's depth, the four low-res depths in
//     one textureGather (FX_GATHER: ProgramCache defines it where the context has
//     ARB_texture_gather; else four texelFetch).
//   - smoke, where the gathered farthest depths (FX_GATHER_FARTHEST, ARB_gpu_shader5) show no
//     edge: 3, the bilinear colour and two gathers of the half-res depth (nearest and farthest),
//     and no read of the full-resolution depth; elsewhere 1 more, then the cases below.
//   - a depth edge: 5. The kept texels' weights are split by row: a row's kept texels are none,
//     one or both, and one bilinear fetch at that row's centre line, its x moved to the kept
//     texels' weighted centre, returns exactly their renormalised blend.
// (The rows are fetched only on an edge; a CPU rasteriser runs both sides of a branch, so it pays
// 5 everywhere there is smoke, still fewer than the 9 texelFetch this took before.)
uniform sampler2D uHalfColor;   // premultiplied RGBA8 (RGBA16F with spheres), half x half
uniform sampler2D uHalfDepth;   // red: min depth per 2x2 block (RG32F, green the max)
uniform sampler2D uSceneDepth;  // full-res scene depth (particles_scene_depth.glsl)
uniform float uDepthThreshold;  // relative: |low - full| > threshold * full is an edge
// The footprint as a line in gl_FragCoord, worked out once per draw (QuarterResPath::composite),
// so a fragment pays two multiply-adds for it and no size query, conversion or division:
// uLowMap maps the view pixel p = gl_FragCoord - uDrawOrigin into the half-res image,
// lowPos = p lowSize / viewSize - 0.5, in texels past the first tap's centre (the tap
// floor(lowPos), the weights lowPos - floor(lowPos)). Its bilinear coordinate is
// (lowPos + 0.5) / lowSize.
// (Folding that into a second line saves two operations, but on llvmpipe, whose filter takes
// the coordinate rounded differently, the composite pass then took 12 % longer, same pixels.)
uniform vec4 uLowMap;           // lowPos = gl_FragCoord.xy * xy + zw
uniform vec2 uInvLow;           // 1 / lowSize
uniform vec4 uDepthUv;          // the scene depth texel's coordinate = gl_FragCoord.xy * zw + xy (SceneDepthSource.cpp)
#include "particles_scene_depth.glsl"

layout(location = 0) out vec4 oColor;

void main() {
    // The bilinear colour of the footprint.
    vec2 lowPos = gl_FragCoord.xy * uLowMap.xy + uLowMap.zw;
    vec4 bilinear = textureLod(uHalfColor, (lowPos + 0.5) * uInvLow, 0.0);
    // No smoke in the footprint (premultiplied, so additive smoke with alpha 0 still counts; every
    // channel is >= 0 and every weight > 0, so the blend is 0 exactly when all four texels are):
    // blending it would leave the pixel as it is, so it is not blended at all. Inside the tiles
    // many pixels are smoke-free; a GPU then skips the other fetches and the blend's
    // read-modify-write there.
    if (all(equal(bilinear, vec4(0.0)))) discard;

#if defined(FX_COMPOSITE_BILINEAR)
    oColor = bilinear;
#else
#if defined(FX_GATHER_FARTHEST)
    // No edge in the footprint, told from the half-res depth alone: this pixel's own 2x2 block is
    // one of the four taps, so its full-res depth lies between their nearest and farthest; where
    // those are within the threshold of the nearest, every tap is within it of this pixel's depth
    // (|low - full| <= farthest - nearest <= threshold * nearest <= threshold * full), which is the
    // test below, passed. Then the bilinear colour, with no read of the full-resolution depth: a
    // GPU fetches it only for pixels near a depth edge. (0.9999: the two shaders decode the same
    // depths, but a compiler may round them apart by an ulp; those pixels take the test below.)
    vec2 corner = (floor(lowPos) + 1.0) * uInvLow;
    vec4 nearest4 = textureGather(uHalfDepth, corner, 0), farthest4 = textureGather(uHalfDepth, corner, 1);
    float nearest = min(min(nearest4.x, nearest4.y), min(nearest4.z, nearest4.w));
    float farthest = max(max(farthest4.x, farthest4.y), max(farthest4.z, farthest4.w));
    if (farthest - nearest <= 0.9999 * uDepthThreshold * nearest) {
        oColor = bilinear;
        return;
    }
#endif
    // This pixel's depth texel, read at its centre through the nearest sampler (the texel
    // texelFetch reads, which a CPU rasteriser bounds-checks lane by lane); nothing drawn: 3.0e38.
    float full = linearSceneDepth(textureLod(uSceneDepth, gl_FragCoord.xy * uDepthUv.zw + uDepthUv.xy, 0.0).r);
    float limit = uDepthThreshold * full;
    // The footprint's first tap (base) and how far past it the pixel lies (f), in texels.
    vec2 base = floor(lowPos);
    // Depths of the taps t0 = base, t1 = base + (1, 0), t2 = base + (0, 1), t3 = base + (1, 1),
    // each clamped into the image. Gathered at the corner the four share: the footprint cannot
    // round to a neighbouring one there, and clamping to the edge clamps the taps.
#ifdef FX_GATHER
    vec4 low = textureGather(uHalfDepth, (base + 1.0) * uInvLow).wzxy;
#else
    ivec2 last = textureSize(uHalfColor, 0) - 1;
    ivec2 t0 = clamp(ivec2(base), ivec2(0), last), t3 = clamp(ivec2(base) + ivec2(1), ivec2(0), last);
    vec4 low = vec4(texelFetch(uHalfDepth, t0, 0).r, texelFetch(uHalfDepth, ivec2(t3.x, t0.y), 0).r,
                    texelFetch(uHalfDepth, ivec2(t0.x, t3.y), 0).r, texelFetch(uHalfDepth, t3, 0).r);
#endif
    vec4 diff = abs(low - full);
    bvec4 inside = lessThanEqual(diff, vec4(limit));
    if (all(inside)) {
        oColor = bilinear;
        return;
    }
    // On an edge, keep the bilinear weights of the texels on this pixel's side of it,
    // renormalised; only when none is, the single nearest-depth texel (the first of equal ones).
    vec2 f = lowPos - base;
    vec4 w = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    vec4 kept = mix(vec4(0.0), w, inside);
    if (kept.x + kept.y + kept.z + kept.w <= 1e-3) {
        float best = min(min(diff.x, diff.y), min(diff.z, diff.w));
        int first = diff.x == best ? 0 : (diff.y == best ? 1 : (diff.z == best ? 2 : 3));
        kept = vec4(equal(ivec4(0, 1, 2, 3), ivec4(first)));
    }
    // Per row, its kept weight and the x (in texels past the first tap's centre) of its kept
    // texels' weighted centre; a row that keeps none is fetched anyway, at weight 0.
    vec2 rowWeight = vec2(kept.x + kept.y, kept.z + kept.w);
    vec2 rowX = vec2(rowWeight.x > 0.0 ? kept.y / rowWeight.x : 0.0, rowWeight.y > 0.0 ? kept.w / rowWeight.y : 0.0);
    vec4 row0 = textureLod(uHalfColor, (base + vec2(0.5 + rowX.x, 0.5)) * uInvLow, 0.0);
    vec4 row1 = textureLod(uHalfColor, (base + vec2(0.5 + rowX.y, 1.5)) * uInvLow, 0.0);
    oColor = (rowWeight.x * row0 + rowWeight.y * row1) / (rowWeight.x + rowWeight.y);
#endif
}
