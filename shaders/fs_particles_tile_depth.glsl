#version 330 core
// Fade classification, step 1 (particles_classify.glsl): the scene depth's range per tile.
// Default: one texel per kTileSize x kTileSize pixels of the linear scene depth, (min, max).
// FX_TILE_COARSE: one texel per 4 x 4 of those (kCoarseTileSize pixels), from the fine tiles.
// Pixels where nothing was drawn count as infinitely far (particles_scene_depth.glsl).
uniform sampler2D uSource;  // the scene depth (z-buffer or linear R32F), or the RG32F fine tiles
#ifndef FX_TILE_COARSE
#include "particles_scene_depth.glsl"
#endif

layout(location = 0) out vec4 oRange;

#ifdef FX_TILE_COARSE
const int kSpan = 4;
#else
const int kSpan = 16;  // FadeClassifier::kTileSize
#endif

void main() {
#ifdef FX_TILE_COARSE
    ivec2 last = textureSize(uSource, 0) - 1;
    ivec2 origin = ivec2(0);
#else
    ivec2 last = sceneDepthViewSize() - 1;  // the view's pixels, wherever it lies in the texture
    ivec2 origin = sceneDepthTexel(ivec2(0));
#endif
    ivec2 first = ivec2(gl_FragCoord.xy) * kSpan;
    vec2 range = vec2(3.0e38, 0.0);
    for (int y = 0; y < kSpan; ++y) {
        for (int x = 0; x < kSpan; ++x) {
            ivec2 p = min(first + ivec2(x, y), last) + origin;
#ifdef FX_TILE_COARSE
            vec2 t = texelFetch(uSource, p, 0).rg;
#else
            vec2 t = vec2(linearSceneDepth(texelFetch(uSource, p, 0).r));
#endif
            range = vec2(min(range.x, t.x), max(range.y, t.y));
        }
    }
    oRange = vec4(range, 0.0, 1.0);
}
