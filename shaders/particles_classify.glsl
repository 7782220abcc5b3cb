// Fade classification, included after particles_common.glsl by vs_particles.glsl
// (FX_CLASSIFY) and vs_particles_count.glsl. From the scene depth's range per screen tile
// (fs_particles_tile_depth.glsl: min and max linear depth per 16 px tile, and per 64 px tile) a
// particle is put in one of three classes:
//   kFadeNeeded: its footprint meets geometry within its softness: the fragment shader fetches the
//                scene depth and evaluates the fade, as without classification;
//   kInFront:    every pixel of the scene in its footprint lies farther than the particle's far
//                side plus its softness: the fade is exactly 1 there (the clamp saturates), so the
//                fragment shader skips the depth fetch and the fade math;
//   kHidden:     every pixel of the scene in its footprint lies nearer than the particle's near
//                side: the fade (or the sphere's visible chord) is exactly 0, so every fragment
//                would blend to nothing; the particle is not rasterised at all.
// Both shortcuts are taken only with a margin (relative 1e-5 of the depth plus 1e-3 of the
// softness) beyond where the clamp saturates, so float rounding cannot tell the classified image
// from the unclassified one: they are equal bit for bit.
// A footprint wider than 4 x 4 coarse tiles, or a particle reaching the near plane, stays
// kFadeNeeded (a vertex reads at most 16 tile texels).

uniform sampler2D uTiles;        // RG32F: (min, max) scene depth per kTileSize px tile, metres
uniform sampler2D uTilesCoarse;  // the same per kCoarseTileSize px tile
uniform vec2 uViewSize;          // the scene depth's size in pixels (the tiles' source)

const int kFadeNeeded = 0;
const int kInFront = 1;
const int kHidden = 2;
const float kTileSize = 16.0;       // keep equal to FadeClassifier::kTileSize
const float kCoarseTileSize = 64.0; // keep equal to FadeClassifier::kCoarseTileSize

// Pixel rectangle (min xy, max xy) of the view-space point `p`'s projection, merged into `rect`.
vec4 addProjected(vec4 rect, vec3 p) {
    vec4 clip = uProj * vec4(p, 1.0);
    vec2 px = (clip.xy / clip.w * 0.5 + 0.5) * uViewSize;
    return vec4(min(rect.xy, px), max(rect.zw, px));
}

// (min, max) scene depth over the tiles of `tiles` (size `tileSize`) that cover the pixel
// rectangle `rect`; x < 0 when the rectangle spans more than 4 x 4 of them.
vec2 tileDepthRange(sampler2D tiles, float tileSize, vec4 rect) {
    ivec2 size = textureSize(tiles, 0);
    ivec2 lo = clamp(ivec2(floor(rect.xy / tileSize)), ivec2(0), size - 1);
    ivec2 hi = clamp(ivec2(floor(rect.zw / tileSize)), ivec2(0), size - 1);
    if (hi.x - lo.x >= 4 || hi.y - lo.y >= 4) return vec2(-1.0);
    vec2 range = vec2(3.0e38, 0.0);
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            vec2 t = texelFetch(tiles, ivec2(x, y), 0).rg;
            range = vec2(min(range.x, t.x), max(range.y, t.y));
        }
    }
    return range;
}

// The class of a particle centred at view-space `centre` with radius `radius`. Billboards
// (sphere false) lie in the view plane at the centre's depth, their corners within
// radius * sqrt(2) of the centre (any rotation, quad or trimmed polygon); spheres span
// depth +-radius and are bounded by their cube. `softScale`: 1 / softness (billboards only).
int fadeClass(vec3 centre, float radius, bool sphere, float softScale) {
    float depth = -centre.z;
    float reach = sphere ? radius : radius * 1.4143;  // sqrt(2), rounded up
    float nearSide = sphere ? depth - radius : depth;
    float farSide = sphere ? depth + radius : depth;
    if (!(nearSide > uNear * 1.01) || !(radius > 0.0)) return kFadeNeeded;
    vec4 rect = vec4(3.0e38, 3.0e38, -3.0e38, -3.0e38);
    for (int i = 0; i < 8; ++i) {
        vec3 corner = vec3((i & 1) != 0 ? reach : -reach, (i & 2) != 0 ? reach : -reach,
                           sphere && (i & 4) != 0 ? radius : (sphere ? -radius : 0.0));
        rect = addProjected(rect, centre + corner);
    }
    // One pixel more each side: rasterisation touches the pixels whose centres the edge passes.
    rect += vec4(-1.0, -1.0, 1.0, 1.0);
    if (rect.z < 0.0 || rect.w < 0.0 || rect.x > uViewSize.x || rect.y > uViewSize.y) return kFadeNeeded;
    vec2 range = tileDepthRange(uTiles, kTileSize, rect);
    if (range.x < 0.0) range = tileDepthRange(uTilesCoarse, kCoarseTileSize, rect);
    if (range.x < 0.0) return kFadeNeeded;
    float slack = 1e-5 * farSide;
    float softness = sphere ? 0.0 : 1.0 / max(softScale, 1e-30);
    if (range.x >= farSide + softness * 1.001 + slack) return kInFront;
    if (range.y <= nearSide - slack) return kHidden;
    return kFadeNeeded;
}
