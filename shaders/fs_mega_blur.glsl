#version 330 core
// Mega-particles, depth-aware separable Gaussian blur (one axis per pass: uDirection (1, 0),
// then (0, 1)), which melts the spheres into one volume. Sigma = mega.blur_radius / 2 texels,
// taps out to 3 sigma. What it blurs (fs_mega_spheres.glsl):
//   colour sums (rgb x tau) and density (tau, normal.xy x tau): a weighted mean of every tap,
//     empty taps included, so the cloud's edge becomes a soft ramp and the normal stays
//     density-weighted (divided by tau when shading);
//   the nearest front depth: a mean over the taps that have one, weighted by their coverage
//     1 - exp(-tau), so an empty pixel next to the cloud gets the depth of the cloud beside it
//     (the composite needs a depth wherever there is smoke).
// Depth-aware: between two pixels that both have a depth, a tap's weight falls off as
// exp(-((d_tap - d) / (uDepthFalloff * d))^2), relative to the pixel's depth d, so a cloud far
// behind another one on screen does not bleed into it; a pixel without depth takes every tap.
//
// In:  uColor (rgb sums, depth), uDensity (tau, normal.xy x tau, 0). The first pass reads the
//      spheres pass's depth encoding (alpha = -depth, -65504 = none: uEncodedDepth 1); its output
//      holds depth as it is (0 = none).
// FX_MEGA_SHADE (the second pass): the blurred result is given fractal detail and light
// (mega_shade.glsl) and written as the finished cloud: premultiplied colour, and its depth.
uniform sampler2D uColor;
uniform sampler2D uDensity;
uniform int uEncodedDepth;
uniform ivec2 uDirection;
uniform int uTaps;               // taps each side (0 = copy), at most 48
// The Gaussian's weight of a tap i texels away, exp(-i^2 / (2 sigma^2)), for i = 0..uTaps:
// worked out once per draw (MegaPasses.cpp), not as an exp per tap of every texel.
uniform float uTapWeight[49];
uniform float uDepthFalloff;     // relative depth difference where the weight is 1/e

layout(location = 0) out vec4 oColor;
#ifdef FX_MEGA_SHADE
// The host's fog, at the cloud texel's depth (its front, which the composite's softness also
// measures from): here at the cloud's resolution, once per texel, not per tap of every
// full-resolution pixel of the composite. The upsample is linear in the colour, so the picture is
// the one the composite fogging each tap at its depth gave.
#include "particles_fog.glsl"
#include "mega_shade.glsl"
layout(location = 1) out vec4 oDepth;  // R32F: the cloud's depth, 0 where there is none
#else
layout(location = 1) out vec4 oDensity;
#endif

float depthOf(vec4 colour) {
    if (uEncodedDepth == 0) return colour.a;
    return colour.a > -60001.0 ? -colour.a : 0.0;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uColor, 0) - 1;
    float d0 = depthOf(texelFetch(uColor, p, 0));
    vec3 sumC = vec3(0.0);
    vec4 sumDensity = vec4(0.0);
    float sumW = 0.0, sumD = 0.0, sumDW = 0.0;
    for (int i = -uTaps; i <= uTaps; ++i) {
        ivec2 q = clamp(p + uDirection * i, ivec2(0), last);
        vec4 c = texelFetch(uColor, q, 0);
        vec4 density = texelFetch(uDensity, q, 0);
        float d = depthOf(c);
        float w = uTapWeight[abs(i)];
        if (d0 > 0.0 && d > 0.0) {
            float rel = (d - d0) / (uDepthFalloff * d0);
            w *= exp(-rel * rel);
        }
        sumC += w * c.rgb;
        sumDensity += w * density;
        sumW += w;
        if (d > 0.0) {
            float wd = w * (1.0 - exp(-density.x));
            sumD += wd * d;
            sumDW += wd;
        }
    }
    sumW = max(sumW, 1e-6);
    vec4 colour = vec4(sumC / sumW, sumDW > 1e-6 ? sumD / sumDW : 0.0);
    vec4 density = sumDensity / sumW;
#ifdef FX_MEGA_SHADE
    oColor = megaShade(colour, density, p, last);
    if (oColor.a > 0.0) oColor = applyFog(oColor, colour.a);
    oDepth = vec4(oColor.a > 0.0 ? colour.a : 0.0);
#else
    oColor = colour;
    oDensity = density;
#endif
}
