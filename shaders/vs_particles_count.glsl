#version 330 core
// Fade classification, counted (Plugin::setFadeClassCounting): one point per particle into a
// 1 x 1 RGBA32F target, blended (ONE, ONE): channel k gains 1 for each particle of class k
// (particles_classify.glsl), with the same function and inputs the particle draw used.
#include "particles_common.glsl"
#include "particles_classify.glsl"

layout(location = 1) in vec4 aPosSize;  // centre (world, m), size (m)

uniform int uSphere;  // 1: spherical billboards

flat out vec4 vClass;

void main() {
    vec3 centre = (uView * vec4(aPosSize.xyz, 1.0)).xyz;
    int c = fadeClass(centre, 0.5 * aPosSize.w, uSphere != 0, uSoftScale);
    vClass = vec4(c == kFadeNeeded ? 1.0 : 0.0, c == kInFront ? 1.0 : 0.0, c == kHidden ? 1.0 : 0.0, 0.0);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
