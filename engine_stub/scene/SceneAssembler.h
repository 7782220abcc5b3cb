#pragma once
// glTF stage 4: the node tree into SceneData's flat pre-order node list, in time linear in the
// node count (explicit stack, world = parent world * local, hierarchy depth bounded).
#include "scene/GltfCommon.h"

namespace cube::gltf {

/// Checks node references and the tree shape (one parent, no cycle, depth <=
/// kMaxHierarchyDepth), then appends the default scene's nodes to `scene->nodes` and checks
/// that some node draws a mesh. `meshFirst` comes from buildMeshes.
bool assembleScene(const Context& ctx, const std::vector<size_t>& meshFirst, SceneData* scene);

}  // namespace cube::gltf
