#include "common.glsl"

uniform vec4 uBaseColor;

in vec3 vNormal;
in vec3 vViewPos;

layout(location = 0) out vec4 oColor;

void main() {
    vec3 n = normalize(vNormal);
    vec3 c = shadeLambert(uBaseColor.rgb, n);
    oColor = vec4(applyHaze(c, length(vViewPos)), 1.0);
}
