// The inversion of DepthMapping.h, in double.
#include "DepthMapping.h"

#include <cmath>

namespace fx {

namespace {

struct Affine {
    double s = 1.0, o = 0.0;  ///< ndc = s d + o
};

Affine ndcOfWindow(const DepthMapping& m) {
    const double n = m.rangeNear, f = m.rangeFar;
    Affine a;
    if (m.clipZeroToOne) {
        a.s = 1.0 / (f - n);
        a.o = -n / (f - n);
    } else {
        a.s = 2.0 / (f - n);
        a.o = -2.0 * n / (f - n) - 1.0;
    }
    return a;
}

struct Coeffs {
    double a, b, c, d;
};

Coeffs coeffs(const glm::mat4& p, const DepthMapping& m) {
    const Affine w = ndcOfWindow(m);
    const double p22 = p[2][2], p23 = p[2][3], p32 = p[3][2], p33 = p[3][3];
    return {p32 - w.o * p33, -w.s * p33, p22 - w.o * p23, -w.s * p23};
}

// d ndc / dt has the sign of this for every t in front of the camera (w > 0).
double ndcGrowth(const glm::mat4& p) { return double(p[2][3]) * p[3][2] - double(p[2][2]) * p[3][3]; }

}  // namespace

double windowDepthOf(const glm::mat4& p, const DepthMapping& m, double t) {
    const double ndc = (-double(p[2][2]) * t + p[3][2]) / (-double(p[2][3]) * t + p[3][3]);
    const Affine w = ndcOfWindow(m);
    return (ndc - w.o) / w.s;
}

double linearDepthOf(const glm::mat4& p, const DepthMapping& m, double d) {
    const Coeffs k = coeffs(p, m);
    return (k.a + k.b * d) / (k.c + k.d * d);
}

double depthSlope(const glm::mat4& p, const DepthMapping& m, double t) {
    const Coeffs k = coeffs(p, m);
    const double d = windowDepthOf(p, m, t);
    const double den = k.c + k.d * d;
    return std::abs((k.b * k.c - k.a * k.d) / (den * den));
}

LinearizeCoefficients linearizeCoefficients(const glm::mat4& p, const DepthMapping& m) {
    const Coeffs k = coeffs(p, m);
    LinearizeCoefficients out;
    out.a = float(k.a);
    out.b = float(k.b);
    out.c = float(k.c);
    out.d = float(k.d);
    // The far side of the clip volume: where the far plane (or an infinite one's limit) lands,
    // and what a cleared buffer holds.
    const bool ndcFalls = ndcGrowth(p) < 0.0;
    const double ndcFar = ndcFalls ? (m.clipZeroToOne ? 0.0 : -1.0) : 1.0;
    const Affine w = ndcOfWindow(m);
    out.farWindow = float((ndcFar - w.o) / w.s);
    out.reversed = conventionOf(p, m) == DepthConvention::ReversedZ;
    return out;
}

DepthConvention conventionOf(const glm::mat4& p, const DepthMapping& m) {
    const double windowGrowth = ndcGrowth(p) * (double(m.rangeFar) - double(m.rangeNear));
    return windowGrowth < 0.0 ? DepthConvention::ReversedZ : DepthConvention::Standard;
}

bool validDepthMapping(const glm::mat4& p, const DepthMapping& m) {
    const auto inUnit = [](float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; };
    if (!inUnit(m.rangeNear) || !inUnit(m.rangeFar) || m.rangeNear == m.rangeFar) return false;
    const double g = ndcGrowth(p);
    return std::isfinite(g) && g != 0.0;
}

}  // namespace fx
