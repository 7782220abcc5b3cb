// The fxbench "overdraw" scenario's panels: an opaque surface with a deliberately expensive
// procedural pattern (uCost octaves of value noise), so shading every hidden layer costs real
// time and depth test EQUAL after a prepass has something to save.
#include "common.glsl"
#include "mesh_fragment.glsl"

uniform vec4 uBaseColor;
uniform int uCost;

float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
float noise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i), hash(i + vec2(1, 0)), u.x), mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), u.x), u.y);
}

void main() {
    vec2 p = vViewPos.xy * 0.7;
    float v = 0.0, a = 0.5;
    for (int i = 0; i < uCost; ++i) {
        v += a * noise(p);
        p *= 2.03;
        a *= 0.5;
    }
    vec3 c = shadeLambert(uBaseColor.rgb * (0.6 + 0.8 * v), normalize(vNormal), smokeShadow(vWorldPos));
    oColor = vec4(applyFog(c, vViewPos.z), 1.0);
    oLinearDepth = -vViewPos.z;
}
