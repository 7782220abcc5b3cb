#version 330 core
// Stateless particles: a soft-edged streak, added to the scene (blend ONE, ONE: order-independent,
// never sorted). The output is premultiplied by the coverage and the life alpha.
// Fogged as additive light (particles_fog.glsl); ViewInfo::slice keeps a spark only where its
// view distance lies in [uSlice.x, uSlice.y) (y 0: no bound; both 0: every spark), per spark as
// the billboards' draw list does per particle.
#include "particles_fog.glsl"
uniform vec2 uSlice;
in vec2 vLocal;
flat in vec4 vColor;
flat in float vDepth;

layout(location = 0) out vec4 oColor;

void main() {
    // Bright core, soft rim across the streak; tapered ends along it.
    float across = 1.0 - smoothstep(0.3, 1.0, abs(vLocal.y));
    float along = 1.0 - smoothstep(0.6, 1.0, abs(vLocal.x));
    float a = vColor.a * across * along;
    float inSlice = vDepth >= uSlice.x && (uSlice.y == 0.0 || vDepth < uSlice.y) ? 1.0 : 0.0;
    oColor = applyFogAdditive(vec4(vColor.rgb * a, a) * inSlice, vDepth);
}
