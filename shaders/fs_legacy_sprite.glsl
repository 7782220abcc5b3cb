// Unrotated, unanimated texture frame; straight alpha; no scene depth (hard edges where the
// quad would meet geometry, which is why the old system kept sprites hovering above the ground).
// Fogged as the scene is (common.glsl applyFog: straight alpha, so only the colour takes the fog).
#include "common.glsl"
uniform sampler2D uAtlas;
uniform vec3 uTint;

in vec2 vUV;
in float vAlpha;
in float vEyeDepth;
layout(location = 0) out vec4 oColor;

void main() {
    vec4 t = texture(uAtlas, vUV);
    oColor = vec4(applyFog(uTint * t.rgb, vEyeDepth), t.a * vAlpha);
}
