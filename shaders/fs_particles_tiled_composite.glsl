#version 330 core
// The tiled path's result onto sceneColor (fx_plugin/render/TiledPath.h): cs_particles_tiled wrote
// each covered pixel's premultiplied smoke (alpha = 1 - transmittance) into uAccum; drawn over the
// tiles that hold particles, blended (ONE, ONE_MINUS_SRC_ALPHA). A pixel with no smoke is
// discarded (its blend would change nothing).
uniform sampler2D uAccum;   // RGBA16F, the view's pixels from (0, 0)
uniform ivec2 uDrawOrigin;  // the view's pixel (0, 0) in sceneColor

layout(location = 0) out vec4 oColor;

void main() {
    vec4 c = texelFetch(uAccum, ivec2(gl_FragCoord.xy) - uDrawOrigin, 0);
    if (c == vec4(0.0)) discard;
    oColor = c;
}
