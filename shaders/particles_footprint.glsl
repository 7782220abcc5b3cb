// The bilinear footprint of the view's pixel `pixel` (particles_scene_depth.glsl's viewPixelOf) in a
// lower-resolution image, for the composites that upsample one (fs_particles_composite.glsl,
// fs_mega_composite.glsl): `base` is the footprint's
// first texel, `f` how far the pixel lies from it toward the next one in x and y, and `last` the
// image's last texel (the composites clamp their taps to it).
void lowResFootprint(vec2 pixel, ivec2 fullSize, ivec2 lowSize, out ivec2 base, out vec2 f, out ivec2 last) {
    vec2 lowPos = pixel * vec2(lowSize) / vec2(fullSize) - 0.5;
    base = ivec2(floor(lowPos));
    f = lowPos - vec2(base);
    last = lowSize - 1;
}

// The footprint of this fragment's view pixel (returned; drawn into sceneColor, the fragment
// lies in the view's rectangle of it) in a lower-resolution image of `lowSize` texels.
vec2 fragmentFootprint(ivec2 lowSize, out ivec2 base, out vec2 f, out ivec2 last) {
    vec2 pixel = viewPixelOf(gl_FragCoord.xy);
    lowResFootprint(pixel, sceneDepthViewSize(), lowSize, base, f, last);
    return pixel;
}
