#version 330 core
// Quarter-res z-buffer: per half-res texel, the FARTHEST scene depth of its 2x2 full-res block,
// as the host's reversed-Z window depth. The half-res particles then z-test against it (GEQUAL):
// a fragment behind the farthest of the four pixels is behind all of them, and since the half-res
// fade uses the nearest of the four (particles_half_depth) it would have shaded to nothing, so
// rejecting it changes no pixel. Where nothing was drawn the depth is the far plane (0).
// The farthest depth is the downsample's green channel (fs_particles_depth_downsample.glsl): one
// fetch of the half-res texel instead of four of the scene depth.
uniform sampler2D uHalfDepth;   // RG32F (min, max) metres per 2x2 block, same size as this target
uniform vec2 uDepthFromLinear;  // window z = x / depth + y (the view's reversed-Z projection)
uniform float uFar;

void main() {
    float d = texelFetch(uHalfDepth, ivec2(gl_FragCoord.xy), 0).g;
    // A hair farther (1e-5 relative), so float rounding between this and the rasteriser's depth
    // of a particle exactly at the surface never rejects a fragment that shades to something.
    gl_FragDepth = d >= uFar ? 0.0 : clamp(uDepthFromLinear.x / (d * 1.00001) + uDepthFromLinear.y, 0.0, 1.0);
}
