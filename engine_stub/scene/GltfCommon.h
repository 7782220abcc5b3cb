#pragma once
// Shared by the glTF loading stages (GltfReader -> GltfValidator -> MeshBuilder ->
// SceneAssembler): the failure reporter and small helpers. Private to engine_stub/scene.
#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/SceneLoader.h"

namespace cube::gltf {

/// Limits checked before the work they bound (see docs/errors.md).
constexpr uint64_t kMaxFileBytes = 256ull << 20;  ///< the scene and every external buffer/image
constexpr int kMaxJsonDepth = 128;                ///< JSON nesting, pre-scanned before parsing
constexpr size_t kMaxNodes = 1u << 20;            ///< nodes in one file
constexpr int kMaxHierarchyDepth = 4096;          ///< node levels from a root

/// Fills `error` (may be null): code, file, "<path>: <detail>". Always returns false.
inline bool fail(const std::string& path, SceneError* error, SceneErrorCode code,
                 const std::string& detail) {
    if (error) {
        error->code = code;
        error->file = path;
        error->message = path + ": " + detail;
    }
    return false;
}

/// One load's model and where its errors go.
struct Context {
    const std::string& path;
    const tinygltf::Model& model;
    SceneError* error;
    bool fail(SceneErrorCode code, const std::string& detail) const {
        return gltf::fail(path, error, code, detail);
    }
};

/// Images tinygltf handed to the image callback (filled during parsing).
struct ImageState {
    std::vector<char> delivered;                   // by image index
    std::vector<std::pair<int, std::string>> bad;  // URI/data-URI images stb cannot identify
};

inline std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    for (char& c : s) {
        if (c == '\n') c = ' ';
    }
    return s;
}

// URIs go into messages; a data URI can be megabytes long.
inline std::string shortUri(const std::string& uri) {
    return uri.size() <= 80 ? uri : uri.substr(0, 77) + "...";
}

inline uint32_t readLE32(const unsigned char* p) {
    return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}

inline bool allFinite(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double d) { return std::isfinite(d); });
}

inline bool finiteMat(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

}  // namespace cube::gltf
