#include "scene/SceneLoader.h"

#include <stb_image.h>
#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace cube {

namespace {

namespace fs = std::filesystem;

// Files (the scene itself and every external buffer/image) larger than this are refused: the
// loader must stay bounded on hostile input, and the race scene is well under 1 MB.
constexpr uint64_t kMaxFileBytes = 256ull << 20;

// ---- file system callbacks handed to tinygltf ----------------------------------------------

struct FsState {
    std::string baseDirPrefix;  // absolute directory of the scene file, with a trailing '/'
};

// External files are looked up next to the scene file only: tinygltf would also try the working
// directory, which makes a load depend on where the program was started.
bool fsFileExists(const std::string& path, void* user) {
    const auto* state = static_cast<const FsState*>(user);
    if (path.compare(0, state->baseDirPrefix.size(), state->baseDirPrefix) != 0) return false;
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

std::string fsExpandFilePath(const std::string& path, void*) { return path; }  // no shell expansion

bool readFile(const std::string& path, std::vector<unsigned char>* out, std::string* why) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        *why = "not a regular file";
        return false;
    }
    const uint64_t size = fs::file_size(path, ec);
    if (ec) {
        *why = ec.message();
        return false;
    }
    if (size > kMaxFileBytes) {
        *why = std::to_string(size) + " bytes exceeds the " + std::to_string(kMaxFileBytes) +
               "-byte limit";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(static_cast<size_t>(size));
    if (!in || (size > 0 && !in.read(reinterpret_cast<char*>(out->data()),
                                     static_cast<std::streamsize>(size)))) {
        *why = "read failed";
        return false;
    }
    return true;
}

bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void*) {
    std::string why;
    if (readFile(path, out, &why)) return true;
    if (err) *err += why;
    return false;
}

bool fsWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&,
                      void*) {
    if (err) *err += "the scene loader never writes files";
    return false;
}

// ---- image callback: never decodes, only notes what arrived ---------------------------------

struct ImageState {
    std::set<int> delivered;                       // image indices tinygltf handed over
    std::vector<std::pair<int, std::string>> bad;  // URI/data-URI images stb cannot identify
};

// Images are not needed by SceneData (colours come from baseColorFactor), so nothing is decoded.
// Bytes from a URI are a complete in-memory file and can be sniffed safely; bytes from a
// bufferView are NOT touched here because tinygltf has not range-checked that bufferView yet
// (validateImages does it afterwards).
bool noteImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
               const unsigned char* bytes, int size, void* user) {
    auto* state = static_cast<ImageState*>(user);
    state->delivered.insert(index);
    if (image->bufferView < 0) {
        int w = 0, h = 0, c = 0;
        if (size <= 0 || !stbi_info_from_memory(bytes, size, &w, &h, &c)) {
            state->bad.emplace_back(index,
                                    stbi_failure_reason() ? stbi_failure_reason() : "unknown");
        }
    }
    return true;
}

// ---- small helpers ---------------------------------------------------------------------------

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    for (char& c : s) {
        if (c == '\n') c = ' ';
    }
    return s;
}

// URIs go into messages; a data URI can be megabytes long.
std::string shortUri(const std::string& uri) {
    return uri.size() <= 80 ? uri : uri.substr(0, 77) + "...";
}

uint32_t readLE32(const unsigned char* p) {
    return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}

// tinygltf puts these into `err` only for *required* external loads, i.e. buffers (images go to
// `warn`), and for embedded buffer data it cannot decode.
bool isBufferFailure(const std::string& err) {
    for (const char* s :
         {"File not found :", "File read error :", "File size mismatch :", "File is empty :",
          "in Buffer", "GLB with empty BIN chunk", "Must be equal or less than binary size"}) {
        if (err.find(s) != std::string::npos) return true;
    }
    return false;
}

bool allFinite(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double d) { return std::isfinite(d); });
}

