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
uniform float uReversed;     // +1: window depth grows with distance, -1: it falls (reversed)
uniform float uBackground;
uniform vec2 uInvSize;       // 1 / uDepth's size in pixels (the view's, or the framebuffer's)
uniform vec2 uTexelOrigin;   // uDepth's texel of the view's pixel (0, 0): 0, or the view's origin
                             // in a depth texture of the whole framebuffer (SceneDepthSource.h)

layout(location = 0) out vec4 oDepth;

void main() {
    // textureLod at the texel centre through HostDepth's nearest sampler: the texel texelFetch
    // gives, cheaper on llvmpipe, which bounds-checks every texelFetch lane (particles_common.glsl).
    float d = textureLod(uDepth, (gl_FragCoord.xy + uTexelOrigin) * uInvSize, 0.0).r;
    float t = (uCoeffs.x + uCoeffs.y * d) / (uCoeffs.z + uCoeffs.w * d);
    // (d - far) has the sign of "beyond the far plane" times uReversed's sign: one compare.
    bool drawn = (d - uFarWindow) * uReversed < 0.0 && t > 0.0 && t < 3.0e38;
    oDepth = vec4(drawn ? t : uBackground, 0.0, 0.0, 0.0);
}
