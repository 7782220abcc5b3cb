// Mixed-resolution particles (QuarterResPath.h): which full-res pixels are *edge* pixels, those
// whose low-res bilinear footprint straddles a depth discontinuity. The edge mask pass
// (fs_particles_edge_mask.glsl) and the composite both include this, so the pixels the mask lets
// the full-res redraw touch are exactly the pixels the composite takes that redraw from.
//
// Needs uHalfDepth (red: min depth per 2x2 block) and uSceneDepth (full-res scene depth, read
// through particles_scene_depth.glsl).
#include "particles_scene_depth.glsl"

// The four low-res texels of the bilinear footprint of the view's full-res pixel `pixel`, and
// their bilinear weights (as the composite's own upsample computes them).
void particlesFootprint(vec2 pixel, ivec2 fullSize, ivec2 lowSize, out ivec2 taps[4], out float weights[4]) {
    vec2 lowPos = pixel * vec2(lowSize) / vec2(fullSize) - 0.5;
    ivec2 base = ivec2(floor(lowPos));
    vec2 f = lowPos - vec2(base);
    ivec2 last = lowSize - 1;
    taps[0] = clamp(base, ivec2(0), last);
    taps[1] = clamp(base + ivec2(1, 0), ivec2(0), last);
    taps[2] = clamp(base + ivec2(0, 1), ivec2(0), last);
    taps[3] = clamp(base + ivec2(1, 1), ivec2(0), last);
    weights[0] = (1.0 - f.x) * (1.0 - f.y);
    weights[1] = f.x * (1.0 - f.y);
    weights[2] = (1.0 - f.x) * f.y;
    weights[3] = f.x * f.y;
}

// The view's pixel's full-res linear depth; "nothing drawn" reads as far away (3.0e38), as in the
// downsample.
float particlesFullDepth(sampler2D sceneDepth, vec2 pixel) {
    return linearSceneDepth(texelFetch(sceneDepth, sceneDepthTexel(ivec2(pixel)), 0).r);
}

// True when some footprint texel's depth differs from `full` by more than threshold * full.
bool particlesIsEdge(sampler2D halfDepth, ivec2 taps[4], float full, float threshold) {
    float limit = threshold * full;
    bool edge = false;
    for (int i = 0; i < 4; ++i) {
        if (abs(texelFetch(halfDepth, taps[i], 0).r - full) > limit) edge = true;
    }
    return edge;
}
