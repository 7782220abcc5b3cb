// The scene depth as every pass that reads it sees it: linear view depth in metres, from either
// form a host hands over (fx_plugin/render/SceneDepthSource.h decides which, per view):
//   - the z-buffer the opaque scene was drawn into (window depth d in .r of a depth texture,
//     read without comparison): t = (A + B d) / (C + D d), the inversion DepthMapping.h derives
//     for every convention (GL or [0, 1] clip z, depth range, reversed-Z, infinite far,
//     orthographic). No linearise pass and no second colour target: the fragment decodes it.
//   - linear R32F metres (FrameBuilder::sceneDepth): A = 0, B = 1, C = 1, D = 0, so t = d exactly.
// A cleared z-buffer texel reads as the far plane's distance; a distance that is not positive,
// not finite or past 3.0e38 reads as 3.0e38, "nothing drawn" (a linear host may clear to 0:
// fx/HostAdapter.h).
uniform vec4 uDepthCoeffs;  // A, B, C, D
// Where the view lies (fx_plugin/render/SceneDepthSource.h): a pass addresses the scene depth by
// the view's own pixel p = gl_FragCoord.xy - uDrawOrigin and reads texel p + uDepthWindow.xy.
// uDrawOrigin: the view's origin in the framebuffer being drawn (sceneColor's viewport origin, or
// 0 in the plugin's own targets). uDepthWindow.xy: 0 for a depth texture of the view's size (the
// plugin's copy), the view's origin for one of the whole framebuffer (the host's z-buffer).
// uDepthWindow.zw: the view's size, which bounds the full-screen passes (not the texture's size).
uniform ivec4 uDepthWindow;
uniform ivec2 uDrawOrigin;

// The view's pixel under a fragment of the target being drawn.
vec2 viewPixelOf(vec2 fragCoord) { return fragCoord - vec2(uDrawOrigin); }
// The scene depth texel of the view's pixel p.
ivec2 sceneDepthTexel(ivec2 p) { return p + uDepthWindow.xy; }
ivec2 sceneDepthViewSize() { return uDepthWindow.zw; }

// The quotient alone, for a reader that makes its own range check (sceneDepthAt).
float decodedSceneDepth(float d) {
    return (uDepthCoeffs.x + uDepthCoeffs.y * d) / (uDepthCoeffs.z + uDepthCoeffs.w * d);
}
float linearSceneDepth(float d) {
    float t = decodedSceneDepth(d);
    // A cleared z-buffer texel (at the far plane) decodes to the far plane's distance (or, with an
    // infinite far plane, to a huge or infinite one), which every reader takes as far away, as
    // the linearise pass's background was; only a distance that is not positive needs the
    // stand-in (a linear host that clears to 0; a window depth past the far side).
    return t > 0.0 && t < 3.0e38 ? t : 3.0e38;  // NaN and infinity too
}
