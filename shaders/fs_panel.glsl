// Tweak panel: vertex colour times the font atlas's coverage (an R8 texture; its white texel
// draws the solid shapes).
uniform sampler2D uAtlas;
in vec2 vUv;
in vec4 vColor;
layout(location = 0) out vec4 oColor;
void main() { oColor = vec4(vColor.rgb, vColor.a * texture(uAtlas, vUv).r); }
