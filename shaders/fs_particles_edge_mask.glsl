#version 330 core
// Mixed-resolution particles, step 3a (QuarterResPath::beginEdges): the edge mask as depth in the
// full-res edge target's own z-buffer. Edge pixels (particles_mixed_edge.glsl) get uPassDepth, a
// value every particle fragment passes the redraw's depth test against (1 for LEQUAL, 0 for
// GEQUAL under reversed-Z); the others uFailDepth, which none passes. The redraw then runs the
// particle programs on edge pixels only: with depth writes off the rejection happens before the
// fragment shader, so the cost follows the edge pixels, not the smoke's area. No colour is
// written.
uniform sampler2D uHalfDepth;   // red: min depth per 2x2 block (RG32F, green the max)
uniform sampler2D uSceneDepth;  // full-res scene depth (particles_scene_depth.glsl)
uniform float uDepthThreshold;
uniform float uPassDepth;
uniform float uFailDepth;

#include "particles_mixed_edge.glsl"

void main() {
    ivec2 taps[4];
    float weights[4];
    vec2 pixel = viewPixelOf(gl_FragCoord.xy);  // the edge target is the view's own: uDrawOrigin 0
    particlesFootprint(pixel, sceneDepthViewSize(), textureSize(uHalfDepth, 0), taps, weights);
    float full = particlesFullDepth(uSceneDepth, pixel);
    gl_FragDepth = particlesIsEdge(uHalfDepth, taps, full, uDepthThreshold) ? uPassDepth : uFailDepth;
}
