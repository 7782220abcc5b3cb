#include "scene/MeshBuilder.h"

#include <stb_image.h>

#include <cstring>
#include <limits>
#include <sstream>

namespace cube::gltf {

namespace {

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "unknown type";
    }
}

const char* componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
        default: return "unknown";
    }
}

std::string componentTypeLabel(int componentType) {
    return std::to_string(componentType) + " (" + componentTypeName(componentType) + ")";
}

// A range-checked view of an accessor's elements inside its buffer.
struct AccessorView {
    const unsigned char* base = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int componentType = 0;
    const unsigned char* element(size_t i) const { return base + i * stride; }
};


class MeshBuilder {
public:
    MeshBuilder(const Context& ctx, const ImageState& images, const std::string& warn)
        : ctx_(ctx), model_(ctx.model), images_(images), warn_(warn) {}

    bool run(SceneData* scene, std::vector<size_t>* meshFirst) {
        return validateBufferViews() && validateImages() && convertMeshes(scene, meshFirst);
    }

private:
    bool fail(SceneErrorCode code, const std::string& detail) const { return ctx_.fail(code, detail); }

    bool validateBufferViews() {
        for (size_t i = 0; i < model_.bufferViews.size(); ++i) {
            const tinygltf::BufferView& bv = model_.bufferViews[i];
            if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size()) {
                return fail(SceneErrorCode::MissingBuffer,
                            "bufferView " + std::to_string(i) + " refers to buffer " +
                                std::to_string(bv.buffer) + " but the file has " +
                                std::to_string(model_.buffers.size()) + " buffer(s)");
            }
            const size_t have = model_.buffers[size_t(bv.buffer)].data.size();
            if (bv.byteOffset > have || bv.byteLength > have - bv.byteOffset) {
                std::ostringstream s;
                s << "bufferView " << i << " needs " << bv.byteLength << " bytes from offset "
                  << bv.byteOffset << " but buffer " << bv.buffer << " has " << have;
                return fail(SceneErrorCode::AccessorOutOfRange, s.str());
            }
        }
        return true;
    }

    bool validateImages() {
        for (size_t i = 0; i < model_.images.size(); ++i) {
            const tinygltf::Image& img = model_.images[i];
            const std::string label =
                "image " + std::to_string(i) +
                (img.uri.empty() ? std::string() : " ('" + shortUri(img.uri) + "')");
            if (img.bufferView >= 0) {
                // Range already checked by validateBufferViews.
                const tinygltf::BufferView& bv = model_.bufferViews[size_t(img.bufferView)];
                const unsigned char* bytes =
                    model_.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset;
                int w = 0, h = 0, c = 0;
                if (bv.byteLength == 0 || bv.byteLength > size_t(std::numeric_limits<int>::max()) ||
                    !stbi_info_from_memory(bytes, int(bv.byteLength), &w, &h, &c)) {
                    return fail(SceneErrorCode::MissingTexture,
                                label + " in bufferView " + std::to_string(img.bufferView) +
                                    " is not a PNG/JPEG image stb can read");
                }
                continue;
            }
            if (!(i < images_.delivered.size() && images_.delivered[i])) {
                return fail(
                    SceneErrorCode::MissingTexture,
                    label + " could not be loaded: expected a readable file next to the scene" +
                        (warn_.empty() ? std::string() : " (tinygltf: " + trimmed(warn_) + ")"));
            }
        }
        for (const auto& bad : images_.bad) {
            const std::string uri = size_t(bad.first) < model_.images.size()
                                        ? shortUri(model_.images[size_t(bad.first)].uri)
                                        : "";
            return fail(SceneErrorCode::MissingTexture,
                        "image " + std::to_string(bad.first) + " ('" + uri +
                            "') is not an image stb can read (" + bad.second + ")");
        }
        for (size_t i = 0; i < model_.textures.size(); ++i) {
            const int src = model_.textures[i].source;
            if (src >= 0 && size_t(src) >= model_.images.size()) {
                return fail(SceneErrorCode::BadReference,
                            "texture " + std::to_string(i) + " uses image " + std::to_string(src) +
                                " but the file has " + std::to_string(model_.images.size()));
            }
        }
        for (size_t i = 0; i < model_.materials.size(); ++i) {
            const tinygltf::Material& m = model_.materials[i];
            for (int tex :
                 {m.pbrMetallicRoughness.baseColorTexture.index,
                  m.pbrMetallicRoughness.metallicRoughnessTexture.index, m.normalTexture.index,
                  m.occlusionTexture.index, m.emissiveTexture.index}) {
                if (tex >= 0 && size_t(tex) >= model_.textures.size()) {
                    return fail(SceneErrorCode::BadReference,
                                "material " + std::to_string(i) + " uses texture " +
                                    std::to_string(tex) + " but the file has " +
                                    std::to_string(model_.textures.size()));
                }
            }
        }
        return true;
    }

    // Resolves accessor `index` as `type` with one of `componentTypes`, checking every byte it
    // covers lies inside its bufferView (whose range inside the buffer is already checked).
    bool viewAccessor(int index, int type, std::initializer_list<int> componentTypes,
                      const std::string& what, AccessorView* view) {
        const std::string label = "accessor " + std::to_string(index) + " (" + what + ")";
        if (index < 0 || size_t(index) >= model_.accessors.size()) {
            return fail(SceneErrorCode::BadReference, label + " does not exist: the file has " +
                                                          std::to_string(model_.accessors.size()) +
                                                          " accessors");
        }
        const tinygltf::Accessor& acc = model_.accessors[size_t(index)];
        if (acc.sparse.isSparse) {
            return fail(SceneErrorCode::Unsupported,
                        label + " is sparse; sparse accessors are not supported");
        }
        if (acc.bufferView < 0) {
            return fail(SceneErrorCode::Unsupported,
                        label + " has no bufferView (implicit zeros are not supported)");
        }
        if (size_t(acc.bufferView) >= model_.bufferViews.size()) {
            return fail(SceneErrorCode::BadReference,
                        label + " uses bufferView " + std::to_string(acc.bufferView) +
                            " but the file has " + std::to_string(model_.bufferViews.size()));
        }
        if (acc.type != type) {
            return fail(SceneErrorCode::BadAttribute,
                        label + " is " + typeName(acc.type) + ", expected " + typeName(type));
        }
        if (std::find(componentTypes.begin(), componentTypes.end(), acc.componentType) ==
            componentTypes.end()) {
            std::string expected;
            for (int ct : componentTypes) {
                expected += (expected.empty() ? "" : " or ") + componentTypeLabel(ct);
            }
            return fail(SceneErrorCode::BadAttribute, label + " has componentType " +
                                                          componentTypeLabel(acc.componentType) +
                                                          ", expected " + expected);
        }
        if (acc.count == 0) {
            return fail(SceneErrorCode::BadAttribute, label + " has count 0, expected at least 1");
        }
        const tinygltf::BufferView& bv = model_.bufferViews[size_t(acc.bufferView)];
        const size_t elementSize =
            size_t(tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType))) *
            size_t(tinygltf::GetNumComponentsInType(uint32_t(acc.type)));
        const size_t stride = bv.byteStride ? bv.byteStride : elementSize;
        if (stride < elementSize) {
            return fail(SceneErrorCode::AccessorOutOfRange,
                        label + " elements are " + std::to_string(elementSize) +
                            " bytes but bufferView " + std::to_string(acc.bufferView) +
                            " has byteStride " + std::to_string(stride));
        }
        // needed = byteOffset + (count - 1) * stride + elementSize, saturating instead of wrapping.
        uint64_t needed = 0;
        const bool overflow =
            __builtin_mul_overflow(uint64_t(acc.count - 1), uint64_t(stride), &needed) ||
            __builtin_add_overflow(needed, uint64_t(acc.byteOffset), &needed) ||
            __builtin_add_overflow(needed, uint64_t(elementSize), &needed);
        if (overflow || needed > bv.byteLength) {
            std::ostringstream s;
            s << label << " needs ";
            if (overflow)
                s << "more than 2^64";
            else
                s << needed;
            s << " bytes (count " << acc.count << ", stride " << stride << ") from offset "
              << acc.byteOffset << " but bufferView " << acc.bufferView << " has " << bv.byteLength;
            return fail(SceneErrorCode::AccessorOutOfRange, s.str());
        }
        view->base = model_.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset + acc.byteOffset;
        view->stride = stride;
        view->count = acc.count;
        view->componentType = acc.componentType;
        return true;
    }

    bool readVec3(const AccessorView& v, size_t i, glm::vec3* out) {
        float f[3];
        std::memcpy(f, v.element(i), sizeof f);
        *out = glm::vec3(f[0], f[1], f[2]);
        return std::isfinite(f[0]) && std::isfinite(f[1]) && std::isfinite(f[2]);
    }

    static uint32_t readIndex(const AccessorView& v, size_t i) {
        const unsigned char* p = v.element(i);
        switch (v.componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
                return uint32_t(p[0]) | (uint32_t(p[1]) << 8);
            default: return readLE32(p);
        }
    }

    bool convertPrimitive(size_t meshIndex, size_t primIndex, SceneMesh* out) {
        const tinygltf::Mesh& mesh = model_.meshes[meshIndex];
        const tinygltf::Primitive& prim = mesh.primitives[primIndex];
        const std::string meshName =
            mesh.name.empty() ? "mesh" + std::to_string(meshIndex) : mesh.name;
        const std::string where =
            "of mesh '" + meshName + "' primitive " + std::to_string(primIndex);
        out->name = primIndex == 0 ? meshName : meshName + "#" + std::to_string(primIndex);

        if (prim.mode != TINYGLTF_MODE_TRIANGLES) {
            return fail(SceneErrorCode::Unsupported, "primitive " + std::to_string(primIndex) +
                                                         " of mesh '" + meshName + "' has mode " +
                                                         std::to_string(prim.mode) +
                                                         ", only TRIANGLES (4) is supported");
        }
        const auto pos = prim.attributes.find("POSITION");
        if (pos == prim.attributes.end()) {
            return fail(SceneErrorCode::BadAttribute, "primitive " + std::to_string(primIndex) +
                                                          " of mesh '" + meshName +
                                                          "' has no POSITION attribute");
        }
        AccessorView positions;
        if (!viewAccessor(pos->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                          "POSITION " + where, &positions)) {
            return false;
        }
        out->vertices.resize(positions.count);
        for (size_t i = 0; i < positions.count; ++i) {
            if (!readVec3(positions, i, &out->vertices[i].position)) {
                return fail(SceneErrorCode::BadAttribute, "POSITION " + where + " vertex " +
                                                              std::to_string(i) + " is not finite");
            }
        }

        const auto nrm = prim.attributes.find("NORMAL");
        const bool hasNormals = nrm != prim.attributes.end();
        if (hasNormals) {
            AccessorView normals;
            if (!viewAccessor(nrm->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                              "NORMAL " + where, &normals)) {
                return false;
            }
            if (normals.count != positions.count) {
                return fail(SceneErrorCode::BadAttribute,
                            "NORMAL " + where + " has " + std::to_string(normals.count) +
                                " elements, expected " + std::to_string(positions.count) +
                                " like POSITION");
            }
            for (size_t i = 0; i < normals.count; ++i) {
                glm::vec3 n;
                if (!readVec3(normals, i, &n)) {
                    return fail(
                        SceneErrorCode::BadAttribute,
                        "NORMAL " + where + " vertex " + std::to_string(i) + " is not finite");
                }
                const float len = glm::length(n);
                out->vertices[i].normal = len > 1e-12f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
            }
        }

        if (prim.indices >= 0) {
            AccessorView idx;
            if (!viewAccessor(
                    prim.indices, TINYGLTF_TYPE_SCALAR,
                    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                    "indices " + where, &idx)) {
                return false;
            }
            if (idx.count % 3 != 0) {
                return fail(SceneErrorCode::BadAttribute,
                            "indices " + where + " has " + std::to_string(idx.count) +
                                " elements, expected a multiple of 3");
            }
            out->indices.resize(idx.count);
            for (size_t i = 0; i < idx.count; ++i) {
                const uint32_t v = readIndex(idx, i);
                if (v >= positions.count) {
                    return fail(SceneErrorCode::IndexOutOfRange,
                                "index " + std::to_string(v) + " (element " + std::to_string(i) +
                                    " of accessor " + std::to_string(prim.indices) + ", indices " +
                                    where + ") must be less than the vertex count " +
                                    std::to_string(positions.count));
                }
                out->indices[i] = v;
            }
        } else {
            if (positions.count % 3 != 0) {
                return fail(SceneErrorCode::BadAttribute,
                            "POSITION " + where + " has " + std::to_string(positions.count) +
                                " vertices and no indices, expected a multiple of 3");
            }
            out->indices.resize(positions.count);
            for (size_t i = 0; i < positions.count; ++i) out->indices[i] = uint32_t(i);
        }

        if (!hasNormals) computeNormals(out);

        out->boundsMin = out->boundsMax = out->vertices[0].position;
        for (const SceneVertex& v : out->vertices) {
            out->boundsMin = glm::min(out->boundsMin, v.position);
            out->boundsMax = glm::max(out->boundsMax, v.position);
        }

        if (prim.material >= 0) {
            if (size_t(prim.material) >= model_.materials.size()) {
                return fail(SceneErrorCode::BadReference,
                            "primitive " + std::to_string(primIndex) + " of mesh '" + meshName +
                                "' uses material " + std::to_string(prim.material) +
                                " but the file has " + std::to_string(model_.materials.size()));
            }
            const std::vector<double>& f =
                model_.materials[size_t(prim.material)].pbrMetallicRoughness.baseColorFactor;
            if (f.size() != 4 || !allFinite(f)) {
                return fail(SceneErrorCode::BadAttribute,
                            "material " + std::to_string(prim.material) + " baseColorFactor has " +
                                std::to_string(f.size()) + " values, expected 4 finite numbers");
            }
            out->baseColor = glm::vec4(float(f[0]), float(f[1]), float(f[2]), float(f[3]));
        }
        return true;
    }

    // Area-weighted smooth normals, for primitives without a NORMAL attribute.
    static void computeNormals(SceneMesh* m) {
        std::vector<glm::vec3> sum(m->vertices.size(), glm::vec3(0.0f));
        for (size_t t = 0; t + 2 < m->indices.size(); t += 3) {
            const uint32_t a = m->indices[t], b = m->indices[t + 1], c = m->indices[t + 2];
            const glm::vec3 n = glm::cross(m->vertices[b].position - m->vertices[a].position,
                                           m->vertices[c].position - m->vertices[a].position);
            sum[a] += n;
            sum[b] += n;
            sum[c] += n;
        }
        for (size_t i = 0; i < sum.size(); ++i) {
            const float len = glm::length(sum[i]);
            m->vertices[i].normal =
                len > 1e-12f && std::isfinite(len) ? sum[i] / len : glm::vec3(0.0f, 1.0f, 0.0f);
        }
    }

    bool convertMeshes(SceneData* scene, std::vector<size_t>* meshFirst) {
        meshFirst->assign(model_.meshes.size(), 0);
        for (size_t m = 0; m < model_.meshes.size(); ++m) {
            (*meshFirst)[m] = scene->meshes.size();
            for (size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
                SceneMesh out;
                if (!convertPrimitive(m, p, &out)) return false;
                scene->meshes.push_back(std::move(out));
            }
        }
        return true;
    }

    const Context& ctx_;
    const tinygltf::Model& model_;
    const ImageState& images_;
    const std::string& warn_;
};

}  // namespace

bool buildMeshes(const Context& ctx, const ImageState& images, const std::string& tinygltfWarnings,
                 SceneData* scene, std::vector<size_t>* meshFirst) {
    return MeshBuilder(ctx, images, tinygltfWarnings).run(scene, meshFirst);
}

}  // namespace cube::gltf
