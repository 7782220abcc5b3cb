#pragma once
// The legacy smoke's data file (data/legacy_smoke.yaml): what the old CUBE SpecialFX read
// before the plugin existed. A handful of keys; parsed with yaml-cpp, errors name file:line.
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace cube {

/// Defaults: rear wheels, slip 0.3, 40 sprites/s, 400 max, 2.5 s life, 0.8 -> 3 m, rising 0.6 m/s,
/// 0.15 m gap under the lowest corner, alpha 0.35, light grey.
struct LegacySmokeDesc {
    std::string name;
    std::string wheels = "rear";  ///< rear | front | all
    float slipThreshold = 0.3f;
    float rate = 40.0f;            ///< sprites per second at full slip
    int capacity = 400;
    float lifetime = 2.5f;
    float startSize = 0.8f;
    float endSize = 3.0f;
    float riseSpeed = 0.6f;
    float hover = 0.15f;           ///< metres between the ground and the sprite's lowest point
    float alpha = 0.35f;           ///< the old trick: low alpha so hard edges stay faint
    glm::vec3 tint{0.85f};
};

/// Loads every reaction in `path`. False + "file:line: message" on the first bad value.
bool loadLegacySmoke(const std::string& path, std::vector<LegacySmokeDesc>* out, std::string* error);

}  // namespace cube
