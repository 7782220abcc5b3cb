#version 330 core
// Stateless particles: a soft-edged streak, added to the scene (blend ONE, ONE: order-independent,
// never sorted). The output is premultiplied by the coverage and the life alpha.
in vec2 vLocal;
flat in vec4 vColor;

layout(location = 0) out vec4 oColor;

void main() {
    // Bright core, soft rim across the streak; tapered ends along it.
    float across = 1.0 - smoothstep(0.3, 1.0, abs(vLocal.y));
    float along = 1.0 - smoothstep(0.6, 1.0, abs(vLocal.x));
    float a = vColor.a * across * along;
    oColor = vec4(vColor.rgb * a, a);
}
