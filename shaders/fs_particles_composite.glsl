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
// versa, and along an edge the result stays as smooth as bilinear. uBilinear = 1 keeps plain
// bilinear (for comparison).
//
// Mixed resolution (uMixed = 1, QuarterResPath.h): the edge pixels (particles_mixed_edge.glsl,
// the same threshold test) take the full-res redraw from uEdgeColor instead of any upsample;
// every other pixel gets plain bilinear, which is what the depth-aware branch gives it too.
uniform sampler2D uHalfColor;   // premultiplied RGBA16F, half x half
uniform sampler2D uHalfDepth;   // R32F min depth per 2x2 block
uniform sampler2D uSceneDepth;  // full-res R32F
uniform int uBilinear;
uniform float uDepthThreshold;  // relative: |low - full| > threshold * full is an edge
uniform int uMixed;
uniform sampler2D uEdgeColor;   // mixed: premultiplied RGBA16F, full size, the edge pixels' redraw

#include "particles_mixed_edge.glsl"

layout(location = 0) out vec4 oColor;

void main() {
    ivec2 fullSize = textureSize(uSceneDepth, 0);
    ivec2 lowSize = textureSize(uHalfColor, 0);
    vec2 lowPos = gl_FragCoord.xy * vec2(lowSize) / vec2(fullSize) - 0.5;
    ivec2 base = ivec2(floor(lowPos));
    vec2 f = lowPos - vec2(base);
    ivec2 last = lowSize - 1;
    ivec2 taps[4] = ivec2[4](clamp(base, ivec2(0), last), clamp(base + ivec2(1, 0), ivec2(0), last),
                             clamp(base + ivec2(0, 1), ivec2(0), last), clamp(base + ivec2(1, 1), ivec2(0), last));
    float weights[4] = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);

    // (No early discard of smoke-free footprints: measured on llvmpipe it made the composite
    // slower, a CPU rasteriser evaluating the rest anyway; the scissor to the particles' bound
    // is what keeps smoke-free screen areas out.)
    vec4 colour[4];
    vec4 bilinear = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        colour[i] = texelFetch(uHalfColor, taps[i], 0);
        bilinear += weights[i] * colour[i];
    }
    if (uBilinear != 0) {
        oColor = bilinear;
        return;
    }
    if (uMixed != 0) {
        ivec2 edgeTaps[4];
        float edgeWeights[4];
        particlesFootprint(gl_FragCoord.xy, fullSize, textureSize(uHalfDepth, 0), edgeTaps, edgeWeights);
        float pixelDepth = particlesFullDepth(uSceneDepth, gl_FragCoord.xy);
        oColor = particlesIsEdge(uHalfDepth, edgeTaps, pixelDepth, uDepthThreshold)
                     ? texelFetch(uEdgeColor, ivec2(gl_FragCoord.xy), 0)
                     : bilinear;
        return;
    }

    // On an edge, keep the bilinear weights of the texels on this pixel's side of it (depth
    // within the threshold), renormalised; only when none is, the single nearest-depth texel.
    float full = texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r;
    if (full <= 0.0) full = 3.0e38;  // nothing drawn (fx/HostAdapter.h), as in the downsample
    float limit = uDepthThreshold * full;
    float best = 3.4e38;
    int nearest = 0;
    vec4 matched = vec4(0.0);
    float matchedWeight = 0.0;
    bool edge = false;
    for (int i = 0; i < 4; ++i) {
        float diff = abs(texelFetch(uHalfDepth, taps[i], 0).r - full);
        if (diff <= limit) {
            matched += weights[i] * colour[i];
            matchedWeight += weights[i];
        } else {
            edge = true;
        }
        if (diff < best) {
            best = diff;
            nearest = i;
        }
    }
    if (!edge) {
        oColor = bilinear;
    } else if (matchedWeight > 1e-3) {
        oColor = matched / matchedWeight;
    } else {
        oColor = colour[nearest];
    }
}
