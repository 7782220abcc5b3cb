#pragma once
// The race scene's light: one sun and a sky/ground hemisphere ambient. The game holds one
// SunLight (Game::sun, from --sun or Game::setSun); the scene renderer lights the meshes and the
// sky with it (shaders/common.glsl) and SpecialFX hands the same sun to the smoke plugin
// (fx::SceneLight). No GL here.
#include <glm/glm.hpp>

namespace cube {

/// Today's sun (shaders/common.glsl's fixed sun before it became an option: normalize(-0.35, 0.85, 0.40)) as angles:
/// azimuth in the ground plane from +X (the track direction) toward +Z, elevation above the
/// horizon, both in degrees.
constexpr double kDefaultSunAzimuthDeg = 131.18592516570965;
constexpr double kDefaultSunElevationDeg = 57.98214701826395;
/// The elevations --sun and Game::setSun accept, degrees (the sun above the horizon).
constexpr double kMinSunElevationDeg = 1.0;
constexpr double kMaxSunElevationDeg = 90.0;

/// What the scene shaders light with. Defaults: the race scene's sun before it became a
/// parameter (58 degrees high, behind-left of the track direction), a warm white sun, a blue
/// sky ambient and a brown ground ambient.
struct SunLight {
    glm::vec3 toSun{-0.3491282676f, 0.8478829357f, 0.3990037344f};  ///< unit, world space, toward the sun
    glm::vec3 color{1.00f, 0.96f, 0.88f};          ///< linear RGB of the sun (scaled 0.85 on surfaces)
    glm::vec3 ambientSky{0.42f, 0.50f, 0.62f};     ///< ambient on surfaces facing up
    glm::vec3 ambientGround{0.22f, 0.20f, 0.17f};  ///< ambient on surfaces facing down
};

/// True when `azimuthDeg` is finite and `elevationDeg` is finite and in
/// [kMinSunElevationDeg, kMaxSunElevationDeg].
bool validSunAngles(double azimuthDeg, double elevationDeg);

/// The sun at these angles (degrees; see kDefaultSunAzimuthDeg). The azimuth wraps (any finite
/// value); the elevation is clamped to [kMinSunElevationDeg, kMaxSunElevationDeg] (callers
/// validate first: validSunAngles). Above 20 degrees the colours are SunLight's defaults, so the
/// default angles give the default light; lower, the sun turns orange and dims and the sky
/// ambient with it, down to about half at 1 degree.
SunLight sunFromAngles(double azimuthDeg, double elevationDeg);

}  // namespace cube
