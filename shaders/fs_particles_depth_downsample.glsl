#version 330 core
// Quarter-res step 1: the half-resolution linear depth (metres), one texel per 2x2 block of the
// scene depth: red the MINIMUM (nearest) depth of the block, green its MAXIMUM (farthest, for the
// half-res z-fill, fs_particles_half_z.glsl). Nearest keeps thin foreground geometry (poles,
// barrier tops, a car's roof line) in the low-res depth, so particles behind it are hidden in
// the half-res pass too; the composite then lets background pixels next to it
// borrow a neighbouring low-res texel (see QuarterResPath.h for the choice and its measured effect).
// The block is one textureGather (FX_GATHER, where the context has ARB_texture_gather; else four
// texelFetch), taken at the corner its four texels share, through the renderer's nearest,
// edge-clamped sampler.
#include "particles_scene_depth.glsl"
uniform sampler2D uSceneDepth;  // full resolution: the z-buffer or linear R32F (particles_scene_depth.glsl)
// FX_GATHER: the block's corner as a texture coordinate, a line in gl_FragCoord set once per draw
// (QuarterResPath::downsampleDepth): the half-res texel i (gl_FragCoord i + 0.5) covers view pixels
// 2i and 2i + 1, whose shared corner is 2 gl_FragCoord in view pixels, plus the view's texel
// origin (uDepthWindow.xy), over the texture's size. No size query, conversion or division.
uniform vec4 uCornerUv;         // corner = gl_FragCoord.xy * xy + zw
uniform vec2 uViewSize;         // the view's full-res size (vs_particles_tiles.glsl's)

layout(location = 0) out vec4 oDepth;

// Nothing drawn reads as infinitely far (3.0e38).
float sceneDepth(ivec2 p) {
    return linearSceneDepth(texelFetch(uSceneDepth, sceneDepthTexel(p), 0).r);
}

void main() {
#ifdef FX_GATHER
    // (2i, 2i + x, 2i + y, 2i + x + y). Past the view's last row or column (an odd size n: the
    // last texel, where 2 gl_FragCoord = 2i + 1 >= n) the gather reads the texel beyond it, which
    // may be another view's: the clamped texel is 2i's own.
    vec4 g = textureGather(uSceneDepth, gl_FragCoord.xy * uCornerUv.xy + uCornerUv.zw).wzxy;
    if (2.0 * gl_FragCoord.x >= uViewSize.x) g.yw = g.xz;
    if (2.0 * gl_FragCoord.y >= uViewSize.y) g.zw = g.xy;
    float a = linearSceneDepth(g.x), b = linearSceneDepth(g.y);
    float c = linearSceneDepth(g.z), d = linearSceneDepth(g.w);
#else
    ivec2 fullSize = sceneDepthViewSize();  // the view's pixels, wherever it lies in the texture
    ivec2 last = fullSize - 1;
    // Texel i covers full-res pixels 2i and 2i + 1 (an odd last row/column is clamped).
    ivec2 p = min(ivec2(gl_FragCoord.xy) * 2, last);
    ivec2 q = min(p + 1, last);
    float a = sceneDepth(p), b = sceneDepth(ivec2(q.x, p.y));
    float c = sceneDepth(ivec2(p.x, q.y)), d = sceneDepth(q);
#endif
    oDepth = vec4(min(min(a, b), min(c, d)), max(max(a, b), max(c, d)), 0.0, 0.0);
}
