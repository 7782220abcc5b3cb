#version 330 core
// The host's z-buffer (a depth texture of any format, or the plugin's copy of the bound
// framebuffer's) into the linear view depth the particle passes read (R32F metres, what
// FrameBuilder::sceneDepth() holds). One texel per pixel, no filtering. The coefficients come
// from fx_plugin/render/DepthMapping.h, which derives them for every convention (GL or [0, 1]
// clip z, depth range, reversed-Z, infinite far, orthographic):
//   t = (A + B d) / (C + D d)
// A texel at the far side of the clip volume (a cleared buffer) or past it, or one that gives no
// positive finite distance, is "nothing drawn": it gets uBackground (the view's far plane, which
// the particle shaders read like a host's cleared linear depth).
uniform sampler2D uDepth;    // window depth in .r (a depth texture read without comparison)
uniform vec4 uCoeffs;        // A, B, C, D
uniform float uFarWindow;    // window depth of the far plane (or of an infinite one's limit)
uniform float uReversed;     // 1: window depth falls with distance
uniform float uBackground;

layout(location = 0) out vec4 oDepth;

void main() {
    float d = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r;
    float t = (uCoeffs.x + uCoeffs.y * d) / (uCoeffs.z + uCoeffs.w * d);
    bool beyond = uReversed > 0.5 ? d <= uFarWindow : d >= uFarWindow;
    // isinf/isnan need no extension in 330; t > 0.0 is false for NaN.
    bool drawn = !beyond && t > 0.0 && !isinf(t);
    oDepth = vec4(drawn ? t : uBackground, 0.0, 0.0, 0.0);
}
