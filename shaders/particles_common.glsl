// Shared by the particle shaders (vs_particles + fs_particles_hard/soft/spherical).
//
// Conventions: view space is right-handed with the camera looking down -Z. "Depth" is always
// the positive linear view-space distance along the view axis in metres: what the particle
// shaders compute for their own fragments, and what sceneDepthAt() decodes from the host's
// z-buffer or reads from its linear R32F depth (particles_scene_depth.glsl). The fade compares
// these linear distances; the z-test that culls hidden fragments is the renderer's, and only
// where the host's z-buffer is reversed-Z float.
//
// Colour: the ramp and the atlas hold straight (not premultiplied) alpha. Every fragment shader
// writes premultiplied colour through shadeOutput(), which the renderer blends with
// (ONE, ONE_MINUS_SRC_ALPHA), or (ONE, ONE) for additive reactions.

uniform mat4 uView;
uniform mat4 uProj;
uniform float uNear;          // metres, > 0
uniform float uFar;           // metres
uniform vec2 uSlopeMax;       // |x/depth|, |y/depth| just past the frustum edges (spherical quads)

// Per reaction (per draw call).
uniform float uRampRow;       // v coordinate of this reaction's row in uRamp (texel centre)
uniform int uBlendMode;       // fx::BlendMode: 0 alpha, 1 premultiplied, 2 additive
uniform float uSoftScale;     // 1 / render.softness, 1/m
uniform float uContrastPower; // render.contrast_power, 1 = linear fade
uniform int uPowerWhole;      // without FX_GENERAL_POWER: contrast_power = uPowerWhole + uPowerHalf / 2
uniform int uPowerHalf;       // 0 or 1
uniform vec2 uNearFadeMap;    // render.near_fade f as a line in depth: (1 / f, -uNear / f); (0, 1) for f = 0 (off)

uniform sampler2D uAtlas;      // 2x2 smoke atlas, RGBA8, straight alpha, frames row-major from top-left
uniform sampler2D uRamp;       // colour by life: one row per reaction, kRampTexels wide
uniform sampler2D uSceneDepth; // the scene depth of the target being drawn (particles_scene_depth.glsl)

#include "particles_scene_depth.glsl"
#include "particles_fog.glsl"

const float kRampTexels = 64.0;  // keep equal to ColorRampTexture::kTexels

