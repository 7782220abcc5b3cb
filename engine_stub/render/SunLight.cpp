#include "render/SunLight.h"

#include <algorithm>
#include <cmath>

namespace cube {

bool validSunAngles(double azimuthDeg, double elevationDeg) {
    return std::isfinite(azimuthDeg) && std::isfinite(elevationDeg) && elevationDeg >= kMinSunElevationDeg &&
           elevationDeg <= kMaxSunElevationDeg;
}

SunLight sunFromAngles(double azimuthDeg, double elevationDeg) {
    constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
    const double az = std::remainder(std::isfinite(azimuthDeg) ? azimuthDeg : 0.0, 360.0) * kDegToRad;
    const double elDeg = std::clamp(std::isfinite(elevationDeg) ? elevationDeg : kDefaultSunElevationDeg,
                                    kMinSunElevationDeg, kMaxSunElevationDeg);
    const double el = elDeg * kDegToRad;
    SunLight s;
    s.toSun = glm::vec3(float(std::cos(el) * std::cos(az)), float(std::sin(el)), float(std::cos(el) * std::sin(az)));
    // Low sun: a longer path through the air reddens and dims the sun and the sky light with it.
    // u = 0 at 20 degrees and above (the default colours), 1 at the horizon.
    const float u = float(std::clamp((20.0 - elDeg) / 20.0, 0.0, 1.0));
    s.color = glm::mix(s.color, glm::vec3(1.00f, 0.55f, 0.28f), u);
    s.ambientSky = glm::mix(s.ambientSky, glm::vec3(0.30f, 0.30f, 0.38f), u);
    s.ambientGround = glm::mix(s.ambientGround, glm::vec3(0.15f, 0.12f, 0.10f), u);
    return s;
}

}  // namespace cube
