#pragma once
// How a host's z-buffer maps distance, and its inversion back to linear view depth. Pure maths,
// no GL: the particle shaders (SceneDepthSource.h) and DepthLinearizer's linearise pass evaluate
// the coefficients built here (linearDepthOf()'s inversion) per pixel, and the z-tested passes
// take their compare direction from conventionOf().
//
// The inversion. A right-handed view (camera looks down -Z; the C layer converts left-handed
// hosts with view' = F view, proj' = proj F, F = diag(1, 1, -1, 1)), any projection P (glm,
// column-major, P[col][row]). A point at distance t along the view direction has view z = -t, so
//     ndc(t) = (P[2][2] (-t) + P[3][2]) / (P[2][3] (-t) + P[3][3])
//     t(ndc) = (P[3][2] - ndc P[3][3]) / (P[2][2] - ndc P[2][3])
// (x and y do not enter: every projection a host meets has P[0][2] = P[1][2] = P[0][3] = P[1][3]
// = 0; an off-centre frustum moves P[2][0], P[2][1], which only shift x, y). Window depth d from
// ndc, with the depth range [n, f] (glDepthRange; n > f allowed):
//     GL clip control (-1..1):  d = n + (f - n) (ndc + 1) / 2  ->  ndc = 2 (d - n) / (f - n) - 1
//     ZERO_TO_ONE:              d = n + (f - n) ndc            ->  ndc = (d - n) / (f - n)
// Write ndc = s d + o; then t = (A + B d) / (C + D d) with
//     A = P[3][2] - o P[3][3],  B = -s P[3][3],  C = P[2][2] - o P[2][3],  D = -s P[2][3].
// This covers every convention with one formula: GL [-1, 1] perspective (d = f/(f-n) (1 - n/t)
// with the default range), a D3D-style [0, 1] matrix drawn with GL's clip control (Irrlicht 1.8:
// window depth 0.5 + 0.5 ndc, in [0.5, 1]), ZERO_TO_ONE, reversed-Z (near at window depth 1), an
// infinite far plane (P[2][2] = -1 or 0: t = 2n / (1 - ndc) or n / ndc) and orthographic matrices
// (P[2][3] = 0, P[3][3] = 1: t affine in d). The coefficients are built in double; the shader
// evaluates them in float (reversed-Z infinite: t = n / d, exact to float rounding).
//
// Depth precision (window depth error -> distance error dt = |dt/dd| * dd, at distance t, near n,
// far f, f >> n; GL perspective, default range, where |dt/dd| = t^2 (f - n) / (f n) ~ t^2 / n):
//   16-bit unorm (rounding 1/2 of 1/65535 = 7.6e-6):  dt ~ 7.6e-6 t^2 / n
//                 n = 0.1 m: 7.6 mm at 10 m, 0.76 m at 100 m; n = 0.5 m: 1.5 mm at 10 m
//   24-bit unorm (1/2 of 1/16777215 = 3.0e-8):        dt ~ 3.0e-8 t^2 / n
//                 n = 0.1 m: 0.03 mm at 10 m, 3.0 mm at 100 m
//   32-bit float, standard (d near 1: half an ulp of [0.5, 1) = 3.0e-8): as 24-bit
//   32-bit float, reversed-Z (d = n / t, relative rounding 6e-8): dt ~ 6e-8 t, 6 um at 100 m
//   A D3D-style [0, 1] matrix drawn with GL's clip control uses only window depths [0.5, 1]: |dt/dd|
//   doubles, one bit of the buffer is lost. Orthographic: dt = (far - near) * rounding, uniform.
// The linearise pass adds float arithmetic on top (relative ~1e-6 of t).
#include <glm/glm.hpp>

#include "fx/Types.h"

namespace fx {

/// Where a pass reads the scene depth: pixels [x0, x1) x [y0, y1) of the view, or all of it
/// (the immediate path copies and linearises only the union of what its passes read).
struct DepthRegion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool whole = true;
};

/// How the host's window depth relates to its clip-space z when it drew the z-buffer.
/// Defaults: GL's own: clip z in [-w, w] (glClipControl GL_NEGATIVE_ONE_TO_ONE) and
/// glDepthRange(0, 1).
struct DepthMapping {
    bool clipZeroToOne = false;  ///< glClipControl(..., GL_ZERO_TO_ONE) was in effect
    float rangeNear = 0.0f;      ///< glDepthRange's near (window depth of ndc -1, or 0 for ZERO_TO_ONE)
    float rangeFar = 1.0f;       ///< glDepthRange's far (window depth of ndc +1); may be < rangeNear
};

/// Linear view depth from window depth d: t = (a + b d) / (c + d_ d), metres along the view
/// direction. `farWindow` is the window depth the far plane (or, with an infinite far plane, the
/// limit t -> infinity) maps to: a texel at it or beyond (farther than it in the buffer's
/// direction) is "nothing drawn", as is one that gives t <= 0 or not finite.
struct LinearizeCoefficients {
    float a = 0.0f, b = 0.0f, c = 1.0f, d = 0.0f;
    float farWindow = 1.0f;
    bool reversed = false;  ///< window depth falls with distance (conventionOf() == ReversedZ)
};

/// Window depth of distance `t` (> 0) under `proj` and `mapping`, in double.
double windowDepthOf(const glm::mat4& proj, const DepthMapping& mapping, double t);
/// The inversion above, in double (the reference the tests and the tolerances use).
double linearDepthOf(const glm::mat4& proj, const DepthMapping& mapping, double windowDepth);
/// |dt / dd| at distance t: metres per unit of window depth (for error bounds).
double depthSlope(const glm::mat4& proj, const DepthMapping& mapping, double t);

/// The linearise pass's coefficients (an infinite far plane's farWindow is the limit of the
/// window depth as t -> infinity, which is where its cleared buffer sits too).
LinearizeCoefficients linearizeCoefficients(const glm::mat4& proj, const DepthMapping& mapping);

/// ReversedZ when the near plane lands at a larger window depth than the far plane (so the
/// z-tested passes compare GEQUAL), else Standard. Decided from the matrix and the mapping alone:
/// a D3D-style matrix, a reversed depth range and a reversed matrix all come out right.
DepthConvention conventionOf(const glm::mat4& proj, const DepthMapping& mapping);

/// False for a mapping no GL can have (non-finite, outside [0, 1], or rangeNear == rangeFar) or a
/// projection that does not tell distance apart (P[2][2] - ndc P[2][3] constant zero).
bool validDepthMapping(const glm::mat4& proj, const DepthMapping& mapping);

}  // namespace fx
