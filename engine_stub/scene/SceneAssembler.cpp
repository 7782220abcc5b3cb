#include "scene/SceneAssembler.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace cube::gltf {

namespace {

class SceneAssembler {
public:
    SceneAssembler(const Context& ctx, const std::vector<size_t>& meshFirst)
        : ctx_(ctx), model_(ctx.model), meshFirst_(meshFirst) {}

    bool run(SceneData* scene) { return convertNodes(scene) && checkNotEmpty(*scene); }

private:
    bool fail(SceneErrorCode code, const std::string& detail) const { return ctx_.fail(code, detail); }

    bool nodeLocal(size_t i, glm::mat4* local) {
        const tinygltf::Node& n = model_.nodes[i];
        const std::string label = "node " + std::to_string(i) + " ('" + n.name + "')";
        auto badSize = [&](const char* field, size_t got, size_t want) {
            return fail(SceneErrorCode::BadNode, label + " " + field + " has " +
                                                     std::to_string(got) + " numbers, expected " +
                                                     std::to_string(want));
        };
        if (!n.matrix.empty() && n.matrix.size() != 16)
            return badSize("matrix", n.matrix.size(), 16);
        if (!n.translation.empty() && n.translation.size() != 3)
            return badSize("translation", n.translation.size(), 3);
        if (!n.rotation.empty() && n.rotation.size() != 4)
            return badSize("rotation", n.rotation.size(), 4);
        if (!n.scale.empty() && n.scale.size() != 3) return badSize("scale", n.scale.size(), 3);
        if (!allFinite(n.matrix) || !allFinite(n.translation) || !allFinite(n.rotation) ||
            !allFinite(n.scale)) {
            return fail(SceneErrorCode::BadNode, label + " transform has a non-finite number");
        }
        if (n.matrix.size() == 16) {
            float m[16];
            for (int k = 0; k < 16; ++k) m[k] = float(n.matrix[size_t(k)]);
            *local = glm::make_mat4(m);  // glTF matrices are column-major, like glm
        } else {
            glm::mat4 t(1.0f), r(1.0f), s(1.0f);
            if (n.translation.size() == 3) {
                t = glm::translate(glm::mat4(1.0f),
                                   glm::vec3(float(n.translation[0]), float(n.translation[1]),
                                             float(n.translation[2])));
            }
            if (n.rotation.size() == 4) {
                glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]),
                            float(n.rotation[2]));  // glTF stores x, y, z, w
                const float len = glm::length(q);
                if (!(len > 1e-6f))
                    return fail(SceneErrorCode::BadNode,
                                label + " rotation is not a unit quaternion");
                r = glm::mat4_cast(q / len);
            }
            if (n.scale.size() == 3) {
                s = glm::scale(glm::mat4(1.0f),
                               glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
            }
            *local = t * r * s;
        }
        if (!finiteMat(*local))
            return fail(SceneErrorCode::BadNode, label + " transform overflows");
        return true;
    }

    bool convertNodes(SceneData* scene) {
        const size_t count = model_.nodes.size();
        std::vector<int> parent(count, -1);
        for (size_t i = 0; i < count; ++i) {
            const tinygltf::Node& n = model_.nodes[i];
            if (n.mesh >= 0 && size_t(n.mesh) >= model_.meshes.size()) {
                return fail(SceneErrorCode::BadReference,
                            "node " + std::to_string(i) + " ('" + n.name + "') uses mesh " +
                                std::to_string(n.mesh) + " but the file has " +
                                std::to_string(model_.meshes.size()));
            }
            for (int c : n.children) {
                if (c < 0 || size_t(c) >= count) {
                    return fail(SceneErrorCode::BadNode,
                                "node " + std::to_string(i) + " ('" + n.name + "') has child " +
                                    std::to_string(c) + " but the file has " +
                                    std::to_string(count) + " nodes");
                }
                if (parent[size_t(c)] != -1 || size_t(c) == i) {
                    return fail(
                        SceneErrorCode::BadNode,
                        "node " + std::to_string(c) + " is a child of node " + std::to_string(i) +
                            (size_t(c) == i ? " itself"
                                            : " and of node " + std::to_string(parent[size_t(c)])) +
                            "; glTF nodes form a strict tree");
                }
                parent[size_t(c)] = int(i);
            }
        }
        // With one parent per node, a cycle is a parent chain that returns to itself.
        std::vector<char> state(count, 0);  // 0 unknown, 1 on the current chain, 2 known acyclic
        for (size_t i = 0; i < count; ++i) {
            std::vector<size_t> chain;
            int j = int(i);
            while (j >= 0 && state[size_t(j)] == 0) {
                state[size_t(j)] = 1;
                chain.push_back(size_t(j));
                j = parent[size_t(j)];
            }
            if (j >= 0 && state[size_t(j)] == 1) {
                return fail(SceneErrorCode::BadNode,
                            "node " + std::to_string(j) + " ('" + model_.nodes[size_t(j)].name +
                                "') is its own ancestor; glTF nodes form a tree without cycles");
            }
            for (size_t k : chain) state[k] = 2;
        }

        std::vector<int> roots;
        if (model_.scenes.empty()) {
            for (size_t i = 0; i < count; ++i) {
                if (parent[i] == -1) roots.push_back(int(i));
            }
        } else {
            const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (size_t(s) >= model_.scenes.size()) {
                return fail(SceneErrorCode::BadReference, "default scene " + std::to_string(s) +
                                                              " does not exist: the file has " +
                                                              std::to_string(model_.scenes.size()));
            }
            std::vector<char> seen(count, 0);
            for (int r : model_.scenes[size_t(s)].nodes) {
                if (r < 0 || size_t(r) >= count || parent[size_t(r)] != -1 || seen[size_t(r)]) {
                    return fail(
                        SceneErrorCode::BadNode,
                        "scene " + std::to_string(s) + " lists node " + std::to_string(r) +
                            ", expected each root once, as an existing node without a parent");
                }
                seen[size_t(r)] = 1;
                roots.push_back(r);
            }
        }

        // Depth-first pre-order with an explicit stack: a deep chain cannot overflow the C++ stack,
        // and each node is visited once (its world matrix from its parent's), so the work is
        // linear in the node count whatever the shape of the tree.
        struct Pending {
            int node, flatParent, depth;
        };
        std::vector<Pending> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, -1, 1});
        scene->nodes.reserve(count);
        while (!stack.empty()) {
            const auto [gi, flatParent, depth] = stack.back();
            stack.pop_back();
            const tinygltf::Node& n = model_.nodes[size_t(gi)];
            if (depth > kMaxHierarchyDepth) {
                return fail(SceneErrorCode::TooDeep,
                            "node " + std::to_string(gi) + " ('" + n.name + "') is " +
                                std::to_string(depth) + " levels below its root; expected at most " +
                                std::to_string(kMaxHierarchyDepth) + " levels of node hierarchy");
            }
            SceneNode node;
            node.name = n.name;
            node.parent = flatParent;
            if (!nodeLocal(size_t(gi), &node.local)) return false;
            node.world =
                flatParent >= 0 ? scene->nodes[size_t(flatParent)].world * node.local : node.local;
            if (!finiteMat(node.world)) {
                return fail(SceneErrorCode::BadNode, "node " + std::to_string(gi) + " ('" + n.name +
                                                         "') world transform overflows");
            }
            readExtras(n.extras, &node);
            if (n.mesh >= 0) {
                const size_t m = size_t(n.mesh);
                for (size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
                    node.meshes.push_back(int(meshFirst_[m] + p));
                }
            }
            computeWorldBox(scene->meshes, &node);
            const int flatIndex = int(scene->nodes.size());
            scene->nodes.push_back(std::move(node));
            for (auto c = n.children.rbegin(); c != n.children.rend(); ++c)
                stack.push_back({*c, flatIndex, depth + 1});
        }
        return true;
    }

    static void readExtras(const tinygltf::Value& extras, SceneNode* node) {
        if (!extras.IsObject()) return;
        const tinygltf::Value& surface = extras.Get("surface");
        if (surface.IsString()) node->surface = surface.Get<std::string>();
        const tinygltf::Value& solid = extras.Get("solid");
        if (solid.IsBool()) node->solid = solid.Get<bool>();
    }

    // World box from the 8 transformed corners of each mesh's local box: O(1) per instance.
    static void computeWorldBox(const std::vector<SceneMesh>& meshes, SceneNode* node) {
        const glm::vec3 origin(node->world[3]);
        node->aabbMin = node->aabbMax = origin;
        bool first = true;
        for (int mi : node->meshes) {
            const SceneMesh& m = meshes[size_t(mi)];
            for (int k = 0; k < 8; ++k) {
                const glm::vec3 corner((k & 1) ? m.boundsMax.x : m.boundsMin.x,
                                       (k & 2) ? m.boundsMax.y : m.boundsMin.y,
                                       (k & 4) ? m.boundsMax.z : m.boundsMin.z);
                const glm::vec3 w(node->world * glm::vec4(corner, 1.0f));
                node->aabbMin = first ? w : glm::min(node->aabbMin, w);
                node->aabbMax = first ? w : glm::max(node->aabbMax, w);
                first = false;
            }
        }
    }

    bool checkNotEmpty(const SceneData& scene) {
        if (scene.meshes.empty())
            return fail(SceneErrorCode::Empty, "has no meshes, expected at least one");
        for (const SceneNode& n : scene.nodes) {
            if (!n.meshes.empty()) return true;
        }
        return fail(SceneErrorCode::Empty,
                    "no node of the scene has a mesh, expected at least one");
    }

    const Context& ctx_;
    const tinygltf::Model& model_;
    const std::vector<size_t>& meshFirst_;
};

}  // namespace

bool assembleScene(const Context& ctx, const std::vector<size_t>& meshFirst, SceneData* scene) {
    return SceneAssembler(ctx, meshFirst).run(scene);
}

}  // namespace cube::gltf
