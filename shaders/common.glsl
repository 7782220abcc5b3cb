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

vec3 shadeLambert(vec3 albedo, vec3 n) {
    float ndl = max(dot(n, uToSun), 0.0);
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.y);
    return albedo * (ambient + uSunColor * ndl * 0.85);
}

vec3 applyHaze(vec3 color, float viewDistance) {
    float f = 1.0 - exp(-kHazeDensity * viewDistance);
    return mix(color, kHazeColor, clamp(f, 0.0, 0.85));
}
