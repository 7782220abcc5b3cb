#pragma once
// glTF stage 1: the file's bytes (through the shared SafeFile opener), the GLB container, and
// tinygltf's parse. External buffers and images are read through the same opener and only
// from the model's folder or below it (canonical paths compared, so neither ".." nor a
// symlink leads out of it).
#include "scene/GltfCommon.h"

namespace cube::gltf {

/// The scene file as read: where its JSON is, and whether it is a GLB.
struct GltfFile {
    std::vector<unsigned char> bytes;
    bool binary = false;
    uint32_t glbLength = 0;       ///< GLB: the header's total length (checked <= bytes.size())
    const char* json = nullptr;   ///< the JSON text (.gltf: all bytes; .glb: the JSON chunk)
    size_t jsonSize = 0;
};

/// Reads and checks the container: FileNotFound, TooLarge, ParseError (bad GLB layout).
bool readGltfFile(const std::string& path, GltfFile* file, SceneError* error);

/// tinygltf's parse, with file access confined to the model's folder. MissingBuffer /
/// ParseError on failure; `images` and `tinygltfWarnings` are filled for MeshBuilder.
bool parseGltf(const std::string& path, const GltfFile& file, tinygltf::Model* model,
               ImageState* images, std::string* tinygltfWarnings, SceneError* error);

}  // namespace cube::gltf
