#pragma once
// The legacy smoke's data file (data/legacy_smoke.yaml): what the old CUBE SpecialFX read
// before the plugin existed. A handful of keys; parsed with yaml-cpp.
//
// Held to the reaction loader's rules and reported with the same named codes (fx::ErrorCode):
// regular files only, read without blocking and at most kLegacyMaxFileBytes (FileNotFound,
// FileTooLarge); UTF-8 text only and exactly one YAML document (SyntaxError); no key twice in a
// map (DuplicateKey); whole numbers where a count is expected (WrongType); ranges (OutOfRange,
// NotFinite, NegativeCount); unknown keys (UnknownKey). Every problem in the file is reported,
// each with file, line, column and the dotted key ("reactions[0].capacity"); nothing throws.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "fx/Diagnostic.h"

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

constexpr size_t kLegacyMaxFileBytes = 1u << 20;  ///< 1 MiB: the shipped file is 600 bytes
constexpr int kLegacyMaxReactions = 64;
constexpr int kLegacyMaxNesting = 8;               ///< collection levels; the schema needs 4
constexpr int kLegacyNestingVisits = 20000;        ///< nodes the nesting check visits at most (aliases)

/// Loads every reaction in `path`. On any error returns false, leaves `out` untouched and
/// appends one diagnostic per problem to `diags` (may be null).
bool loadLegacySmoke(const std::string& path, std::vector<LegacySmokeDesc>* out, fx::Diagnostics* diags);
/// The same, with the diagnostics joined one per line ("file:line:col: error[Code] key: ...").
bool loadLegacySmoke(const std::string& path, std::vector<LegacySmokeDesc>* out, std::string* error);
/// Parses already-read text; `nameForMessages` names the file in diagnostics. The fuzz entry.
bool loadLegacySmokeText(const std::string& text, const std::string& nameForMessages,
                         std::vector<LegacySmokeDesc>* out, fx::Diagnostics* diags);

}  // namespace cube