bool finiteMat(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

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

// ---- the conversion: one instance per load ---------------------------------------------------

class Converter {
public:
    Converter(const std::string& path, const tinygltf::Model& model, SceneError* error)
        : path_(path), model_(model), error_(error) {}

    bool run(SceneData* scene) {
        scene->sourcePath = path_;
        return validateExtensions() && validateBufferViews() && validateImages() &&
               convertMeshes(scene) && convertNodes(scene) && checkNotEmpty(*scene);
    }

    /// Filled by tinygltf during the load, read by validateImages afterwards.
    ImageState* imageState() { return &images_; }
    std::string* warnings() { return &warn_; }

    bool fail(SceneErrorCode code, const std::string& detail) {
        if (error_) {
            error_->code = code;
            error_->file = path_;
            error_->message = path_ + ": " + detail;
        }
        return false;
    }

private:
    bool validateExtensions() {
        if (!model_.extensionsRequired.empty()) {
            return fail(SceneErrorCode::Unsupported, "requires extension '" +
                                                         model_.extensionsRequired.front() +
                                                         "', which this loader does not support");
        }
        return true;
    }

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
            if (!images_.delivered.count(int(i))) {
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

    bool convertMeshes(SceneData* scene) {
        meshFirst_.assign(model_.meshes.size(), 0);
        for (size_t m = 0; m < model_.meshes.size(); ++m) {
            meshFirst_[m] = scene->meshes.size();
            for (size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
                SceneMesh out;
                if (!convertPrimitive(m, p, &out)) return false;
                scene->meshes.push_back(std::move(out));
            }
        }
        return true;
    }

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

        // Depth-first pre-order with an explicit stack: a deep chain cannot overflow the C++ stack.
        std::vector<std::pair<int, int>> stack;  // (glTF node, flat parent)
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, -1);
        while (!stack.empty()) {
            const auto [gi, flatParent] = stack.back();
            stack.pop_back();
            const tinygltf::Node& n = model_.nodes[size_t(gi)];
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
                stack.emplace_back(*c, flatIndex);
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

    ImageState images_;
    std::string warn_;
    const std::string& path_;
    const tinygltf::Model& model_;
    SceneError* error_;
    std::vector<size_t> meshFirst_;
};

// Checks the GLB container before tinygltf sees it: tinygltf 2.7.0 forgets the 8-byte BIN chunk
// header in its bounds check and could read past the end of a crafted file.
bool checkGlbLayout(const std::vector<unsigned char>& bytes, std::string* why, uint32_t* length) {
    if (bytes.size() < 20) {
        *why = "truncated: " + std::to_string(bytes.size()) + " bytes, a GLB header needs 20";
        return false;
    }
    *length = readLE32(&bytes[8]);
    const uint64_t json = readLE32(&bytes[12]);
    if (readLE32(&bytes[4]) != 2) {
        *why = "GLB version " + std::to_string(readLE32(&bytes[4])) + ", expected 2";
        return false;
    }
    if (*length > bytes.size()) {
        *why = "GLB header says " + std::to_string(*length) + " bytes but the file has " +
               std::to_string(bytes.size()) + " (truncated?)";
        return false;
    }
    if (20 + json > *length) {
        *why = "JSON chunk of " + std::to_string(json) + " bytes runs past the GLB length " +
               std::to_string(*length) + " (truncated?)";
        return false;
    }
    const uint64_t binHeader = 20 + json;
    if (binHeader < *length) {
        if (binHeader + 8 > *length ||
            binHeader + 8 + readLE32(&bytes[size_t(binHeader)]) > *length) {
            *why =
                "BIN chunk runs past the GLB length " + std::to_string(*length) + " (truncated?)";
            return false;
        }
    }
    return true;
}

}  // namespace

const char* sceneErrorCodeName(SceneErrorCode code) {
    switch (code) {
        case SceneErrorCode::None: return "None";
        case SceneErrorCode::FileNotFound: return "FileNotFound";
        case SceneErrorCode::ParseError: return "ParseError";
        case SceneErrorCode::MissingBuffer: return "MissingBuffer";
        case SceneErrorCode::AccessorOutOfRange: return "AccessorOutOfRange";
        case SceneErrorCode::IndexOutOfRange: return "IndexOutOfRange";
        case SceneErrorCode::BadAttribute: return "BadAttribute";
        case SceneErrorCode::MissingTexture: return "MissingTexture";
        case SceneErrorCode::MissingNode: return "MissingNode";
        case SceneErrorCode::Empty: return "Empty";
        case SceneErrorCode::BadNode: return "BadNode";
        case SceneErrorCode::BadReference: return "BadReference";
        case SceneErrorCode::Unsupported: return "Unsupported";
    }
    return "Unknown";
}

std::string SceneError::str() const {
    return std::string(sceneErrorCodeName(code)) + ": " + message;
}

bool loadScene(const std::string& path, SceneData* out, SceneError* error) {
    tinygltf::Model model;
    Converter conv(path, model, error);

    std::error_code ec;
    if (!fs::exists(path, ec) || !fs::is_regular_file(path, ec)) {
        return conv.fail(SceneErrorCode::FileNotFound,
                         "file not found, expected a .gltf or .glb file at this path");
    }
    std::vector<unsigned char> bytes;
    std::string why;
    if (!readFile(path, &bytes, &why)) {
        return conv.fail(SceneErrorCode::FileNotFound, "cannot be read: " + why);
    }

    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const std::string ext = fs::path(path).extension().string();
    if (!binary && (ext == ".glb" || ext == ".GLB")) {
        return conv.fail(SceneErrorCode::ParseError,
                         "expected binary glTF (a .glb starting with 'glTF'), found " +
                             std::to_string(bytes.size()) + " bytes without that magic");
    }
    uint32_t glbLength = 0;
    if (binary && !checkGlbLayout(bytes, &why, &glbLength)) {
        return conv.fail(SceneErrorCode::ParseError, "invalid GLB: " + why);
    }

    FsState fsState;
    fsState.baseDirPrefix = fs::absolute(fs::path(path), ec).parent_path().string();
    if (fsState.baseDirPrefix.empty() || fsState.baseDirPrefix.back() != '/')
        fsState.baseDirPrefix += '/';

    tinygltf::TinyGLTF gltf;
    gltf.SetFsCallbacks(tinygltf::FsCallbacks{&fsFileExists, &fsExpandFilePath, &fsReadWholeFile,
                                              &fsWriteWholeFile, &fsState});
    gltf.SetImageLoader(&noteImage, conv.imageState());

    std::string err;
    bool parsed = false;
    try {
        const std::string baseDir = fsState.baseDirPrefix;
        parsed = binary
                     ? gltf.LoadBinaryFromMemory(&model, &err, conv.warnings(), bytes.data(),
                                                 glbLength, baseDir)
                     : gltf.LoadASCIIFromString(&model, &err, conv.warnings(),
                                                reinterpret_cast<const char*>(bytes.data()),
                                                static_cast<unsigned int>(bytes.size()), baseDir);
    } catch (const std::exception& e) {
        err += std::string(err.empty() ? "" : "; ") + "exception: " + e.what();
        parsed = false;
    }
    if (!parsed) {
        if (isBufferFailure(err)) {
            return conv.fail(SceneErrorCode::MissingBuffer,
                             "buffer data could not be loaded (tinygltf: " + trimmed(err) + ")");
        }
        return conv.fail(SceneErrorCode::ParseError,
                         std::string("not valid ") + (binary ? "binary glTF" : "glTF JSON") +
                             " (tinygltf: " + (err.empty() ? "no details" : trimmed(err)) + ")");
    }

    SceneData scene;
    try {
        if (!conv.run(&scene)) return false;
    } catch (const std::exception& e) {  // e.g. bad_alloc on a hostile file
        return conv.fail(SceneErrorCode::ParseError, std::string("conversion failed: ") + e.what());
    }
    *out = std::move(scene);
    if (error) *error = SceneError{};
    return true;
}

bool requireNodes(const SceneData& scene, const std::vector<std::string>& names,
                  SceneError* error) {
    for (const std::string& name : names) {
        if (scene.findNode(name) < 0) {
            if (error) {
                error->code = SceneErrorCode::MissingNode;
                error->file = scene.sourcePath;
                error->message = scene.sourcePath + ": node '" + name +
                                 "' not found, expected a node with exactly that name";
            }
            return false;
        }
    }
    return true;
}

}  // namespace cube
