#include "scene/SceneData.h"

#include <algorithm>
#include <cmath>

namespace cube {

namespace {

bool hasBox(const SceneNode& n) { return !n.meshes.empty(); }

}  // namespace

int SceneData::findNode(const std::string& name) const {
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

std::vector<int> SceneData::nodesWithPrefix(const std::string& prefix) const {
    std::vector<int> found;
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].name.compare(0, prefix.size(), prefix) == 0)
            found.push_back(static_cast<int>(i));
    }
    return found;
}

bool SceneData::isDescendant(int node, int ancestor) const {
    const int count = static_cast<int>(nodes.size());
    if (node < 0 || node >= count || ancestor < 0 || ancestor >= count) return false;
    // Parents precede children (pre-order), so the walk up terminates within `count` steps.
    for (int p = nodes[static_cast<size_t>(node)].parent; p >= 0 && p < count;
         p = nodes[static_cast<size_t>(p)].parent) {
        if (p == ancestor) return true;
    }
    return false;
}

void SceneData::setLocal(int node, const glm::mat4& local) {
    if (node < 0 || size_t(node) >= nodes.size()) return;
    nodes[size_t(node)].local = local;
    // Pre-order: the subtree is the run of nodes after `node` that descend from it, and each
    // parent is refreshed before its children.
    for (size_t n = size_t(node); n < nodes.size(); ++n) {
        if (n != size_t(node) && !isDescendant(int(n), node)) break;
        SceneNode& s = nodes[n];
        s.world = s.parent >= 0 ? nodes[size_t(s.parent)].world * s.local : s.local;
    }
}

std::string SceneData::surfaceAt(float x, float z) const {
    const SceneNode* best = nullptr;
    for (const SceneNode& n : nodes) {
        if (n.surface.empty() || !hasBox(n)) continue;
        if (x < n.aabbMin.x || x > n.aabbMax.x || z < n.aabbMin.z || z > n.aabbMax.z) continue;
        if (!best || n.aabbMax.y > best->aabbMax.y) best = &n;
    }
    return best ? best->surface : std::string();
}

float SceneData::penetrationDepth(const glm::vec3& centre, float radius, int* nodeOut) const {
    float deepest = 0.0f;
    int deepestNode = -1;
    for (size_t i = 0; i < nodes.size(); ++i) {
        const SceneNode& n = nodes[i];
        if (!n.solid || !hasBox(n)) continue;
        const glm::vec3 closest = glm::clamp(centre, n.aabbMin, n.aabbMax);
        const glm::vec3 d = centre - closest;
        const float dist2 = glm::dot(d, d);
        float depth = 0.0f;
        if (dist2 > 0.0f) {
            depth = radius - std::sqrt(dist2);
        } else {
            // Centre inside the box: push out through the nearest face.
            const glm::vec3 toMin = centre - n.aabbMin;
            const glm::vec3 toMax = n.aabbMax - centre;
            const float face = std::min({toMin.x, toMin.y, toMin.z, toMax.x, toMax.y, toMax.z});
            depth = radius + face;
        }
        if (depth > deepest) {
            deepest = depth;
            deepestNode = static_cast<int>(i);
        }
    }
    if (nodeOut) *nodeOut = deepestNode;
    return deepest;
}

std::vector<int> SceneData::solidsOverlapping(const glm::vec3& boxMin,
                                              const glm::vec3& boxMax) const {
    std::vector<int> found;
    for (size_t i = 0; i < nodes.size(); ++i) {
        const SceneNode& n = nodes[i];
        if (!n.solid || !hasBox(n)) continue;
        if (glm::all(glm::lessThanEqual(boxMin, n.aabbMax)) &&
            glm::all(glm::lessThanEqual(n.aabbMin, boxMax))) {
            found.push_back(static_cast<int>(i));
        }
    }
    return found;
}

}  // namespace cube
