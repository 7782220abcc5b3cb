// The host's fog (fx::Fog, API 2.1), applied to the smoke as GL's fixed-function fog applies it
// to the host's geometry at the same distance, so distant smoke fades with what lies behind it.
// Distance c = |z_eye| (GL's FRAGMENT_DEPTH fog coordinate in the abs(z) form the spec allows):
//   linear  f = (end - c) / (end - start)
//   exp     f = exp(-density c)
//   exp2    f = exp(-(density c)^2)
// clamped to [0, 1] (1 = no fog). On premultiplied colour (rgb, a), blended (ONE,
// ONE_MINUS_SRC_ALPHA) over a background the host fogged itself:
//   (f rgb + (1 - f) fogColour a, a)
// the smoke's own light is fogged and its coverage is not, as fixed-function fog on an opaque
// surface of that coverage. Additive output (a = 0) is the same formula: f rgb, fading to nothing.
// uFogMode 0 (the default of a program nobody set it on) returns the colour untouched, bit for bit.
uniform int uFogMode;      // 0 off, 1 linear, 2 exp, 3 exp2 (fx::Fog::Mode)
uniform vec3 uFogColor;    // linear RGB
uniform vec3 uFogParams;   // start, end, density

float fogFactor(float distance) {
    float c = abs(distance);
    float linear = (uFogParams.y - c) / (uFogParams.y - uFogParams.x);
    float dc = uFogParams.z * c;
    float f = uFogMode == 1 ? linear : (uFogMode == 2 ? exp(-dc) : exp(-dc * dc));
    return clamp(f, 0.0, 1.0);
}

vec4 applyFog(vec4 premultiplied, float distance) {
    if (uFogMode == 0) return premultiplied;
    float f = fogFactor(distance);
    return vec4(f * premultiplied.rgb + (1.0 - f) * uFogColor * premultiplied.a, premultiplied.a);
}

// A particle's fog, once per vertex (vs_particles): (fog colour x (1 - f), f), at the particle's
// depth; (0, 0, 0, 1) with fog off. Exact for a billboard, which faces the camera at one view
// depth; a spherical particle takes its centre's depth, the middle of the chord through it. The
// vertex shader folds it into the particle's tint (particles_common.glsl, particleTint), so the
// fragment stage pays nothing for fog.
vec4 particleFog(float distance) {
    float f = uFogMode == 0 ? 1.0 : fogFactor(distance);
    return vec4(uFogColor * (1.0 - f), f);
}

// Light added (blend ONE, ONE) fades to nothing: rgb and the alpha it adds, times f.
vec4 applyFogAdditive(vec4 added, float distance) {
    if (uFogMode == 0) return added;
    return added * fogFactor(distance);
}
