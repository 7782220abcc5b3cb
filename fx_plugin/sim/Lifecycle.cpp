#include "Lifecycle.h"

#include <cmath>

namespace fx {

namespace {

// Where t falls among `count` >= 1 keys sorted by t: between keys[lo] and keys[hi] at weight w
// of keys[hi]. Before the first key and past the last, lo == hi (that key's value holds); a
// non-finite t reads as 0.
struct Segment {
    int lo, hi;
    float w;
};

template <class Key>
Segment findSegment(const Key* keys, int count, float t) {
    if (!std::isfinite(t)) t = 0.0f;
    if (t <= keys[0].t) return {0, 0, 0.0f};
    for (int i = 1; i < count; ++i) {
        if (t <= keys[i].t) {
            const float span = keys[i].t - keys[i - 1].t;
            // span == 0 is a hard step: the later key wins from its t on.
            return {i - 1, i, span > 0.0f ? (t - keys[i - 1].t) / span : 1.0f};
        }
    }
    return {count - 1, count - 1, 0.0f};
}

}  // namespace

glm::vec4 evalColorRamp(const ColorStop* stops, int count, float t) {
    if (count <= 0 || !stops) return glm::vec4(1.0f);
    const Segment s = findSegment(stops, count, t);
    if (s.lo == s.hi) return stops[s.lo].rgba;
    return glm::mix(stops[s.lo].rgba, stops[s.hi].rgba, s.w);
}

float evalCurve(const std::vector<CurvePoint>& curve, float f, float fallback) {
    if (curve.empty()) return fallback;
    const Segment s = findSegment(curve.data(), static_cast<int>(curve.size()), f);
    if (s.lo == s.hi) return curve[s.lo].v;
    return curve[s.lo].v + (curve[s.hi].v - curve[s.lo].v) * s.w;
}

void bakeColorRamp(const std::vector<ColorStop>& stops, int texels, float* rgbaOut) {
    for (int i = 0; i < texels; ++i) {
        const float t = texels > 1 ? static_cast<float>(i) / static_cast<float>(texels - 1) : 0.0f;
        const glm::vec4 c = evalColorRamp(stops, t);
        for (int k = 0; k < 4; ++k) rgbaOut[4 * i + k] = c[k];
    }
}

}  // namespace fx