vec2 rotate2(vec2 v, float angle) {
    float s = sin(angle), c = cos(angle);
    return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

// The ramp's u for a life fraction, hitting the first and last texel centres exactly at 0 and 1.
float rampU(float life) {
    return (clamp(life, 0.0, 1.0) * (kRampTexels - 1.0) + 0.5) / kRampTexels;
}

// The atlas coordinate of frame `frame`'s top-left corner (frames row-major from the top-left
// of the 2x2 atlas). The vertex shader passes it flat, so fragments do no integer work for it.
vec2 atlasCell(float frame) {
    int f = clamp(int(frame + 0.5), 0, 3);
    return vec2(float(f & 1), float(f >> 1)) * 0.5;
}

// Atlas coordinate of a particle-space point `local` in [-1, 1]^2 (+y up, already rotated) in
// the frame whose corner is `cell` (atlasCell). The PNG is uploaded top row first, so t = 0 is
// the image's top: +y (up) goes to smaller t. The map is affine in `local`, so billboards work it
// out per vertex and the rasteriser interpolates it (vAtlasUV): their fragments do no arithmetic
// for it. Past the frame's square (a rotated quad's corners) it reads into the neighbouring cell,
// where insideFrame masks the fragment.
vec2 atlasUVOf(vec2 local, vec2 cell) {
    return cell + vec2(0.25 + 0.25 * local.x, 0.25 - 0.25 * local.y);
}

// Spherical billboards look the atlas up per fragment at the closest approach's offset o from
// the centre (view x, y, metres), turned by the particle's angle into units of the radius:
// atlasUVOf(rotate2(o / r, angle), cell), affine in o. The vertex shader folds the turn, the radius
// and atlasUVOf's scale into one flat map, so a fragment does four multiply-adds:
// uv = base + o.x map.xz + o.y map.yw. The point lies inside the unit disc wherever the fragment
// is kept, so it stays on the frame's square (whose border the atlas alpha is exactly 0 on)
// up to rounding; the fragments outside the disc that read past it are discarded.
void sphereAtlasMap(vec2 turn, float radius, vec2 cell, out vec4 map, out vec2 base) {
    vec2 t = 0.25 * turn / radius;
    map = vec4(t.x, -t.y, -t.y, -t.x);
    base = cell + vec2(0.25);
}

// `v` turned back by the angle whose (cos, sin) is `turn` (rotate2 with the sine and cosine
// computed once per particle in the vertex shader).
vec2 turnBack(vec2 v, vec2 turn) {
    return vec2(turn.x * v.x + turn.y * v.y, turn.x * v.y - turn.y * v.x);
}

// 1 inside the frame's square [-1, 1]^2 (less a 1/256 rim), 0 outside. A rotated quad's corners
// reach past the square; clamped onto the cell border they would read the coarse mip levels'
// border texels, which are not 0 once a level's texels span the puff's margin. Masking them makes
// the sprite exactly its frame, which is also what the trimmed polygons (inside the square)
// draw, so quads and trimmed polygons give the same pixels.
float insideFrame(vec2 local) {
    return max(abs(local.x), abs(local.y)) < 0.996 ? 1.0 : 0.0;
}

// t^p for t in [0, 1]. FX_GENERAL_POWER: pow(). Otherwise p is a whole or half-whole number up to
// 16, built from squarings and one sqrt: a few multiplies instead of exp2(p * log2(t)), which costs
// more than the rest of the soft fragment on a CPU rasteriser (every lane evaluates both sides of
// a branch there). FX_POWER_STEPS = 2p (a ProgramCache key of its own: one program per power the
// reactions use): the bits are constants, so only the multiplies that power needs are left.
// Without it they are uniform bits, and every lane pays for the whole chain and its selects.
#ifdef FX_POWER_STEPS
const int kPowerWhole = FX_POWER_STEPS / 2;
const int kPowerHalf = FX_POWER_STEPS - 2 * kPowerWhole;
#else
#define kPowerWhole uPowerWhole
#define kPowerHalf uPowerHalf
#endif
float powerOf(float t, float power) {
#ifdef FX_GENERAL_POWER
    return pow(t, power);
#else
    float t2 = t * t, t4 = t2 * t2, t8 = t4 * t4, t16 = t8 * t8;
    float r = (kPowerWhole & 1) != 0 ? t : 1.0;
    r *= (kPowerWhole & 2) != 0 ? t2 : 1.0;
    r *= (kPowerWhole & 4) != 0 ? t4 : 1.0;
    r *= (kPowerWhole & 8) != 0 ? t8 : 1.0;
    r *= (kPowerWhole & 16) != 0 ? t16 : 1.0;
    return kPowerHalf != 0 ? r * sqrt(t) : r;
#endif
}

// NVIDIA's soft-particle contrast curve ("Soft Particles", Lorach 2007): symmetric S-curve
// around 0.5, 0.5 * (2x)^p below it and 1 - 0.5 * (2 - 2x)^p above; power 1 is the identity.
// Written without branches: t = 2 min(x, 1 - x), y = 0.5 + 0.5 sign(2x - 1) (1 - t^p).
// (The shader code in this file avoids branches on purpose: a CPU rasteriser runs both sides.)
#if defined(FX_POWER_STEPS) && FX_POWER_STEPS == 2
float contrastCurve(float x, float power) { return x; }  // power 1: the identity, nothing to evaluate
#else
float contrastCurve(float x, float power) {
    float u = 2.0 * x - 1.0;
    float t = clamp(1.0 - abs(u), 0.0, 1.0);
    return 0.5 + 0.5 * sign(u) * (1.0 - powerOf(t, power));
}
#endif

// A billboard's soft fade, saturate((t - z) s) through the contrast curve, with t the scene's
// depth at window depth d, t = (A + B d) / (C + D d) (linearSceneDepth), z the billboard's depth
// and s = uSoftScale. A billboard lies at one depth, so its vertices fold z and s into the
// numerator, flat per particle (softFadeLine): (t - z) s = (a + b d) / (C + D d) with
// a = (A - z C) s, b = (B - z D) s. A fragment pays two multiply-adds and a division where
// linearSceneDepth and the fade took those and a subtraction, a multiply and a range check of
// four operations. The range check becomes one comparison: t > 0 exactly where the quotient
// exceeds -z s (softFadeLine's third value); where it does not (nothing drawn at a linear host's
// clear of 0, NaN) the fade is 1, as t's stand-in 3.0e38 gave. A t of 3.0e38 or more, or
// infinite, fades to 1 through the clamp. The rounding is that of linearSceneDepth's own terms
// (both sum the same products of the coefficients, z a factor of t's size where the fade is
// under 1): TechniqueTest.SoftFadeIsExactWithExtremeClipPlanes holds it to the CPU's fade at
// near 0.01 m and far 1e7 m.
// FX_HALF_RES_DEPTH: d is already linear metres (the downsample's), so the line is
// (a, b) = (-z s, s) and there is no division.
vec3 softFadeLine(float depth) {
    float zs = depth * uSoftScale;
#ifdef FX_HALF_RES_DEPTH
    return vec3(-zs, uSoftScale, -zs);
#else
    return vec3((uDepthCoeffs.x - depth * uDepthCoeffs.z) * uSoftScale,
                (uDepthCoeffs.y - depth * uDepthCoeffs.w) * uSoftScale, -zs);
#endif
}
float softFade(float d, vec3 line) {
#ifdef FX_HALF_RES_DEPTH
    float x = clamp(line.x + line.y * d, 0.0, 1.0);
#else
    float v = (line.x + line.y * d) / (uDepthCoeffs.z + uDepthCoeffs.w * d);
    float x = clamp(v > line.z ? v : 1.0, 0.0, 1.0);
#endif
    return contrastCurve(x, uContrastPower);
}

// 0 at the near plane, 1 from render.near_fade metres in front of it on (no pop when a particle
// reaches the near plane and is clipped). One multiply-add: the division and the switch are
// worked out once per draw (ParticleDraw's nearFadeMap), not per fragment.
float nearFadeFactor(float depth) {
    return clamp(depth * uNearFadeMap.x + uNearFadeMap.y, 0.0, 1.0);
}

// The scene's linear depth at this pixel (particles_scene_depth.glsl: decoded from the z-buffer,
// or the host's linear depth; 3.0e38 where nothing was drawn). Read with textureLod
// at the pixel's texel centre through the renderer's nearest sampler (NearestSampler): the same
// texel texelFetch gives, and cheaper on llvmpipe, which bounds-checks every texelFetch lane
// (fxbench standard scenario, medians of three alternations: soft / hard frame 1.256 against
// 1.278 with texelFetch).
// `fragCoord` is gl_FragCoord of the target being drawn; the view's placement in it and in the
// depth texture is particles_scene_depth.glsl's (both offsets 0 for a view at (0, 0) of its own).
// uDepthUv: (texel of the view's pixel (0, 0) - uDrawOrigin, 1) / the texture's size, set once per
// draw (SceneDepthSource.cpp), so a fragment pays one multiply-add for its coordinate.
// FX_HALF_RES_DEPTH (the quarter-res draws, ProgramCache::Key::halfRes): the texture is the
// plugin's own half-res depth, linear metres already made safe by the downsample (which decoded
// it with linearSceneDepth), so it is read as it is: no division, no range check.
uniform vec4 uDepthUv;
// The texel as stored: window depth (or the host's linear depth), or the half-res linear depth.
float sceneDepthTexelAt(vec2 fragCoord) {
    return textureLod(uSceneDepth, fragCoord * uDepthUv.zw + uDepthUv.xy, 0.0).r;
}
float sceneDepthAt(vec2 fragCoord) {
#ifdef FX_HALF_RES_DEPTH
    return sceneDepthTexelAt(fragCoord);
#else
    // At full res only spherical particles read it, and end their chord at min(exit, t): a t of
    // 3.0e38 or more, or infinite, ends it as far away as linearSceneDepth's stand-in would, so
    // only a t that is not positive (or NaN) needs the stand-in: one comparison instead of two.
    float t = decodedSceneDepth(sceneDepthTexelAt(fragCoord));
    return t > 0.0 ? t : 3.0e38;
#endif
}

// Premultiplied output, fogged. With `ramp` the ramp colour at the particle's life (straight
// alpha), `fade` its life fade (billboards: times their near fade, which is the particle's own),
// `colour` the atlas colour (lit smoke: the light on it) and `coverage` every per-pixel factor
// (atlas alpha, soft fade, sphere visibility, spheres' near fade):
//   alpha:         (rgb * a, a)        with a = ramp.a * fade * coverage, rgb = ramp.rgb * colour
//   premultiplied: (rgb * k, ramp.a * k) with k = fade * coverage (ramp rgb taken as premultiplied)
//   additive:      (rgb * a, 0)        blended (ONE, ONE): adds light, leaves coverage alone
// then fogged as (f rgb + (1 - f) fogColour alpha, alpha) (particles_fog.glsl). Everything but
// colour and coverage is the particle's own, so the vertex shader folds it into two flat values
// (particleTint) and a fragment does seven scalar operations for it (shadeOutput). What each
// particle program does per fragment: scripts/shader_ops.py, held to a budget by a test.
void particleTint(vec4 ramp, float fade, vec4 fog, out vec4 tint, out vec3 fogAdd) {
    float a = ramp.a * fade;
    float alpha = uBlendMode == 2 ? 0.0 : a;
    tint = vec4(ramp.rgb * (uBlendMode == 1 ? fade : a) * fog.a, alpha);
    fogAdd = fog.rgb * alpha;
}
vec4 shadeOutput(vec4 tint, vec3 fogAdd, vec3 colour, float coverage) {
    return vec4(coverage * (tint.rgb * colour + fogAdd), tint.a * coverage);
}

#ifdef FX_LIT
// ---- Lit smoke (Plugin::setSceneLight, reaction key `lighting:`) ----
// Diffuse light on a per-pixel normal (the atlas's normal map for billboards, the sphere's own
// normal for spherical billboards), wrapped because smoke is translucent, plus single
// scattering with the Henyey-Greenstein phase, so smoke between the camera and the sun glows
// where it is thin. Both are dimmed by the smoke between the pixel and the sun: the opacity
// map (SmokeOpacityMap.h), four slices of optical depth along the light.
uniform vec3 uSunView;        // unit, view space, toward the sun
uniform vec3 uSunColor;       // linear RGB
uniform vec3 uAmbient;        // host ambient x lighting.ambient
uniform float uNormalStrength;
uniform float uScattering;
uniform float uAnisotropy;    // Henyey-Greenstein g
uniform float uAbsorption;    // optical depth per unit of accumulated opacity
uniform int uShadowed;        // 1: uOpacity holds this frame's opacity map
uniform mat4 uViewToShadow;   // view space -> (u, v, light depth, 1), each in [0, 1] inside the map
uniform sampler2D uOpacity;   // RGBA16F: optical depth up to light depth 1/4, 2/4, 3/4, 1
// Lit programs read uAtlas as the lit atlas (SmokeAtlas::litTexture): R, G = the normal map's
// x and y (128 + 127 n), B = the atlas grey, A = the atlas alpha: one fetch for shape, colour
// and normal, where a separate normal map would cost a second filtered fetch per fragment.

const float kWrap = 0.5;      // diffuse wrap: light reaches 1/3 of the way round the terminator

// The atlas normal of a lit-atlas texel in particle space (x right, y up, z toward the viewer;
// the normal map only holds normals facing the viewer, so z is the rest of unit length).
// (0, 0, 1) where the puff is empty (x = y = 0 there). 128 + 127 n decoded as one multiply-add.
vec3 atlasNormal(vec4 litTexel) {
    float x = litTexel.r * (255.0 / 127.0) - 128.0 / 127.0;
    float y = litTexel.g * (255.0 / 127.0) - 128.0 / 127.0;
    return vec3(x, y, sqrt(max(1.0 - x * x - y * y, 0.0)));
}

// A billboard's shading normal in view space, not normalised (sunCosine normalises it): the
// atlas normal turned with the sprite (texture axes are the screen axes rotated by the
// particle's angle), mixed by the normal strength s with a flat card facing the camera. `turn`
// is the angle's (cos, sin) times s (the vertex shader's vTurn in lit programs), so the mix's
// x and y are the turn alone: (s turned.xy, 1 + s (n.z - 1)).
vec3 billboardNormalOf(vec4 litTexel, vec2 turn, float strength) {
    vec3 n = atlasNormal(litTexel);
    return vec3(turnBack(n.xy, turn), 1.0 + strength * (n.z - 1.0));
}
vec3 billboardNormal(vec4 litTexel, vec2 turn) { return billboardNormalOf(litTexel, turn, uNormalStrength); }

// The cosine between the normal `m` (any positive length) and the sun: light only needs the
// normal through this, so it is never normalised on its own.
float sunCosine(vec3 m) {
    return dot(m, uSunView) * inversesqrt(dot(m, m));
}

// Optical depth of the smoke between view-space point `p` and the sun. The four channels are
// the optical depth up to the slice boundaries 1/4 .. 1; between them it is linear, and 0 at
// light depth 0 (no branches: each channel's increment weighted by how far p is past its start).
float opticalDepthToSun(vec3 p) {
    vec4 s = uViewToShadow * vec4(p, 1.0);
    vec4 m = texture(uOpacity, s.xy);
    float inside = all(greaterThanEqual(s.xy, vec2(0.0))) && all(lessThanEqual(s.xy, vec2(1.0))) ? 1.0 : 0.0;
    // Read half a slice toward the sun: a particle is spread over the quarter-slice around its
    // own depth, and this keeps it from shadowing itself.
    vec4 w = clamp(vec4(clamp(s.z, 0.0, 1.0) * 4.0 - 0.5) - vec4(0.0, 1.0, 2.0, 3.0), 0.0, 1.0);
    vec4 increments = m - vec4(0.0, m.rgb);
    return dot(increments, w) * inside * float(uShadowed);
}

// Henyey-Greenstein times 4 pi (1 on average over the sphere) for a smoke point at view
// position `p`: (1 - g^2) / (1 + g^2 - 2 g c)^1.5, c the cosine between the sun's light
// direction and the direction to the eye. The vertex shader evaluates it (and the transmittance
// toward the sun) per vertex: both change slowly across a particle, and per pixel they cost a
// fetch, a matrix and an exp on every fragment.
// The ...Of forms take the reaction's values as arguments (the tiled path's compute shader holds
// every batch's at once); the others read this draw's uniforms.
float phaseHGOf(vec3 p, float g) {
    float c = dot(-uSunView, normalize(-p));
    float base = max(1.0 + g * g - 2.0 * g * c, 1e-4);
    return (1.0 - g * g) / (base * sqrt(base));
}
float phaseHG(vec3 p) { return phaseHGOf(p, uAnisotropy); }

// Sun light reaching view position `p` through the smoke in front of it.
vec3 sunThroughSmokeOf(vec3 p, float absorption) {
    return uSunColor * exp(-absorption * opticalDepthToSun(p));
}
vec3 sunThroughSmoke(vec3 p) { return sunThroughSmokeOf(p, uAbsorption); }

// Light arriving at a smoke pixel whose normal makes `cosSun` with the sun (sunCosine) and whose
// opacity is `density`:
// ambient + the sun through the smoke x (the diffuse and scattered shares). `sunLight` and
// `phase` come from the vertex shader (sunThroughSmoke, phaseHG).
vec3 smokeLightOf(float cosSun, float density, vec3 sunLight, float phase, vec3 ambient, float scattering) {
    float diffuse = clamp(cosSun * (1.0 / (1.0 + kWrap)) + kWrap / (1.0 + kWrap), 0.0, 1.0);
    float thin = 1.0 - 0.6 * density;  // thin edges pass more forward-scattered light
    float lit = diffuse + scattering * (phase * thin - diffuse);  // mix(diffuse, phase thin, scattering)
    return ambient + sunLight * lit;
}
vec3 smokeLight(float cosSun, float density, vec3 sunLight, float phase) {
    return smokeLightOf(cosSun, density, sunLight, phase, uAmbient, uScattering);
}
#endif
