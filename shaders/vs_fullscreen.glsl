// One triangle covering the viewport; no vertex buffer needed (gl_VertexID).
out vec2 vUV;

uniform float uDepth;  // clip-space z of the triangle (1.0 = far plane, for the sky)

void main() {
    vec2 p = vec2((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0);
    vUV = p * 0.5 + 0.5;
    gl_Position = vec4(p, uDepth, 1.0);
}
