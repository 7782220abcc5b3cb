#version 330 core
// The smoke's opacity map (SmokeOpacityMap.h): every shadow-casting particle drawn as a
// billboard facing the sun (vs_particles with the light's view and projection) into an RGBA16F
// target with additive blending. Channel k collects the opacity of the particles that lie
// before the slice boundary (k + 1) / 4 of light depth, so each channel is the optical depth
// (in units of opacity) from the sun down to that boundary. A particle is spread linearly over
// the quarter-slice around its depth instead of being switched at the boundary, so smoke that
// drifts through a boundary darkens what is below it gradually (no popping).
#include "particles_common.glsl"
#include "particles_varyings.glsl"

uniform vec2 uDepthRange;  // light-view distance (metres) of light depth 0 and 1

layout(location = 0) out vec4 oOpacity;

void main() {
    float opacity = texture(uAtlas, vAtlasUV).a * insideFrame(vLocal) * vOpacity;
    float depth = (-vViewPos.z - uDepthRange.x) / (uDepthRange.y - uDepthRange.x);
    vec4 share = clamp((vec4(0.25, 0.5, 0.75, 1.0) - depth) * 4.0 + 0.5, 0.0, 1.0);
    oOpacity = opacity * share;
}
