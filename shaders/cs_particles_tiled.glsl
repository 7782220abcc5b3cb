#version 430 core
// Tiled particles (fx_plugin/render/TiledPath.h): hard and soft billboards and spheres shaded by
// compute shaders in two dispatches.
//   FX_TILED_SETUP: one invocation per particle works out what the vertex shader does per vertex
//     (the particle's map from pixels to its texture, its tint, fog, fade line, level of detail)
//     into six vec4 of uRecords, once however many tiles the particle touches.
//   Otherwise: one work group per 16 x 16 pixel tile of the view, one invocation per pixel. The
//     CPU bounded and counted, and the GPU listed, every particle in the tiles its bound touches,
//     front to back (TileBins.h, TileSort.h); each
//     invocation walks its tile's list, reading each particle's record (the same address across
//     the group: one cached read for all), and evaluates it for its pixel in registers. No shared
//     memory and no barrier.
//   - The scene depth is fetched once per pixel, not once per particle fragment: the fetch that
//     bounds soft's and spherical's raster passes on the GPUs we measured is paid by the pixels,
//     not the overdraw.
//   - The blend is done in registers, front to back (premultiplied "under": what the raster path's
//     (ONE, ONE_MINUS_SRC_ALPHA) and additive (ONE, ONE) blends give back to front, with the
//     additive particles' alpha 0), and stops once the pixel is opaque to 1/2048: no fixed-function
//     blend per fragment, one write per pixel.
// The result, premultiplied colour and 1 - transmittance, goes to uAccum; a draw over the covered
// tiles blends it onto sceneColor with (ONE, ONE_MINUS_SRC_ALPHA) (fs_particles_tiled_composite).
//
// Per particle it is the raster path's own program (vs_particles.glsl with fs_particles_hard, _soft
// or _spherical), lit (FX_LIT: the TiledSetupLit and TiledShadeLit builds) or not:
//   - A billboard lies at one view depth, so its texture coordinate is an affine map of the pixel
//     (worked out per particle below), its level of detail one value, its tint, fog and near fade
//     the particle's own. Hard particles are cut where the scene lies in front of them, compared in
//     linear depth (the raster path's z-test compares window depths: the two differ only where the
//     depths are equal to rounding). Soft particles fade as softFade does (pow() for any contrast
//     power).
//   - A sphere (perspective views only: TiledPath::canDraw) is intersected with the pixel's ray as
//     fs_particles_spherical does; its atlas level of detail is one value per sphere, that of its
//     centre (the raster path's varies a little over the disc).
//   - Lit smoke (FX_LIT, batches whose reaction takes the scene light): the light that the raster
//     path's vertex shader works out per vertex (the sun through the opacity map, the phase) is
//     worked out once per particle in the setup, at a sphere's centre (as the raster path does) and
//     at the vertices of the fan the raster path draws a billboard with (its frame's trimmed
//     polygon, or the quad), and read per pixel across that fan's triangles as the rasteriser
//     interpolates it: the light of a large puff depends on where its vertices lie. The per-pixel
//     light (the atlas normal, the diffuse and scattered shares) is the raster fragment shaders',
//     with each batch's values from uniform arrays.
// The atlas is read from one mip level, the nearest, as ParticleDraw's sampler does.
#include "particles_common.glsl"

