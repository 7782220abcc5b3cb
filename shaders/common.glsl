// Shared by the engine's scene shaders.
// Lighting constants of the race scene: one sun, a sky/ground hemisphere ambient, light haze.
const vec3 kSunDir = normalize(vec3(-0.35, 0.85, 0.40));
const vec3 kSunColor = vec3(1.00, 0.96, 0.88);
const vec3 kSkyAmbient = vec3(0.42, 0.50, 0.62);
const vec3 kGroundAmbient = vec3(0.22, 0.20, 0.17);
const vec3 kHazeColor = vec3(0.70, 0.78, 0.88);
const float kHazeDensity = 0.0022;

vec3 shadeLambert(vec3 albedo, vec3 n) {
    float ndl = max(dot(n, kSunDir), 0.0);
    vec3 ambient = mix(kGroundAmbient, kSkyAmbient, 0.5 + 0.5 * n.y);
    return albedo * (ambient + kSunColor * ndl * 0.85);
}

vec3 applyHaze(vec3 color, float viewDistance) {
    float f = 1.0 - exp(-kHazeDensity * viewDistance);
    return mix(color, kHazeColor, clamp(f, 0.0, 0.85));
}
