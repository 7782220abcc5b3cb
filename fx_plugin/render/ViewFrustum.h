#pragma once
// The clip volume of a view, for culling particles by their bounding sphere. Tested in view
// space: the four side planes come from the projection matrix (Gribb & Hartmann, normalised,
// pointing inwards), near and far are the view's clip distances themselves. Extracting near/far
// from proj * view instead loses them to float rounding at a 1e7 far/near ratio.
#include <cmath>

#include <glm/glm.hpp>

#include "base/Sse2.h"

namespace fx {

class ViewFrustum {
public:
    ViewFrustum(const glm::mat4& view, const glm::mat4& proj, float nearPlane, float farPlane)
        : view_(view), near_(nearPlane), far_(farPlane) {
        const glm::mat4 rows = glm::transpose(proj);  // rows[i] = row i of proj
        sides_[0] = rows[3] + rows[0];  // left
        sides_[1] = rows[3] - rows[0];  // right
        sides_[2] = rows[3] + rows[1];  // bottom
        sides_[3] = rows[3] - rows[1];  // top
        for (glm::vec4& p : sides_) {
            const float len = glm::length(glm::vec3(p));
            if (len > 0.0f) p /= len;
        }
#if FX_SSE2
        for (int row = 0; row < 3; ++row) {
            for (int col = 0; col < 4; ++col) lanes_.view[row][col] = _mm_set1_ps(view_[col][row]);
        }
        for (int side = 0; side < 4; ++side) {
            for (int c = 0; c < 4; ++c) lanes_.sides[side][c] = _mm_set1_ps(sides_[side][c]);
        }
        lanes_.nearPlane = _mm_set1_ps(near_);
        lanes_.farPlane = _mm_set1_ps(far_);
#endif
    }

    /// True when the sphere (world space) reaches into the frustum; conservative near the
    /// corners. A non-finite centre or radius is outside.
    bool intersectsSphere(const glm::vec3& centre, float radius) const {
        if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z) ||
            !std::isfinite(radius)) {
            return false;
        }
        // In view space: row r of view_ times (centre, 1), as (V0 x + V1 y) + (V2 z + V3).
        glm::vec3 v;
        for (int r = 0; r < 3; ++r) {
            v[r] = (view_[0][r] * centre.x + view_[1][r] * centre.y) + (view_[2][r] * centre.z + view_[3][r]);
        }
        const float depth = -v.z;
        if (depth + radius < near_ || depth - radius > far_) return false;
        for (const glm::vec4& p : sides_) {
            if (((p.x * v.x + p.y * v.y) + p.z * v.z) + p.w < -radius) return false;
        }
        return true;
    }

#if FX_SSE2
    /// intersectsSphere of four spheres (centres x, y, z and radii r, a sphere a lane) as a mask,
    /// bit k for lane k: the same operations in the same order, so the same answers
    /// (DrawListOrderTest's FourSpheresAtATime... test). Inlined, with the matrices' entries and
    /// the planes broadcast once per frustum (lanes_): called for every four particles of the draw
    /// list's cull, it was a third of that cull as a call that broadcast 30 scalars each time
    /// (bench_draw BM_DrawListBuildJobs, perf).
    FX_LANES_INLINE int intersectsSpheres4(__m128 x, __m128 y, __m128 z, __m128 r) const {
        const __m128i exponent = _mm_set1_epi32(0x7f800000);
        auto infinite = [&](__m128 a) { return _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(a), exponent), exponent); };
        const int notFinite = _mm_movemask_ps(_mm_castsi128_ps(
            _mm_or_si128(_mm_or_si128(infinite(x), infinite(y)), _mm_or_si128(infinite(z), infinite(r)))));
        __m128 v[3];
        for (int row = 0; row < 3; ++row) {
            const __m128* m = lanes_.view[row];
            v[row] = _mm_add_ps(_mm_add_ps(_mm_mul_ps(m[0], x), _mm_mul_ps(m[1], y)), _mm_add_ps(_mm_mul_ps(m[2], z), m[3]));
        }
        const __m128 sign = _mm_set1_ps(-0.0f);
        const __m128 depth = _mm_xor_ps(v[2], sign), minusR = _mm_xor_ps(r, sign);
        __m128 out = _mm_or_ps(_mm_cmplt_ps(_mm_add_ps(depth, r), lanes_.nearPlane),
                               _mm_cmpgt_ps(_mm_sub_ps(depth, r), lanes_.farPlane));
        for (int side = 0; side < 4; ++side) {
            const __m128* p = lanes_.sides[side];
            const __m128 d = _mm_add_ps(
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(p[0], v[0]), _mm_mul_ps(p[1], v[1])), _mm_mul_ps(p[2], v[2])), p[3]);
            out = _mm_or_ps(out, _mm_cmplt_ps(d, minusR));
        }
        return ~(_mm_movemask_ps(out) | notFinite) & 15;
    }
#endif

private:
    glm::mat4 view_;
    glm::vec4 sides_[4];
    float near_, far_;
#if FX_SSE2
    struct Lanes {
        __m128 view[3][4];   ///< row r of view_, entry c, in every lane
        __m128 sides[4][4];  ///< plane p's x, y, z, w in every lane
        __m128 nearPlane, farPlane;
    } lanes_;
#endif
};

/// |x/depth| and |y/depth| slightly past the frustum edges, from a perspective projection (the
/// particle vertex shaders' uSlopeMax).
inline glm::vec2 frustumSlopes(const glm::mat4& proj) {
    const float sx = (1.0f + std::fabs(proj[2][0])) / std::fmax(std::fabs(proj[0][0]), 1e-6f);
    const float sy = (1.0f + std::fabs(proj[2][1])) / std::fmax(std::fabs(proj[1][1]), 1e-6f);
    return glm::vec2(sx, sy) * 1.02f;
}

}  // namespace fx