// Two vec4 per particle: InstanceStream's ParticleInstance (x, y, z, size), (life, rotation,
// fade, frame).
layout(std430, binding = 0) readonly buffer Instances { vec4 uInstances[]; };
// Each tile's particles, front to back: instance index | batch << 26.
layout(std430, binding = 1) readonly buffer Entries { uint uEntries[]; };
// The tiles with particles: (tile x, tile y, first entry, entry count).
layout(std430, binding = 2) readonly buffer Tiles { uvec4 uTiles[]; };
// Six vec4 per particle, by instance index. Billboards: [0] the local map (local = [0].xy px +
// [0].zw py + [1].xy, p the pixel centre), [1].zw the atlas cell, [2] soft: (softFadeLine,
// contrast power), hard: (0, 0, 0, depth). Spheres: [0] = (view centre, radius squared), [1] =
// (atlas base, near fade map), [2] = the atlas map (sphereAtlasMap). Both: [3] particleTint's
// tint, [4] (fogAdd, atlas level of detail), [5].x the kind (0 hard, 1 soft, 2 sphere).
// [5].y: 1 where the particle is lit (FX_LIT), else 0.
layout(std430, binding = 3) buffer Records { vec4 uRecords[]; };
#ifdef FX_LIT
// Lit particles' light, kLightStride vec4 per particle by instance index. Billboards: [0] - [7]
// (sun light rgb, phase) at the vertices of the fan the raster path draws it with (fanVertex: the
// frame's trimmed polygon, or the quad's corners), [8] = (cos, sin of its angle, normal strength,
// the fan: its vertex count + 16 x (its polygon in uShapes + 1), 0 for the quad). Spheres: [0] at
// the centre, [8] = (cos, sin) x 0.6 normal strength x radius (the bumps' scale, as
// vs_particles.glsl's vTurn), 0, 0.
layout(std430, binding = 4) buffer Light { vec4 uLight[]; };
const uint kLightStride = 9u;
// The billboards' trimmed polygons (TrimmedShapes::packed(), vs_particles.glsl's uShapes):
// [frame][bucket][vertex] (x, y) in the particle's texture space, two vertices per vec4.
layout(std430, binding = 5) readonly buffer Shapes { vec4 uShapes[]; };
const int kShapeVertices = 8;  // TrimmedShapes::kMaxVertices

// Vertex i of a billboard's fan as the raster path draws it (a GL_TRIANGLE_FAN, convex and
// counter-clockwise). polygon >= 0: the trimmed polygon's, in texture space (padded by repeating
// its last vertex). polygon < 0: the quad's corners (1, -1), (1, 1), (-1, 1), (-1, -1) in its
// (right, up) frame, whose triangles are those of the strip (0, 1, 2), (1, 2, 3) vs_particles.glsl
// draws with the corners (-1, -1), (1, -1), (-1, 1), (1, 1).
vec2 fanVertex(int polygon, int i) {
    if (polygon < 0) {
        int k = min(i, 3);
        return vec2(k < 2 ? 1.0 : -1.0, k == 0 || k == 3 ? -1.0 : 1.0);
    }
    int index = polygon * kShapeVertices + i;
    vec4 pair = uShapes[index / 2];
    return (index % 2) == 0 ? pair.xy : pair.zw;
}
#endif

const int kMaxBatches = 32;         // TiledPath::kMaxBatches
const uint kBatchShift = 26u;
const float kOpaque = 1.0 - 1.0 / 2048.0;
uniform vec4 uPixelToNdc;           // ndc = (view pixel + 0.5) * xy + zw
uniform int uGroupsX;               // groups per row of the dispatch (a row holds at most 65,535)

#ifdef FX_TILED_SETUP
layout(local_size_x = 64) in;
uniform vec4 uBatchA[kMaxBatches];  // ramp row v, blend mode, soft scale, contrast power
uniform vec4 uBatchB[kMaxBatches];  // the batch's uNearFadeMap (x, y), kind (0 hard, 1 soft, 2 sphere), 0
uniform ivec2 uBatchRange[kMaxBatches];  // first instance, count
uniform int uBatchCount;
uniform int uInstanceCount;
uniform float uAtlasTexels;         // the atlas's level-0 width (square)
uniform float uPixelSlope;          // spheres: one pixel in ray slope (the larger of x and y)
#ifdef FX_LIT
uniform vec4 uBatchLight[kMaxBatches];  // anisotropy, absorption, normal strength, 1 lit / 0 unlit
uniform int uTrimmed;          // 1: the raster path draws the billboards' trimmed polygons (ParticleShape::Trimmed)
uniform int uShapeBuckets;     // LOD buckets per frame in uShapes
uniform float uLodScale;       // texels per pixel = uLodScale * depth / size (vs_particles.glsl's)

