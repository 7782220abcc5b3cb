#version 330 core
// Stateless particles (004): each instance is a birth record, and the particle is evaluated here
// from the current time. No CPU work per particle after its birth. The motion is the exact drag
// solution with gravity, a float port of fx_plugin/sim/StatelessParticle.h (keep them in step):
//     p(t) = p0 + u t + (v0 - u) R(t) + g L(t),  R = (1 - e^-kt) / k,  L = (t - R) / k
// with Taylor series below k t = 0.5 where 1 - e^-kt and t - R cancel in float.
// A record not alive at uTime (not yet born, dead, or an unused ring slot) becomes a degenerate
// quad outside the clip volume. Sparks are streaks: the quad is stretched along the projected
// velocity by kStreakSeconds of travel, so fast particles read as lines at any frame rate.

layout(location = 0) in vec2 aCorner;        // (+-1, +-1), triangle strip order
layout(location = 1) in vec4 aPosBirth;      // p0 (world, m), birth (s, reaction clock)
layout(location = 2) in vec4 aVelLife;       // v0 (m/s), lifetime (s)
layout(location = 3) in vec4 aSizesRotSpin;  // start size, end size (m), rotation (rad), spin (rad/s)
layout(location = 4) in vec4 aFrame;         // atlas frame (unused by sparks), padding

uniform mat4 uView;
uniform mat4 uProj;
uniform float uTime;
uniform vec3 uTerminal;   // wind * wind_factor + rise_speed * up
uniform vec3 uGravity;    // (0, -gravity, 0)
uniform float uDrag;
uniform float uFadeIn;
uniform float uFadeOut;
uniform int uRampCount;   // colour ramp stops (1..16)
uniform float uRampT[16];
uniform vec4 uRampC[16];
uniform int uAlphaCount;  // alpha_over_life points; 0 = the fade smoothsteps
uniform float uAlphaT[16];
uniform float uAlphaV[16];
uniform int uSizeCount;   // size_over_life points; 0 = the ease-out growth
uniform float uSizeT[16];
uniform float uSizeV[16];

out vec2 vLocal;
flat out vec4 vColor;     // straight colour, alpha including the life fade
flat out float vDepth;    // the spark's view distance, metres (-z_view: the streak lies at that z)

const float kStreakSeconds = 0.05;

vec2 reachLift(float k, float t) {
    float kt = k * t;
    if (kt < 0.5) {
        float x = -kt;
        float r = 1.0 / 40320.0, l = 1.0 / 362880.0;
        r = r * x + 1.0 / 5040.0;  l = l * x + 1.0 / 40320.0;
        r = r * x + 1.0 / 720.0;   l = l * x + 1.0 / 5040.0;
        r = r * x + 1.0 / 120.0;   l = l * x + 1.0 / 720.0;
        r = r * x + 1.0 / 24.0;    l = l * x + 1.0 / 120.0;
        r = r * x + 1.0 / 6.0;     l = l * x + 1.0 / 24.0;
        r = r * x + 0.5;           l = l * x + 1.0 / 6.0;
        r = r * x + 1.0;           l = l * x + 0.5;
        return vec2(t * r, t * t * l);
    }
    float reach = (1.0 - exp(-kt)) / k;
    return vec2(reach, (t - reach) / k);
}

// Where f lies on a piecewise-linear curve's knots ts[0..count): between knots lo and hi = lo + 1,
// w of the way from ts[lo] to ts[hi] (1 where they coincide); lo = hi at or before the first knot
// (0) and past the last (count - 1), where the curve holds its end value.
void curveSegment(float f, int count, float ts[16], out int lo, out int hi, out float w) {
    lo = hi = count - 1;
    w = 0.0;
    if (f <= ts[0]) {
        lo = hi = 0;
        return;
    }
    for (int i = 1; i < count; ++i) {
        if (f <= ts[i]) {
            float span = ts[i] - ts[i - 1];
            lo = i - 1;
            hi = i;
            w = span > 0.0 ? (f - ts[i - 1]) / span : 1.0;
            return;
        }
    }
}

float curveAt(float f, int count, float ts[16], float vs[16]) {
    int lo, hi;
    float w;
    curveSegment(f, count, ts, lo, hi, w);
    return lo == hi ? vs[lo] : mix(vs[lo], vs[hi], w);
}

vec4 rampAt(float f) {
    int lo, hi;
    float w;
    curveSegment(f, uRampCount, uRampT, lo, hi, w);
    return lo == hi ? uRampC[lo] : mix(uRampC[lo], uRampC[hi], w);
}

void main() {
    float age = uTime - aPosBirth.w;
    if (!(age >= 0.0 && age < aVelLife.w)) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: culled
        vLocal = vec2(0.0);
        vColor = vec4(0.0);
        return;
    }
    float f = age / aVelLife.w;
    vec2 rl = reachLift(uDrag, age);
    vec3 d0 = aVelLife.xyz - uTerminal;
    vec3 pos = aPosBirth.xyz + uTerminal * age + d0 * rl.x + uGravity * rl.y;
    vec3 vel = uTerminal + d0 * exp(-uDrag * age) + uGravity * rl.x;

    float growth = uSizeCount > 0 ? curveAt(f, uSizeCount, uSizeT, uSizeV) : 1.0 - (1.0 - f) * (1.0 - f);
    float size = aSizesRotSpin.x + (aSizesRotSpin.y - aSizesRotSpin.x) * growth;
    float fade = uAlphaCount > 0 ? curveAt(f, uAlphaCount, uAlphaT, uAlphaV)
                                 : (uFadeIn > 0.0 ? smoothstep(0.0, uFadeIn, f) : 1.0) *
                                       (uFadeOut > 0.0 ? smoothstep(0.0, uFadeOut, 1.0 - f) : 1.0);
    vec4 ramp = rampAt(f);
    vColor = vec4(ramp.rgb, ramp.a * fade);

    vec3 c = (uView * vec4(pos, 1.0)).xyz;
    vec2 v2 = (mat3(uView) * vel).xy;
    float speed = length(v2);
    vec2 along = speed > 1e-4 ? v2 / speed : vec2(cos(aSizesRotSpin.z), sin(aSizesRotSpin.z));
    vec2 across = vec2(-along.y, along.x);
    float halfSize = 0.5 * size;
    vec2 offset = along * aCorner.x * (halfSize + 0.5 * speed * kStreakSeconds) + across * aCorner.y * halfSize;
    vLocal = aCorner;
    vDepth = -c.z;
    gl_Position = uProj * vec4(c + vec3(offset, 0.0), 1.0);
}
