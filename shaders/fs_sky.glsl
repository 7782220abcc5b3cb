// Sky gradient from the view direction, drawn at the far plane after the opaque pass.
#include "common.glsl"

uniform mat4 uInvViewProj;

in vec2 vUV;
layout(location = 0) out vec4 oColor;

void main() {
    vec4 p = uInvViewProj * vec4(vUV * 2.0 - 1.0, 1.0, 1.0);
    vec3 dir = normalize(p.xyz / p.w);
    float up = clamp(dir.y, -0.2, 1.0);
    vec3 zenith = vec3(0.26, 0.45, 0.78);
    vec3 sky = mix(kHazeColor, zenith, smoothstep(0.0, 0.55, up));
    float sun = pow(max(dot(dir, kSunDir), 0.0), 400.0);
    // The sky lies past any fog's reach: fully fogged where fog is on (f = 0 at infinity).
    oColor = vec4(applyFog(sky + kSunColor * sun, 1.0e30), 1.0);
}
