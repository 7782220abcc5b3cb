#pragma once
// How a particle looks over its life fraction f = age / lifetime in [0, 1]: size growth, alpha
// fade and colour. Shared by the simulation (which stores size and fade per particle for the
// renderer) and by anyone who wants the same curves elsewhere (a shader port, a tool).
#include <vector>

#include <glm/glm.hpp>

#include "reactions/ReactionDesc.h"

namespace fx {

/// Growth curve g(f) = 1 - (1 - f)^2: a puff expands fastest at birth and slows as it mixes
/// into the air (ease-out), g(0) = 0, g(1) = 1, g'(1) = 0.
inline float growthCurve(float f) {
    f = glm::clamp(f, 0.0f, 1.0f);
    const float r = 1.0f - f;
    return 1.0f - r * r;
}

/// Size at life fraction f: start + (end - start) * growthCurve(f).
inline float sizeAt(float startSize, float endSize, float f) {
    return startSize + (endSize - startSize) * growthCurve(f);
}

/// Alpha fade factor in [0, 1]: smoothstep up over the first `fadeIn` of life and smoothstep
/// down over the last `fadeOut` (C1, as 002's age-based fading asks); a zero span means no fade.
inline float fadeAt(float f, float fadeIn, float fadeOut) {
    f = glm::clamp(f, 0.0f, 1.0f);
    const float in = fadeIn > 0.0f ? glm::smoothstep(0.0f, fadeIn, f) : 1.0f;
    const float out = fadeOut > 0.0f ? glm::smoothstep(0.0f, fadeOut, 1.0f - f) : 1.0f;
    return in * out;
}

/// An over-life curve at life fraction f: piecewise linear, flat outside its points; `fallback`
/// when the curve is empty. Points must be in non-decreasing t (the loader guarantees it).
float evalCurve(const std::vector<CurvePoint>& curve, float f, float fallback);

/// The particle's size at f: sizeOverLife when the reaction gives one, else growthCurve.
inline float sizeAt(const ParticleDesc& p, float startSize, float endSize, float f) {
    if (p.sizeOverLife.empty()) return sizeAt(startSize, endSize, f);
    return startSize + (endSize - startSize) * evalCurve(p.sizeOverLife, f, 0.0f);
}

/// The particle's alpha factor at f: alphaOverLife when given, else the fade_in/out smoothsteps.
inline float fadeAt(const ParticleDesc& p, float f) {
    if (p.alphaOverLife.empty()) return fadeAt(f, p.fadeIn, p.fadeOut);
    return evalCurve(p.alphaOverLife, f, 1.0f);
}

/// The colour ramp at life fraction t, piecewise linear between stops; before the first stop
/// the first colour, after the last the last. Stops must be in non-decreasing t (the loader
/// guarantees it); an empty ramp is opaque white. Equal t values make a hard step.
glm::vec4 evalColorRamp(const ColorStop* stops, int count, float t);
inline glm::vec4 evalColorRamp(const std::vector<ColorStop>& stops, float t) {
    return evalColorRamp(stops.data(), static_cast<int>(stops.size()), t);
}

/// Samples the ramp at `texels` evenly spaced t = i / (texels - 1), into RGBA floats (4 per
/// texel): what a renderer uploads as a 1D lookup texture.
void bakeColorRamp(const std::vector<ColorStop>& stops, int texels, float* rgbaOut);

}  // namespace fx
