#pragma once
// The clip volume of a view, for culling particles by their bounding sphere. Tested in view
// space: the four side planes come from the projection matrix (Gribb & Hartmann, normalised,
// pointing inwards), near and far are the view's clip distances themselves. Extracting near/far
// from proj * view instead loses them to float rounding at a 1e7 far/near ratio.
#include <cmath>

#include <glm/glm.hpp>

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
    }

    /// True when the sphere (world space) reaches into the frustum; conservative near the
    /// corners. A non-finite centre or radius is outside.
    bool intersectsSphere(const glm::vec3& centre, float radius) const {
        if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z) ||
            !std::isfinite(radius)) {
            return false;
        }
        const glm::vec3 v = glm::vec3(view_ * glm::vec4(centre, 1.0f));
        const float depth = -v.z;
        if (depth + radius < near_ || depth - radius > far_) return false;
        for (const glm::vec4& p : sides_) {
            if (glm::dot(glm::vec3(p), v) + p.w < -radius) return false;
        }
        return true;
    }

private:
    glm::mat4 view_;
    glm::vec4 sides_[4];
    float near_, far_;
};

/// |x/depth| and |y/depth| slightly past the frustum edges, from a perspective projection (the
/// particle vertex shaders' uSlopeMax).
inline glm::vec2 frustumSlopes(const glm::mat4& proj) {
    const float sx = (1.0f + std::fabs(proj[2][0])) / std::fmax(std::fabs(proj[0][0]), 1e-6f);
    const float sy = (1.0f + std::fabs(proj[2][1])) / std::fmax(std::fabs(proj[1][1]), 1e-6f);
    return glm::vec2(sx, sy) * 1.02f;
}

}  // namespace fx
