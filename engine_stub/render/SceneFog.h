#pragma once
// The track's fog: GL's fixed-function fog, done in the scene's shaders (shaders/common.glsl,
// applyFog) and handed to the plugin as fx::ViewInfo::fog with the same values, so the smoke
// fades with the geometry at the same distance. Distance: the fragment's eye-space |z|.
// Defaults: off (cube_game --fog turns it on; the golden configurations leave it off).
#include <glm/glm.hpp>

namespace cube {

struct SceneFog {
    enum class Mode { Off = 0, Linear, Exp, Exp2 };  ///< the numbers of fx::Fog::Mode and uFogMode
    Mode mode = Mode::Off;
    glm::vec3 color{0.70f, 0.78f, 0.88f};  ///< the sky's horizon haze (common.glsl kHazeColor)
    float start = 0.0f;    ///< Linear: metres
    float end = 1.0f;      ///< Linear: metres, != start
    float density = 1.0f;  ///< Exp, Exp2: 1/m
    bool on() const { return mode != Mode::Off; }
};

}  // namespace cube
