// Scene geometry for the opaque pass and the depth prepass. Both passes use this one vertex
// shader with `invariant` so the prepass z-buffer matches the opaque pass bit for bit, which is
// what makes depth test EQUAL (prepass-EQUAL) draw exactly the same pixels as LESS.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModel;
uniform mat4 uView;
uniform mat4 uProj;

out vec3 vNormal;
out vec3 vViewPos;
out vec3 vWorldPos;

invariant gl_Position;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec4 viewPos = uView * world;
    vViewPos = viewPos.xyz;
    vWorldPos = world.xyz;
    vNormal = mat3(uModel) * aNormal;
    gl_Position = uProj * viewPos;
}
