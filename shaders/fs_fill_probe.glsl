#version 330 core
// A trivial textured, alpha-blended write: one fetch, nothing else (the physical limit of a
// particle pass).
uniform sampler2D uTex;
in vec2 vUv;
layout(location = 0) out vec4 oColor;
void main() { oColor = texture(uTex, vUv); }
