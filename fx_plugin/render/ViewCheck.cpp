#include "ViewCheck.h"

#include <cmath>

namespace fx {
namespace {

bool finiteMatrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

}  // namespace

std::string viewProblem(const ViewInfo& view) {
    std::string bad;
    if (view.width <= 0 || view.height <= 0) {
        bad = "size " + std::to_string(view.width) + "x" + std::to_string(view.height) +
              "; expected width and height > 0";
    } else if (!std::isfinite(view.nearPlane) || !std::isfinite(view.farPlane) ||
               !(view.nearPlane > 0.0f) || !(view.farPlane > view.nearPlane)) {
        bad = "near " + std::to_string(view.nearPlane) + ", far " + std::to_string(view.farPlane) +
              "; expected 0 < near < far, both finite";
    } else if (!finiteMatrix(view.view) || !finiteMatrix(view.proj) || !std::isfinite(view.eye.x) ||
               !std::isfinite(view.eye.y) || !std::isfinite(view.eye.z)) {
        bad = "non-finite view or projection matrix or eye; expected finite values";
    } else if (static_cast<uint8_t>(view.depth) > static_cast<uint8_t>(DepthConvention::ReversedZ)) {
        bad = "depth convention " + std::to_string(static_cast<int>(view.depth)) +
              "; expected Standard or ReversedZ";
    } else if (static_cast<uint8_t>(view.fog.mode) > static_cast<uint8_t>(Fog::Mode::Exp2)) {
        bad = "fog mode " + std::to_string(static_cast<int>(view.fog.mode)) + "; expected Off, Linear, Exp or Exp2";
    } else if (view.fog.on() &&
               (!std::isfinite(view.fog.color.x) || !std::isfinite(view.fog.color.y) ||
                !std::isfinite(view.fog.color.z) || !std::isfinite(view.fog.start) || !std::isfinite(view.fog.end) ||
                !std::isfinite(view.fog.density) || !(view.fog.density >= 0.0f))) {
        bad = "fog: non-finite value or negative density; expected finite values, density >= 0";
    } else if (view.fog.mode == Fog::Mode::Linear && view.fog.end == view.fog.start) {
        bad = "linear fog with start = end = " + std::to_string(view.fog.start) + "; expected end != start";
    } else if (!std::isfinite(view.slice.minDistance) || !(view.slice.minDistance >= 0.0f) ||
               !(view.slice.maxDistance == 0.0f || view.slice.maxDistance > view.slice.minDistance)) {
        bad = "slice [" + std::to_string(view.slice.minDistance) + ", " + std::to_string(view.slice.maxDistance) +
              "); expected minDistance >= 0 finite and maxDistance 0 (no bound) or > minDistance";
    }
    return bad;
}

}  // namespace fx