// The light the raster path's vertex shader hands its fragments (vSunLight, vPhase) at view
// position p: (sun light rgb, phase).
vec4 lightAt(vec3 p, vec4 batchLight) {
    return vec4(sunThroughSmokeOf(p, batchLight.y), phaseHGOf(p, batchLight.x));
}
#endif

void main() {
    uint index = gl_GlobalInvocationID.y * uint(uGroupsX) * 64u + gl_GlobalInvocationID.x;
    if (index >= uint(uInstanceCount)) return;
    int batch = 0;
    for (int b = 0; b < uBatchCount; ++b) {
        if (int(index) >= uBatchRange[b].x && int(index) < uBatchRange[b].x + uBatchRange[b].y) batch = b;
    }
    vec4 posSize = uInstances[2u * index];
    vec4 lrff = uInstances[2u * index + 1u];
    vec4 a = uBatchA[batch];
    vec4 b = uBatchB[batch];
    uint kind = uint(b.z);
    vec3 c = (uView * vec4(posSize.xyz, 1.0)).xyz;
    float depth = -c.z;
    float radius = 0.5 * posSize.w;
    vec4 ramp = textureLod(uRamp, vec2(rampU(lrff.x), a.x), 0.0);
    vec2 cell = atlasCell(lrff.w);
    float fade = lrff.z;
    float lod;
    vec4 r0, r1, r2;
    if (kind == 2u) {
        // As the vertex shader's FX_SPHERICAL branch: the sphere itself, its atlas map; the near
        // fade is per pixel, at the visible chord's middle.
        vec4 map;
        vec2 base;
        sphereAtlasMap(vec2(cos(lrff.y), sin(lrff.y)), radius, cell, map, base);
        r0 = vec4(c, radius > 0.0 ? radius * radius : 0.0);
        r1 = vec4(base, b.xy);
        r2 = map;
        // Texels of level 0 per pixel at the centre: the map's 1/4 per radius, a pixel's slope
        // times the depth.
        lod = log2(max(0.25 / radius * max(depth, uNear) * uPixelSlope * uAtlasTexels, 1e-8));
    } else {
        // The plane z = c.z: clip.w = P23 z + P33, ndc = (M xy + k) / w with M the projection's
        // upper 2 x 2 (TiledPath takes only projections whose w does not depend on x, y).
        // Inverted: xy = M^-1 (ndc w - k), and local = rotate2((xy - c.xy) / radius, angle).
        float w = uProj[2][3] * c.z + uProj[3][3];
        mat2 m = mat2(uProj[0].xy, uProj[1].xy);
        vec2 k = uProj[2].xy * c.z + uProj[3].xy;
        mat2 inv = inverse(m);
        float s = sin(lrff.y), co = cos(lrff.y);
        mat2 turn = mat2(co, s, -s, co);  // rotate2
        mat2 toLocal = turn * inv * (w / radius);
        vec2 offset = turn * (-(inv * k) - c.xy) / radius;
        // ndc = p * uPixelToNdc.xy + uPixelToNdc.zw folded in.
        mat2 perPixel = toLocal * mat2(uPixelToNdc.x, 0.0, 0.0, uPixelToNdc.y);
        offset += toLocal * uPixelToNdc.zw;
        bool clipped = !(depth >= uNear && depth <= uFar) || !(radius > 0.0);
        r0 = clipped ? vec4(0.0) : vec4(perPixel[0], perPixel[1]);
        r1 = vec4(clipped ? vec2(2.0) : offset, cell);
        float zs = depth * a.z;
        r2 = kind == 1u ? vec4((uDepthCoeffs.x - depth * uDepthCoeffs.z) * a.z,
                               (uDepthCoeffs.y - depth * uDepthCoeffs.w) * a.z, -zs, a.w)
                        : vec4(0.0, 0.0, 0.0, depth);
        // A billboard's near fade is its own: into the tint with the life fade.
        fade *= clamp(depth * b.x + b.y, 0.0, 1.0);
        // Texels of level 0 per pixel: the map's larger column (atlasUVOf scales local by 1/4).
        float rho = 0.25 * uAtlasTexels * max(length(perPixel[0]), length(perPixel[1]));
        lod = log2(max(rho, 1e-8));
    }
    // The tint, as particleTint with this batch's blend mode.
    vec4 fog = particleFog(depth);
    float alpha = ramp.a * fade;
    float outAlpha = a.y == 2.0 ? 0.0 : alpha;
    uint at = 6u * index;
    uRecords[at] = r0;
    uRecords[at + 1u] = r1;
    uRecords[at + 2u] = r2;
    uRecords[at + 3u] = vec4(ramp.rgb * (a.y == 1.0 ? fade : alpha) * fog.a, outAlpha);
    uRecords[at + 4u] = vec4(fog.rgb * outAlpha, lod);
    float lit = 0.0;
#ifdef FX_LIT
    vec4 batchLight = uBatchLight[batch];
    if (batchLight.w != 0.0) {
        lit = 1.0;
        uint l = kLightStride * index;
        vec2 turn = vec2(cos(lrff.y), sin(lrff.y));
        if (kind == 2u) {
            uLight[l] = lightAt(c, batchLight);  // the quad lies at the sphere's front: lit as a whole
            uLight[l + 8u] = vec4(turn * (batchLight.z * 0.6 * radius), 0.0, 0.0);
        } else {
            // vs_particles.glsl's fan: trimmed, its frame's polygon for the particle's LOD bucket
            // (shapeVertex()), else the quad; each vertex at the centre plus the camera's right and
            // up times the radius, turned back by the angle from texture space.
            int polygon = -1, n = 4;
            if (uTrimmed != 0) {
                float texelsPerPixel = uLodScale * max(depth, uNear) / max(posSize.w, 1e-6);
                int bucket = clamp(int(ceil(log2(max(texelsPerPixel, 1e-6)) + 0.5)), 0, uShapeBuckets - 1);
                polygon = clamp(int(lrff.w + 0.5), 0, 3) * uShapeBuckets + bucket;
                n = 1;
                for (int k = 1; k < kShapeVertices; ++k) {
                    if (fanVertex(polygon, k) != fanVertex(polygon, k - 1)) n = k + 1;
                }
            }
            vec3 right = normalize(vec3(uView[0][0], uView[1][0], uView[2][0]));
            vec3 up = normalize(vec3(uView[0][1], uView[1][1], uView[2][1]));
            for (int k = 0; k < n; ++k) {
                vec2 v = fanVertex(polygon, k);
                vec2 corner = polygon < 0 ? v : turnBack(v, turn);
                vec3 world = posSize.xyz + (corner.x * right + corner.y * up) * radius;
                uLight[l + uint(k)] = lightAt((uView * vec4(world, 1.0)).xyz, batchLight);
            }
            uLight[l + 8u] = vec4(turn, batchLight.z, float(n + 16 * (polygon + 1)));
        }
    }
#endif
    uRecords[at + 5u] = vec4(float(kind), lit, 0.0, 0.0);
}
#else
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba16f, binding = 0) writeonly uniform image2D uAccum;
uniform int uTileCount;
uniform ivec2 uViewSize;            // the view's pixels
#ifdef FX_LIT
uniform sampler2D uLitAtlas;        // SmokeAtlas::litTexture: the lit batches' atlas (uAtlas the others')
uniform vec4 uBatchShade[kMaxBatches];  // ambient (host ambient x lighting.ambient), scattering
#endif

