#pragma once
// The host world's basis against the plugin's (fxPluginDesc::upAxis, API 2.1). The plugin's world
// is Y-up: reaction files, gravity, emission directions and wind fields are written in it. A Z-up
// host (right-handed: X, Y on the ground, Z up) is turned into it at the boundary, once per value,
// so nothing past the C layer knows there was a choice:
//   host -> plugin  C: (x, y, z) -> (x, z, -y)      (a quarter turn about X; +Z goes to +Y)
//   plugin -> host  B = C^-1: (x, y, z) -> (x, -z, y)
// Views: view' = view B (the host's view of the host's world is the plugin's view of its own).
// The shadow's worldToShadow goes back: m' = m C. Each is a permutation with one sign change, so
// the turned values are exact: a Z-up host gets the Y-up host's picture bit for bit.
#include <glm/glm.hpp>

#include "fx/Types.h"

namespace fx {

/// A host world vector (position, velocity, direction) in the plugin's world.
inline glm::vec3 toPluginWorld(UpAxis up, glm::vec3 h) {
    return up == UpAxis::Z ? glm::vec3(h.x, h.z, -h.y) : h;
}

/// The host's view matrix (host world -> view space) as the plugin's: view B.
inline glm::mat4 viewFromPluginWorld(UpAxis up, const glm::mat4& view) {
    if (up != UpAxis::Z) return view;
    glm::mat4 out = view;
    out[1] = view[2];   // B e_y = e_z
    out[2] = -view[1];  // B e_z = -e_y
    return out;
}

/// A matrix that takes the plugin's world points (worldToShadow) as one that takes the host's: m C.
inline glm::mat4 fromHostWorld(UpAxis up, const glm::mat4& m) {
    if (up != UpAxis::Z) return m;
    glm::mat4 out = m;
    out[1] = -m[2];  // C e_y = -e_z
    out[2] = m[1];   // C e_z = e_y
    return out;
}

}  // namespace fx
