#pragma once
// One wheel as the effects see it: where its contact patch is, how fast it moves and slips, and
// on what. The scripted car (game/Vehicle) fills these every step; the legacy particle systems
// (scene/cubeParticleSystem) and the plugin's host glue read them.
#include <string>

#include <glm/glm.hpp>

namespace cube {

struct WheelState {
    glm::vec3 contact{0.0f};   ///< contact patch, world space
    glm::vec3 velocity{0.0f};  ///< m/s, world space
    float slip = 0.0f;         ///< 0 rolling .. 1 spinning
    std::string surface;       ///< from the scene's ground tags ("" off the map)
    bool rear = false;
};

}  // namespace cube
