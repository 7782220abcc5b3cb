#version 330 core
// Mega-particles, depth downsample: the scene's linear depth at the spheres target's size, each
// texel the MINIMUM (nearest) of the full-resolution texels it covers (up to 5 x 5 at the
// smallest mega.resolution, 0.25). Nearest is the conservative choice (as in
// fs_particles_depth_downsample.glsl): thin foreground geometry survives, so no sphere is drawn
// where any covered pixel holds nearer geometry; the blur fills such texels from their
// neighbours and the composite decides per full-resolution pixel.
#include "particles_scene_depth.glsl"
uniform sampler2D uSceneDepth;  // full resolution: the z-buffer or linear R32F (particles_scene_depth.glsl)

layout(location = 0) out vec4 oDepth;

uniform vec2 uRatio;  // full-resolution texels per target texel, per axis (>= 1)

float sceneDepth(ivec2 p) {
    return linearSceneDepth(texelFetch(uSceneDepth, sceneDepthTexel(p), 0).r);  // nothing drawn: 3.0e38
}

void main() {
    ivec2 last = sceneDepthViewSize() - 1;  // the view's pixels, wherever it lies in the texture
    vec2 cell = floor(gl_FragCoord.xy);
    ivec2 lo = min(ivec2(floor(cell * uRatio)), last);
    ivec2 hi = clamp(ivec2(ceil((cell + 1.0) * uRatio)) - 1, lo, last);
    float d = 3.0e38;
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 5; ++x) {
            ivec2 p = lo + ivec2(x, y);
            if (p.x <= hi.x && p.y <= hi.y) d = min(d, sceneDepth(p));
        }
    }
    oDepth = vec4(d);
}