void main() {
    uint tileIndex = gl_WorkGroupID.y * uint(uGroupsX) + gl_WorkGroupID.x;
    if (tileIndex >= uint(uTileCount)) return;
    uvec4 tile = uTiles[tileIndex];
    ivec2 pixel = ivec2(tile.xy) * 16 + ivec2(gl_LocalInvocationID.xy);
    if (!all(lessThan(pixel, uViewSize))) return;  // past the view's last column or row
    vec2 p = vec2(pixel) + 0.5;
    // The scene depth under the pixel, once (gl_FragCoord's stand-in: the view's pixel placed in
    // sceneColor, as the raster pass reads it).
    float d = sceneDepthTexelAt(p + vec2(uDrawOrigin));
    float invDen = 1.0 / (uDepthCoeffs.z + uDepthCoeffs.w * d);
    float quotient = (uDepthCoeffs.x + uDepthCoeffs.y * d) * invDen;
    float sceneLinear = quotient > 0.0 && quotient < 3.0e38 ? quotient : 3.0e38;
    // Spheres: the pixel's ray per metre of view depth (x/depth, y/depth), as the raster quad's
    // interpolated slope gives it at the pixel centre.
    vec2 ndc = p * uPixelToNdc.xy + uPixelToNdc.zw;
    vec2 slope = vec2((ndc.x + uProj[2][0]) / uProj[0][0], (ndc.y + uProj[2][1]) / uProj[1][1]);
    float invLen2 = 1.0 / (1.0 + slope.x * slope.x + slope.y * slope.y);

    vec4 acc = vec4(0.0);  // premultiplied colour in front; acc.a = 1 - transmittance
    for (uint e = 0u; e < tile.w && acc.a < kOpaque; ++e) {
        uint entry = uEntries[tile.z + e];
        uint instance = entry & ((1u << kBatchShift) - 1u);
        uint at = 6u * instance;
        vec4 kindLit = uRecords[at + 5u];
        uint kind = uint(kindLit.x);
        vec4 map = uRecords[at];
        vec4 mo = uRecords[at + 1u];
        vec2 uv, local = vec2(0.0);
        float tMid = 0.0, d2 = 0.0;
        vec3 centre = map.xyz;
        if (kind == 2u) {
            // fs_particles_spherical: the ray's closest approach to the centre.
            tMid = (centre.x * slope.x + centre.y * slope.y - centre.z) * invLen2;
            vec2 offset = vec2(slope.x * tMid - centre.x, slope.y * tMid - centre.y);
            float offsetZ = tMid + centre.z;
            d2 = offset.x * offset.x + offset.y * offset.y + offsetZ * offsetZ;
            if (d2 >= map.w) continue;
            vec4 am = uRecords[at + 2u];
            uv = vec2(mo.x + offset.x * am.x + offset.y * am.y, mo.y + offset.x * am.z + offset.y * am.w);
        } else {
            local = map.xy * p.x + map.zw * p.y + mo.xy;
            if (max(abs(local.x), abs(local.y)) >= 0.996) continue;  // insideFrame
            uv = atlasUVOf(local, mo.zw);
        }
        vec4 fogLod = uRecords[at + 4u];
#ifdef FX_LIT
        bool lit = kindLit.y != 0.0;
        vec4 texel = lit ? textureLod(uLitAtlas, uv, fogLod.w) : textureLod(uAtlas, uv, fogLod.w);
#else
        vec4 texel = textureLod(uAtlas, uv, fogLod.w);
#endif
        if (texel.a == 0.0) continue;
        float coverage, z0 = 0.0;
        if (kind == 2u) {
            // The chord clipped to the near plane and the scene, the near fade at the visible
            // chord's middle.
            float halfDepth = sqrt((map.w - d2) * invLen2);
            z0 = max(tMid - halfDepth, uNear);
            float z1 = min(tMid + halfDepth, sceneLinear);
            float visible = clamp((z1 - z0) / (2.0 * halfDepth), 0.0, 1.0);
            coverage = texel.a * visible * clamp(0.5 * (z0 + z1) * mo.z + mo.w, 0.0, 1.0);
        } else {
            vec4 f = uRecords[at + 2u];
            float fade;
            if (kind == 0u) {
                fade = f.w <= sceneLinear ? 1.0 : 0.0;  // hard: cut where the scene is nearer
            } else {
                float v = (f.x + f.y * d) * invDen;
                float x = clamp(v > f.z ? v : 1.0, 0.0, 1.0);
                fade = f.w == 1.0 ? x : contrastCurve(x, f.w);
            }
            coverage = texel.a * fade;
        }
        vec3 colour = texel.rgb;
#ifdef FX_LIT
        if (lit) {
            // fs_particles_hard, _soft, _spherical's FX_LIT lines, with the vertex shader's light
            // read from the particle's light record.
            uint l = kLightStride * instance;
            vec4 turn = uLight[l + 8u];
            vec4 sunPhase;
            vec3 m;
            if (kind == 2u) {
                sunPhase = uLight[l];
                vec2 bent = turnBack(atlasNormal(texel).xy, turn.xy);
                m = vec3(slope.x * z0 - centre.x + bent.x, slope.y * z0 - centre.y + bent.y, -z0 - centre.z);
            } else {
                // The light linear across the raster fan's triangles (0, j + 1, j + 2), as the
                // rasteriser interpolates a billboard (one depth: linear in its plane). The pixel's
                // triangle lies between the two rays from vertex 0 it lies between (the fan is
                // convex and counter-clockwise: it is left of every ray before); its weights are
                // its barycentric ones (outside the polygon, where the atlas is empty, the nearest
                // triangle's carried on).
                int code = int(turn.w);
                int n = code % 16, polygon = code / 16 - 1;
                vec4 l0 = uLight[l];
                // The fan's eight vertices at once (a polygon is four vec4 of uShapes): loads that
                // wait on nothing, and a search unrolled over registers (one load after another
                // per ray cost the fill scene's lit pass 0.35 ms on an H200).
                vec4 s0, s1, s2, s3;
                if (polygon < 0) {
                    s0 = vec4(1.0, -1.0, 1.0, 1.0);
                    s1 = vec4(-1.0, 1.0, -1.0, -1.0);
                    s2 = s3 = vec4(-1.0);
                } else {
                    int at = polygon * (kShapeVertices / 2);
                    s0 = uShapes[at];
                    s1 = uShapes[at + 1];
                    s2 = uShapes[at + 2];
                    s3 = uShapes[at + 3];
                }
                vec2 v0 = s0.xy;
                vec2 e[7] = vec2[7](s0.zw - v0, s1.xy - v0, s1.zw - v0, s2.xy - v0, s2.zw - v0, s3.xy - v0, s3.zw - v0);
                vec2 d = (polygon < 0 ? turnBack(local, turn.xy) : local) - v0;
                int j = 0;  // triangle j: vertices 0, j + 1, j + 2; e[k] is vertex k + 1's ray
                vec2 a = e[0], b = e[1];
                for (int k = 1; k < 6; ++k) {
                    if (k <= n - 3 && e[k].x * d.y - e[k].y * d.x > 0.0) {
                        j = k;
                        a = e[k];
                        b = e[k + 1];
                    }
                }
                // A fan of fewer than three vertices (a frame with nothing drawn) lights vertex 0
                // alone: the setup wrote no others, and 0 x an unwritten NaN is NaN.
                float area = a.x * b.y - a.y * b.x;
                sunPhase = l0;
                if (n >= 3 && abs(area) > 1e-12) {
                    vec2 w = vec2(d.x * b.y - d.y * b.x, a.x * d.y - a.y * d.x) / area;
                    sunPhase += w.x * (uLight[l + uint(j + 1)] - l0) + w.y * (uLight[l + uint(j + 2)] - l0);
                }
                m = billboardNormalOf(texel, turn.xy * turn.z, turn.z);
            }
            vec4 shade = uBatchShade[entry >> kBatchShift];
            colour = texel.bbb * smokeLightOf(sunCosine(m), texel.a, sunPhase.rgb, sunPhase.a, shade.rgb, shade.a);
        }
#endif
        vec4 tint = uRecords[at + 3u];
        vec4 src = vec4(coverage * (tint.rgb * colour + fogLod.rgb), tint.a * coverage);
        acc += (1.0 - acc.a) * src;
    }
    imageStore(uAccum, pixel, acc);
}
#endif
