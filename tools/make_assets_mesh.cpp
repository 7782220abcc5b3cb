// make_assets: MeshData's shapes and the glTF writer's bookkeeping (see make_assets.h).

#include "make_assets.h"

#include <cmath>

namespace assets {

void MeshData::quad(vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec3 n) {
    const uint32_t b = uint32_t(pos.size());
    for (const vec3& p : {p0, p1, p2, p3}) {
        pos.push_back(p);
        nrm.push_back(n);
    }
    const bool ccw = glm::dot(glm::cross(p1 - p0, p2 - p0), n) + glm::dot(glm::cross(p2 - p0, p3 - p0), n) > 0.0f;
    const uint32_t order[6] = {0, 1, 2, 0, 2, 3};
    const uint32_t flipped[6] = {0, 2, 1, 0, 3, 2};
    for (uint32_t k : ccw ? order : flipped) idx.push_back(b + k);
}

void MeshData::box(vec3 lo, vec3 hi, bool bottom) {
    const vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                       {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    quad(c[3], c[2], c[6], c[7], {0, 1, 0});               // top
    if (bottom) quad(c[0], c[1], c[5], c[4], {0, -1, 0});  // bottom
    quad(c[1], c[2], c[6], c[5], {1, 0, 0});               // +X
    quad(c[0], c[3], c[7], c[4], {-1, 0, 0});              // -X
    quad(c[4], c[5], c[6], c[7], {0, 0, 1});               // +Z
    quad(c[0], c[1], c[2], c[3], {0, 0, -1});              // -Z
}

void MeshData::hexa(const vec3 c[8], bool bottom) {
    vec3 centre(0.0f);
    for (int i = 0; i < 8; ++i) centre += c[i] * 0.125f;
    const int faces[6][4] = {{3, 2, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {0, 3, 7, 4}, {4, 5, 6, 7}, {0, 1, 2, 3}};
    for (int f = 0; f < 6; ++f) {
        if (f == 1 && !bottom) continue;
        const vec3 a = c[faces[f][0]], b = c[faces[f][1]], d = c[faces[f][2]], e = c[faces[f][3]];
        vec3 n = glm::cross(d - a, e - b);
        if (glm::length(n) < 1e-8f) continue;  // collapsed to a line (a wedge's edge)
        n = glm::normalize(n);
        if (glm::dot(n, 0.25f * (a + b + d + e) - centre) < 0.0f) n = -n;
        quad(a, b, d, e, n);
    }
}

void MeshData::cylinder(vec3 centre, vec3 axis, float radius, float length, int segments) {
    // u x v = axis, so (cos, sin) runs counter-clockwise seen from +axis.
    const vec3 u = axis.y != 0.0f ? vec3(0, 0, 1) : (axis.z != 0.0f ? vec3(1, 0, 0) : vec3(0, 1, 0));
    const vec3 v = glm::cross(axis, u);
    const vec3 h = axis * (0.5f * length);
    auto dir = [&](int i) {
        const double t = 2.0 * 3.14159265358979323846 * double(i % segments) / double(segments);
        return float(std::cos(t)) * u + float(std::sin(t)) * v;
    };
    for (int i = 0; i < segments; ++i) {
        const vec3 d0 = dir(i), d1 = dir(i + 1);
        // Side: one quad per segment with the face normal (flat-shaded tyre tread).
        quad(centre + radius * d0 - h, centre + radius * d1 - h, centre + radius * d1 + h,
             centre + radius * d0 + h, glm::normalize(d0 + d1));
    }
    for (float side : {1.0f, -1.0f}) {  // caps as triangle fans
        const uint32_t c = uint32_t(pos.size());
        pos.push_back(centre + side * h);
        nrm.push_back(side * axis);
        for (int i = 0; i < segments; ++i) {
            pos.push_back(centre + side * h + radius * dir(i));
            nrm.push_back(side * axis);
        }
        for (int i = 0; i < segments; ++i) {
            const uint32_t a = c + 1 + uint32_t(i), b = c + 1 + uint32_t((i + 1) % segments);
            idx.insert(idx.end(), {c, side > 0 ? a : b, side > 0 ? b : a});
        }
    }
}

void MeshData::tubeArc(vec3 centre, float rIn, float rOut, float z0, float z1, float a0, float a1, int segments) {
    auto dir = [&](int i) {
        const double t = double(a0) + double(a1 - a0) * double(i) / double(segments);
        return vec3(float(std::cos(t)), float(std::sin(t)), 0.0f);
    };
    const vec3 lo(0, 0, z0), hi(0, 0, z1);
    for (int i = 0; i < segments; ++i) {
        const vec3 d0 = dir(i), d1 = dir(i + 1), n = glm::normalize(d0 + d1);
        const vec3 o0 = centre + rOut * d0, o1 = centre + rOut * d1, i0 = centre + rIn * d0, i1 = centre + rIn * d1;
        quad(o0 + lo, o1 + lo, o1 + hi, o0 + hi, n);  // outer skin
        if (rIn > 0.0f) quad(i0 + lo, i1 + lo, i1 + hi, i0 + hi, -n);  // inner skin
        quad(i0 + hi, i1 + hi, o1 + hi, o0 + hi, {0, 0, 1});  // flat rings
        quad(i0 + lo, i1 + lo, o1 + lo, o0 + lo, {0, 0, -1});
    }
    if (std::abs(a1 - a0) < 2.0f * kPi - 1e-4f) {  // open ends
        for (int end = 0; end < 2; ++end) {
            const vec3 d = dir(end ? segments : 0);
            const vec3 n = glm::normalize(glm::cross(vec3(0, 0, 1), d)) * (end ? 1.0f : -1.0f) *
                           (a1 > a0 ? 1.0f : -1.0f);
            quad(centre + rIn * d + lo, centre + rOut * d + lo, centre + rOut * d + hi, centre + rIn * d + hi, n);
        }
    }
}

void MeshData::frustum(vec3 base, float r0, float r1, float h, int segments) {
    auto dir = [&](int i) {
        const double t = 2.0 * 3.14159265358979323846 * double(i % segments) / double(segments);
        return vec3(float(std::cos(t)), 0.0f, float(std::sin(t)));
    };
    const vec3 up(0, h, 0);
    for (int i = 0; i < segments; ++i) {
        const vec3 d0 = dir(i), d1 = dir(i + 1), mid = glm::normalize(d0 + d1);
        // The slanted side's normal: outward, tilted up by the taper.
        const vec3 n = glm::normalize(mid * h + vec3(0, r0 - r1, 0));
        quad(base + r0 * d0, base + r0 * d1, base + up + r1 * d1, base + up + r1 * d0, n);
    }
    if (r1 <= 0.0f) return;
    const uint32_t c = uint32_t(pos.size());
    pos.push_back(base + up);
    nrm.push_back({0, 1, 0});
    for (int i = 0; i < segments; ++i) {
        pos.push_back(base + up + r1 * dir(i));
        nrm.push_back({0, 1, 0});
    }
    for (int i = 0; i < segments; ++i) {
        const uint32_t a = c + 1 + uint32_t(i), b = c + 1 + uint32_t((i + 1) % segments);
        idx.insert(idx.end(), {c, b, a});  // counter-clockwise seen from above (+Z is toward -angle)
    }
}

void MeshData::append(const MeshData& other) {
    const uint32_t b = uint32_t(pos.size());
    pos.insert(pos.end(), other.pos.begin(), other.pos.end());
    nrm.insert(nrm.end(), other.nrm.begin(), other.nrm.end());
    for (uint32_t i : other.idx) idx.push_back(b + i);
}

// ---- glTF assembly -----------------------------------------------------------------------------

GltfBuilder::GltfBuilder() {
    model_.asset.version = "2.0";
    model_.asset.generator = "cube make_assets";
    model_.buffers.emplace_back();
}

int GltfBuilder::material(const std::string& name, vec4 rgba, float roughness, float metallic) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {rgba.r, rgba.g, rgba.b, rgba.a};
    m.pbrMetallicRoughness.metallicFactor = metallic;
    m.pbrMetallicRoughness.roughnessFactor = roughness;
    model_.materials.push_back(m);
    return int(model_.materials.size()) - 1;
}

int GltfBuilder::mesh(const std::string& name, const std::vector<std::pair<MeshData, int>>& parts) {
    tinygltf::Mesh m;
    m.name = name;
    for (const auto& [data, mat] : parts) {
        tinygltf::Primitive p;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        p.material = mat;
        p.attributes["POSITION"] = vec3Accessor(data.pos, true);
        p.attributes["NORMAL"] = vec3Accessor(data.nrm, false);
        p.indices = indexAccessor(data.idx, data.pos.size());
        m.primitives.push_back(p);
    }
    model_.meshes.push_back(m);
    return int(model_.meshes.size()) - 1;
}

int GltfBuilder::node(const std::string& name, int meshIndex, vec3 translation, Value extras) {
    tinygltf::Node n;
    n.name = name;
    n.mesh = meshIndex;
    if (translation != vec3(0.0f)) n.translation = {translation.x, translation.y, translation.z};
    n.extras = std::move(extras);
    model_.nodes.push_back(n);
    return int(model_.nodes.size()) - 1;
}

tinygltf::Model GltfBuilder::finish(const std::string& sceneName, const std::vector<int>& roots) {
    tinygltf::Scene s;
    s.name = sceneName;
    s.nodes = roots;
    model_.scenes.push_back(s);
    model_.defaultScene = 0;
    model_.buffers[0].data = bin_;
    return model_;
}

int GltfBuilder::view(const void* data, size_t bytes, int target) {
    while (bin_.size() % 4) bin_.push_back(0);  // every view starts 4-byte aligned
    tinygltf::BufferView bv;
    bv.buffer = 0;
    bv.byteOffset = bin_.size();
    bv.byteLength = bytes;
    bv.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    bin_.insert(bin_.end(), p, p + bytes);
    model_.bufferViews.push_back(bv);
    return int(model_.bufferViews.size()) - 1;
}

int GltfBuilder::vec3Accessor(const std::vector<vec3>& v, bool withBounds) {
    tinygltf::Accessor a;
    a.bufferView = view(v.data(), v.size() * sizeof(vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = v.size();
    if (withBounds) {  // required by the spec for POSITION
        vec3 lo = v[0], hi = v[0];
        for (const vec3& p : v) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        a.minValues = {lo.x, lo.y, lo.z};
        a.maxValues = {hi.x, hi.y, hi.z};
    }
    model_.accessors.push_back(a);
    return int(model_.accessors.size()) - 1;
}

int GltfBuilder::indexAccessor(const std::vector<uint32_t>& idx, size_t vertexCount) {
    tinygltf::Accessor a;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = idx.size();
    if (vertexCount <= 65536) {
        const std::vector<uint16_t> narrow(idx.begin(), idx.end());
        a.bufferView = view(narrow.data(), narrow.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    } else {
        a.bufferView = view(idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    }
    model_.accessors.push_back(a);
    return int(model_.accessors.size()) - 1;
}

}  // namespace assets
