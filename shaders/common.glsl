// Shared by the engine's scene shaders.
// The race scene's light: one sun and a sky/ground hemisphere ambient, set by the engine from
// its SunLight (engine_stub/render/SunLight.h, SceneRenderer::setSun); light haze.
uniform vec3 uToSun;          // unit, world space, toward the sun
uniform vec3 uSunColor;
uniform vec3 uSkyAmbient;     // on surfaces facing up
uniform vec3 uGroundAmbient;  // on surfaces facing down
// fs_sky.glsl draws the sun's disc by these names.
#define kSunDir uToSun
#define kSunColor uSunColor
const vec3 kHazeColor = vec3(0.70, 0.78, 0.88);
const float kHazeDensity = 0.0022;

// `sunVisible`: the share of the sun's light that reaches the surface (1 = all).
vec3 shadeLambert(vec3 albedo, vec3 n, float sunVisible) {
    float ndl = max(dot(n, uToSun), 0.0);
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.y);
    return albedo * (ambient + uSunColor * (ndl * 0.85 * sunVisible));
}
vec3 shadeLambert(vec3 albedo, vec3 n) { return shadeLambert(albedo, n, 1.0); }

// The smoke's shadow (fx::SmokeShadow, the plugin's opacity map; SceneRenderer::setSmokeShadow):
// channel k is the optical depth of the smoke from the sun down to light depth (k + 1) / 4,
// alpha the whole column; between the slices it is linear, so a surface above the cloud (a
// grandstand roof) gets no shadow and one below it the whole column's.
uniform sampler2D uSmokeOpacity;
uniform mat4 uWorldToSmoke;      // world -> (u, v, light depth, 1)
uniform float uSmokeAbsorption;  // optical depth per unit of opacity; 0 = no smoke this frame

// The share of the sun that reaches world position `p` through the smoke (1 without smoke).
float smokeShadow(vec3 p) {
    vec4 s = uWorldToSmoke * vec4(p, 1.0);
    bool inside = all(greaterThanEqual(s.xy, vec2(0.0))) && all(lessThanEqual(s.xy, vec2(1.0)));
    vec4 m = inside && uSmokeAbsorption > 0.0 ? texture(uSmokeOpacity, s.xy) : vec4(0.0);
    vec4 w = clamp(vec4(clamp(s.z, 0.0, 1.0) * 4.0) - vec4(0.0, 1.0, 2.0, 3.0), 0.0, 1.0);
    float depth = dot(m - vec4(0.0, m.rgb), w);
    return exp(-uSmokeAbsorption * depth);
}

// The track's fog (render/SceneFog.h, SceneRenderer::setFog), fixed-function GL's: f = (end - c)
// / (end - start), exp(-density c) or exp(-(density c)^2), clamped to [0, 1], c = |z_eye|; the
// colour becomes f colour + (1 - f) fog colour. The plugin gets the same fog (fx::ViewInfo::fog)
// and fogs the smoke by the same formula. Built only into the programs of a fogged scene
// (CUBE_FOG, SceneRenderer::init): a CPU rasteriser evaluates both sides of a branch on every
// fragment, so a run-time "off" still paid for the exponentials. Without it the colour is
// returned untouched.
#ifdef CUBE_FOG
uniform int uFogMode;     // 1 linear, 2 exp, 3 exp2
uniform vec3 uFogColor;
uniform vec3 uFogParams;  // start, end, density
#endif

vec3 applyFog(vec3 color, float eyeZ) {
#ifndef CUBE_FOG
    return color;
#else
    float c = abs(eyeZ);
    float dc = uFogParams.z * c;
    float f = uFogMode == 1 ? (uFogParams.y - c) / (uFogParams.y - uFogParams.x)
                            : (uFogMode == 2 ? exp(-dc) : exp(-dc * dc));
    f = clamp(f, 0.0, 1.0);
    return f * color + (1.0 - f) * uFogColor;
#endif
}

vec3 applyHaze(vec3 color, float viewDistance) {
    float f = 1.0 - exp(-kHazeDensity * viewDistance);
    return mix(color, kHazeColor, clamp(f, 0.0, 0.85));
}
