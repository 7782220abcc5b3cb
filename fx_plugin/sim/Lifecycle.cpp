#include "Lifecycle.h"

#include <cmath>

namespace fx {

glm::vec4 evalColorRamp(const ColorStop* stops, int count, float t) {
    if (count <= 0 || !stops) return glm::vec4(1.0f);
    if (!std::isfinite(t)) t = 0.0f;
    if (t <= stops[0].t) return stops[0].rgba;
    for (int i = 1; i < count; ++i) {
        if (t <= stops[i].t) {
            const float span = stops[i].t - stops[i - 1].t;
            // span == 0 is a hard step: the later stop wins from its t on.
            const float w = span > 0.0f ? (t - stops[i - 1].t) / span : 1.0f;
            return glm::mix(stops[i - 1].rgba, stops[i].rgba, w);
        }
    }
    return stops[count - 1].rgba;
}

float evalCurve(const std::vector<CurvePoint>& curve, float f, float fallback) {
    const int count = static_cast<int>(curve.size());
    if (count == 0) return fallback;
    if (!std::isfinite(f)) f = 0.0f;
    if (f <= curve[0].t) return curve[0].v;
    for (int i = 1; i < count; ++i) {
        if (f <= curve[i].t) {
            const float span = curve[i].t - curve[i - 1].t;
            const float w = span > 0.0f ? (f - curve[i - 1].t) / span : 1.0f;
            return curve[i - 1].v + (curve[i].v - curve[i - 1].v) * w;
        }
    }
    return curve[count - 1].v;
}

void bakeColorRamp(const std::vector<ColorStop>& stops, int texels, float* rgbaOut) {
    for (int i = 0; i < texels; ++i) {
        const float t = texels > 1 ? static_cast<float>(i) / static_cast<float>(texels - 1) : 0.0f;
        const glm::vec4 c = evalColorRamp(stops, t);
        for (int k = 0; k < 4; ++k) rgbaOut[4 * i + k] = c[k];
    }
}

}  // namespace fx
