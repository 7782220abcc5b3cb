#pragma once
// The scene light as the renderers use it (Plugin::setSceneLight, API 1.2): validated, the sun
// direction normalised. `on` false (the default, and after clearSceneLight) = unlit smoke.
#include <glm/glm.hpp>

namespace fx {

struct LightState {
    bool on = false;
    glm::vec3 toSun{0.0f, 1.0f, 0.0f};  ///< unit, world space, toward the sun
    glm::vec3 sunColor{1.0f};
    glm::vec3 ambient{0.0f};
};

}  // namespace fx
