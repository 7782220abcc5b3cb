#include "common.glsl"
#include "mesh_fragment.glsl"

uniform vec4 uBaseColor;

void main() {
    vec3 n = normalize(vNormal);
    vec3 c = shadeLambert(uBaseColor.rgb, n, smokeShadow(vWorldPos));
    oColor = vec4(applyFog(applyHaze(c, length(vViewPos)), vViewPos.z), 1.0);
    oLinearDepth = -vViewPos.z;
}
