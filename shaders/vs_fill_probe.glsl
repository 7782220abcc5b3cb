#version 330 core
// fxbench's fill-rate probe (render/FillRateProbe): quads in pixels, origin bottom-left.
layout(location = 0) in vec2 aPos;
uniform vec2 uViewSize;
out vec2 vUv;
void main() {
    vUv = aPos / 64.0;
    gl_Position = vec4(aPos / uViewSize * 2.0 - 1.0, 0.0, 1.0);
}
