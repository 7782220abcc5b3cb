// Legacy smoke: quads already aligned to the view plane on the CPU (the old CUBE way).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec2 aUV;
layout(location = 2) in float aAlpha;

uniform mat4 uViewProj;

out vec2 vUV;
out float vAlpha;
out float vEyeDepth;  // -z_eye: a perspective projection's clip w

void main() {
    vUV = aUV;
    vAlpha = aAlpha;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
    vEyeDepth = gl_Position.w;
}
