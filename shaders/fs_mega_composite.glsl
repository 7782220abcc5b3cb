#version 330 core
// Mega-particles, composite: the finished cloud (reduced resolution, premultiplied) onto the
// scene at full resolution, blended (ONE, ONE_MINUS_SRC_ALPHA).
//
// Depth-aware upsample: the four texels of the bilinear footprint, each kept only as far as the
// full-resolution scene depth lies behind that texel's cloud depth:
// saturate((scene - cloud) / render.softness). Geometry nearer than the cloud gets no smoke,
// however far the blur spread the cloud's edge over it (seed 001's caveat about fuzzy edges
// creeping over objects in front), and geometry just behind the cloud's front fades it softly.
// The cloud arrives fogged (fs_mega_blur.glsl, at each texel's cloud depth): the upsample only
// weighs it.
uniform sampler2D uCloud;       // RGBA16F premultiplied
uniform sampler2D uCloudDepth;  // R32F metres, 0 = no cloud
uniform sampler2D uSceneDepth;  // full resolution: the z-buffer or linear R32F
#include "particles_scene_depth.glsl"
uniform float uSoftScale;       // 1 / render.softness, 1/m
// The bilinear footprint as a line in gl_FragCoord, set once per draw (MegaPasses.cpp), as the
// quarter-res composite takes it: lowPos = p lowSize / viewSize - 0.5 for the view pixel p, in
// texels past the first tap's centre (the tap floor(lowPos), the weights lowPos - floor(lowPos)),
// with no size query, conversion or division per pixel.
uniform vec4 uLowMap;           // lowPos = gl_FragCoord.xy * xy + zw
uniform vec2 uInvLow;           // 1 / the cloud's size
uniform ivec2 uLowLast;         // the cloud's last texel

layout(location = 0) out vec4 oColor;

void main() {
    vec2 lowPos = gl_FragCoord.xy * uLowMap.xy + uLowMap.zw;
    vec2 corner = floor(lowPos);
    ivec2 base = ivec2(corner), last = uLowLast;
    vec2 f = lowPos - corner;
    // The four taps' cloud depths (t0 = base, t1 = +x, t2 = +y, t3 = +x+y, each clamped into the
    // image): one textureGather at the corner they share, through an edge-clamped sampler
    // (FX_GATHER: the context has ARB_texture_gather), else four texelFetch. A footprint without
    // cloud adds nothing: the pixel is discarded before its colour and scene-depth fetches.
#ifdef FX_GATHER
    vec4 cloud = textureGather(uCloudDepth, (corner + 1.0) * uInvLow).wzxy;
#else
    vec4 cloud;
    for (int i = 0; i < 4; ++i) cloud[i] = texelFetch(uCloudDepth, clamp(base + ivec2(i & 1, i >> 1), ivec2(0), last), 0).r;
#endif
    if (all(lessThanEqual(cloud, vec4(0.0)))) discard;
    float scene = linearSceneDepth(texelFetch(uSceneDepth, sceneDepthTexel(ivec2(viewPixelOf(gl_FragCoord.xy))), 0).r);  // nothing drawn: 3.0e38
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 tap = clamp(base + o, ivec2(0), last);
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        float visible = cloud[i] > 0.0 ? clamp((scene - cloud[i]) * uSoftScale, 0.0, 1.0) : 0.0;
        sum += (w * visible) * texelFetch(uCloud, tap, 0);
    }
    oColor = sum;
}
