// Copies a texture into a viewport rectangle (mirror inset). uFlipX mirrors it horizontally.
uniform sampler2D uSource;
uniform float uFlipX;

in vec2 vUV;
layout(location = 0) out vec4 oColor;

void main() {
    vec2 uv = vec2(mix(vUV.x, 1.0 - vUV.x, uFlipX), vUV.y);
    oColor = vec4(texture(uSource, uv).rgb, 1.0);
}
