#pragma once
// glTF stage 2: the JSON itself, before tinygltf turns it into a model. Two steps:
//  - checkJsonNesting: a byte scan (strings and escapes respected) that refuses nesting deeper
//    than kMaxJsonDepth, so no recursive JSON parser ever sees input that could overflow its
//    stack (tens of thousands of '[' in `extras`, say);
//  - validateGltfJson: the rules tinygltf accepts silently, each message naming the rule as the
//    Khronos glTF validator does ([NODE_MATRIX_TRS], [TYPE_MISMATCH], ...), plus what this loader
//    refuses (required extensions, by name; a `uri` outside the model's folder) and what it
//    ignores (textures, skins, animations, cameras, used extensions: one warning each).
#include <string>
#include <vector>

#include "scene/SceneLoader.h"

namespace cube::gltf {

/// False + TooDeep naming the line when `json` nests deeper than `maxDepth`. Linear time.
bool checkJsonNesting(const std::string& path, const char* json, size_t size, int maxDepth,
                      SceneError* error);

/// Checks the rules above on already depth-checked JSON. Text that does not parse is left to
/// tinygltf (returns true) so its ParseError message is the one reported. `warnings` gets one
/// line per ignored feature.
bool validateGltfJson(const std::string& path, const char* json, size_t size, SceneError* error,
                      std::vector<std::string>* warnings);

}  // namespace cube::gltf
