#version 330 core
// Quarter-res z-buffer: per half-res texel, the FARTHEST scene depth of its 2x2 full-res block,
// as the host's reversed-Z window depth. The half-res particles then z-test against it (GEQUAL):
// a fragment behind the farthest of the four pixels is behind all of them, and since the half-res
// fade uses the nearest of the four (particles_half_depth) it would have shaded to nothing, so
// rejecting it changes no pixel. Where nothing was drawn the depth is the far plane (0).
uniform sampler2D uSceneDepth;  // full resolution, R32F metres
uniform vec2 uDepthFromLinear;  // window z = x / depth + y (the view's reversed-Z projection)
uniform float uFar;

float sceneDepth(ivec2 p) {
    float d = texelFetch(uSceneDepth, p, 0).r;
    return d > 0.0 ? d : 3.0e38;  // <= 0: nothing drawn (fx/HostAdapter.h)
}

void main() {
    ivec2 last = textureSize(uSceneDepth, 0) - 1;
    ivec2 p = min(ivec2(gl_FragCoord.xy) * 2, last);
    ivec2 q = min(p + 1, last);
    float d = max(max(sceneDepth(p), sceneDepth(ivec2(q.x, p.y))), max(sceneDepth(ivec2(p.x, q.y)), sceneDepth(q)));
    // A hair farther (1e-5 relative), so float rounding between this and the rasteriser's depth
    // of a particle exactly at the surface never rejects a fragment that shades to something.
    gl_FragDepth = d >= uFar ? 0.0 : clamp(uDepthFromLinear.x / (d * 1.00001) + uDepthFromLinear.y, 0.0, 1.0);
}
