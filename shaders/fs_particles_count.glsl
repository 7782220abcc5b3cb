#version 330 core
// Fade classification, counted: see vs_particles_count.glsl.
flat in vec4 vClass;
layout(location = 0) out vec4 oCount;

void main() {
    oCount = vClass;
}
