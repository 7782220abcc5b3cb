#include "common.glsl"

uniform vec4 uBaseColor;

in vec3 vNormal;
in vec3 vViewPos;
in vec3 vWorldPos;

layout(location = 0) out vec4 oColor;
// Linear view depth (metres) for a second render target: where the opaque pass also writes the
// scene depth the particles read (no depth prepass). Without one bound the output is dropped.
layout(location = 1) out float oLinearDepth;

void main() {
    vec3 n = normalize(vNormal);
    vec3 c = shadeLambert(uBaseColor.rgb, n, smokeShadow(vWorldPos));
    oColor = vec4(applyHaze(c, length(vViewPos)), 1.0);
    oLinearDepth = -vViewPos.z;
}
