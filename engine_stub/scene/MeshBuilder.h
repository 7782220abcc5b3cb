#pragma once
// glTF stage 3: buffers, images and mesh primitives into SceneMeshes. Every bufferView and
// accessor range, component type and index is checked before a byte is read.
#include "scene/GltfCommon.h"

namespace cube::gltf {

/// Validates buffer views and images, then converts every mesh primitive into `scene->meshes`.
/// `meshFirst[m]` receives the index of glTF mesh m's first SceneMesh. `tinygltfWarnings`
/// is quoted when an image is missing.
bool buildMeshes(const Context& ctx, const ImageState& images, const std::string& tinygltfWarnings,
                 SceneData* scene, std::vector<size_t>* meshFirst);

}  // namespace cube::gltf
