#pragma once
// SceneData: the CPU-side result of loading a glTF scene (see SceneLoader.h). No GL here: the
// renderer uploads meshes, the game queries nodes, surfaces and solid bounds.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace cube {

/// One vertex as the loader delivers it: position and unit normal, both in the mesh's local space.
struct SceneVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
};

/// One drawable piece: a glTF mesh *primitive* (a glTF mesh with three primitives becomes three
/// SceneMeshes). Triangle list, indices always uint32 and always < vertices.size().
/// Defaults: baseColor is opaque white when the primitive has no material.
struct SceneMesh {
    std::string name;  ///< glTF mesh name; "<name>#<k>" for primitive k > 0 of the same mesh
    std::vector<SceneVertex> vertices;
    std::vector<uint32_t> indices;
    glm::vec4 baseColor{1.0f};                   ///< PBR baseColorFactor (linear RGBA)
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  ///< local-space bounds of the vertices
};

/// One node of the flattened hierarchy. Nodes are stored in depth-first pre-order, so a parent
/// always precedes its children (parent < own index) and world = nodes[parent].world * local.
/// Defaults: surface "" (not ground), solid false, parent -1 (root).
struct SceneNode {
    std::string name;
    int parent = -1;
    glm::mat4 local{1.0f};
    glm::mat4 world{1.0f};
    std::vector<int> meshes;  ///< indices into SceneData::meshes
    std::string surface;      ///< extras.surface: "asphalt", "kerb", "grass", "gravel", "sand", ...
    bool solid = false;       ///< extras.solid: barriers, tyre stacks
    /// World-space box of this node's own meshes (children not included). A node without meshes
    /// gets an empty box at its world origin (aabbMin == aabbMax) and takes part in no query.
    glm::vec3 aabbMin{0.0f}, aabbMax{0.0f};
};

/// A loaded scene. Queries are linear scans: the race track has a few dozen nodes.
struct SceneData {
    std::string sourcePath;  ///< the file it was loaded from (used in error messages)
    std::vector<SceneMesh> meshes;
    std::vector<SceneNode> nodes;
    /// What the loader read past, one line each ("race.gltf: 2 animation(s) ignored: ..."),
    /// for the caller to show once.
    std::vector<std::string> warnings;

    /// Index of the first node named exactly `name`, or -1.
    int findNode(const std::string& name) const;
    /// Indices of every node whose name starts with `prefix`, in node order.
    std::vector<int> nodesWithPrefix(const std::string& prefix) const;
    /// True when `ancestor` is a strict ancestor of `node` (a node is not its own descendant).
    /// Out-of-range indices give false.
    bool isDescendant(int node, int ancestor) const;

    /// Animation: node `node`'s local transform from now on; its world transform and its
    /// descendants' follow (world = parent's world * local). The world boxes (aabbMin/Max) stay
    /// those of the loaded pose. An index out of range changes nothing.
    void setLocal(int node, const glm::mat4& local);

    /// Surface under the world point (x, z): the surface of the ground node (non-empty surface,
    /// at least one mesh) whose XZ box contains the point, bounds inclusive, picking the one with
    /// the highest top (aabbMax.y) where several overlap. "" when no ground node is under it.
    std::string surfaceAt(float x, float z) const;

    /// Deepest penetration of a sphere into the world boxes of solid nodes: 0 when it touches none,
    /// otherwise how far the sphere must move out along the shortest axis (a centre inside a box
    /// counts its distance to the nearest face plus the radius). `nodeOut` (optional) receives the
    /// node of the deepest contact, or -1.
    float penetrationDepth(const glm::vec3& centre, float radius, int* nodeOut = nullptr) const;

    /// Solid nodes whose world box overlaps the box [boxMin, boxMax] (touching counts).
    std::vector<int> solidsOverlapping(const glm::vec3& boxMin, const glm::vec3& boxMax) const;
};

}  // namespace cube
