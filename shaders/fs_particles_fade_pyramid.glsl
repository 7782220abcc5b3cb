#version 330 core
// The fade pyramid (FadePyramid.h): the scene's nearest linear depth over square blocks of the
// view, 4 x 4 pixels at level 0 and twice as wide a level up, so a soft billboard's vertices can
// tell which parts of it have no geometry within its softness (vs_particles.glsl, FX_FADE_MASK)
// and those fragments skip the scene-depth fetch.
// FX_FADE_PYRAMID_FIRST: level 0 from the scene depth (particles_scene_depth.glsl), decoded as
// linearSceneDepth does (3.0e38 where nothing was drawn). Its texel c covers the view's pixels
// 4c .. 4c + 3. Past the view's last row or column the reads go on into the texels beyond it
// (another view's, or the texture's clamped edge): a minimum over more pixels is never larger,
// so the level stays a lower bound of every pixel it covers.
// Otherwise: level L from level L - 1 (the texture's only level in sampling range while level L
// is drawn: FadePyramid::build), the minimum of the 2 x 2 texels below, clamped to its size.
layout(location = 0) out vec4 oMin;

#ifdef FX_FADE_PYRAMID_FIRST
#include "particles_scene_depth.glsl"
uniform sampler2D uSceneDepth;  // through the nearest sampler (texelFetch and gather ignore it)
uniform vec2 uInvDepthSize;     // 1 / the depth texture's size

void main() {
    // The block's first pixel, and its texel in the depth texture.
    ivec2 first = sceneDepthTexel(ivec2(gl_FragCoord.xy) * 4);
    float m = 3.0e38;
#ifdef FX_GATHER
    // Four gathers, each at the corner its 2 x 2 texels share.
    for (int y = 1; y <= 3; y += 2) {
        for (int x = 1; x <= 3; x += 2) {
            vec4 d = textureGather(uSceneDepth, (vec2(first + ivec2(x, y))) * uInvDepthSize);
            m = min(m, min(min(linearSceneDepth(d.x), linearSceneDepth(d.y)),
                           min(linearSceneDepth(d.z), linearSceneDepth(d.w))));
        }
    }
#else
    ivec2 last = textureSize(uSceneDepth, 0) - 1;
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            m = min(m, linearSceneDepth(texelFetch(uSceneDepth, min(first + ivec2(x, y), last), 0).r));
        }
    }
#endif
    oMin = vec4(m, 0.0, 0.0, 0.0);
}
#else
uniform sampler2D uBelow;  // level L - 1, the base and only level in range

void main() {
    ivec2 last = textureSize(uBelow, 0) - 1;
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    ivec2 q = min(p + 1, last);
    float m = min(min(texelFetch(uBelow, p, 0).r, texelFetch(uBelow, ivec2(q.x, p.y), 0).r),
                  min(texelFetch(uBelow, ivec2(p.x, q.y), 0).r, texelFetch(uBelow, q, 0).r));
    oMin = vec4(m, 0.0, 0.0, 0.0);
}
#endif
