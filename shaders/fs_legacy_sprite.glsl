// Unrotated, unanimated texture frame; straight alpha; no scene depth (hard edges where the
// quad would meet geometry, which is why the old system kept sprites hovering above the ground).
uniform sampler2D uAtlas;
uniform vec3 uTint;

in vec2 vUV;
in float vAlpha;
layout(location = 0) out vec4 oColor;

void main() {
    vec4 t = texture(uAtlas, vUV);
    oColor = vec4(uTint * t.rgb, t.a * vAlpha);
}
