#version 330 core
// One triangle covering the bound target (quarter-res downsample and composite); no vertex
// buffer: positions come from gl_VertexID. The fragment shaders work from gl_FragCoord.
void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
