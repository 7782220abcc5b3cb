// make_assets: writes the committed data/ files (see data/README.md).
//
//   make_assets [out_dir=data]
//
// Output is deterministic: the same build produces the same bytes on every run (fixed seeds, no
// clocks, sorted JSON from tinygltf's writer). The race scene is built in race_scene(), the smoke
// atlas in make_assets_smoke.cpp.

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

// Defined in make_assets_smoke.cpp (the tool's files share no header: it is two files).
bool writeSmokeAtlas(const std::string& path);

namespace {

using glm::vec3;
using glm::vec4;
using tinygltf::Value;

// ---- geometry ----------------------------------------------------------------------------------

// One primitive's worth of triangles, before it goes into the buffer.
struct MeshData {
    std::vector<vec3> pos, nrm;
    std::vector<uint32_t> idx;

    // Quad p0..p3 (a convex loop) facing `n`: the winding is fixed up to be counter-clockwise seen
    // from the side `n` points to, so callers list corners in any rotational order.
    void quad(vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec3 n) {
        const uint32_t b = uint32_t(pos.size());
        for (const vec3& p : {p0, p1, p2, p3}) {
            pos.push_back(p);
            nrm.push_back(n);
        }
        const bool ccw = glm::dot(glm::cross(p1 - p0, p2 - p0), n) > 0.0f;
        const uint32_t order[6] = {0, 1, 2, 0, 2, 3};
        const uint32_t flipped[6] = {0, 2, 1, 0, 3, 2};
        for (uint32_t k : ccw ? order : flipped) idx.push_back(b + k);
    }

    // Axis-aligned box; the bottom face is left out when it lies on the ground.
    void box(vec3 lo, vec3 hi, bool bottom = true) {
        const vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                           {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                           {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
        quad(c[3], c[2], c[6], c[7], {0, 1, 0});               // top
        if (bottom) quad(c[0], c[1], c[5], c[4], {0, -1, 0});  // bottom
        quad(c[1], c[2], c[6], c[5], {1, 0, 0});               // +X
        quad(c[0], c[3], c[7], c[4], {-1, 0, 0});              // -X
        quad(c[4], c[5], c[6], c[7], {0, 0, 1});               // +Z
        quad(c[0], c[1], c[2], c[3], {0, 0, -1});              // -Z
    }

    // Closed cylinder around `axis` (a unit X/Y/Z vector) through `centre`.
    void cylinder(vec3 centre, vec3 axis, float radius, float length, int segments) {
        // u x v = axis, so (cos, sin) runs counter-clockwise seen from +axis.
        const vec3 u =
            axis.y != 0.0f ? vec3(0, 0, 1) : (axis.z != 0.0f ? vec3(1, 0, 0) : vec3(0, 1, 0));
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
};

// ---- glTF assembly -----------------------------------------------------------------------------

class GltfBuilder {
public:
    GltfBuilder() {
        model_.asset.version = "2.0";
        model_.asset.generator = "cube make_assets";
        model_.buffers.emplace_back();
    }

    int material(const std::string& name, vec4 rgba, float roughness = 0.8f) {
        tinygltf::Material m;
        m.name = name;
        m.pbrMetallicRoughness.baseColorFactor = {rgba.r, rgba.g, rgba.b, rgba.a};
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        m.pbrMetallicRoughness.roughnessFactor = roughness;
        model_.materials.push_back(m);
        return int(model_.materials.size()) - 1;
    }

    // One glTF mesh; each (geometry, material) pair becomes one primitive.
    int mesh(const std::string& name, const std::vector<std::pair<MeshData, int>>& parts) {
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

    int node(const std::string& name, int meshIndex, vec3 translation, Value extras = Value()) {
        tinygltf::Node n;
        n.name = name;
        n.mesh = meshIndex;
        if (translation != vec3(0.0f))
            n.translation = {translation.x, translation.y, translation.z};
        n.extras = std::move(extras);
        model_.nodes.push_back(n);
        return int(model_.nodes.size()) - 1;
    }

    void child(int parent, int childNode) {
        model_.nodes[size_t(parent)].children.push_back(childNode);
    }

    tinygltf::Model finish(const std::string& sceneName, const std::vector<int>& roots) {
        tinygltf::Scene s;
        s.name = sceneName;
        s.nodes = roots;
        model_.scenes.push_back(s);
        model_.defaultScene = 0;
        model_.buffers[0].data = bin_;
        return model_;
    }

private:
    int view(const void* data, size_t bytes, int target) {
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

    int vec3Accessor(const std::vector<vec3>& v, bool withBounds) {
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

    int indexAccessor(const std::vector<uint32_t>& idx, size_t vertexCount) {
        tinygltf::Accessor a;
        a.type = TINYGLTF_TYPE_SCALAR;
        a.count = idx.size();
        if (vertexCount <= 65536) {
            const std::vector<uint16_t> narrow(idx.begin(), idx.end());
            a.bufferView =
                view(narrow.data(), narrow.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        } else {
            a.bufferView = view(idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        }
        model_.accessors.push_back(a);
        return int(model_.accessors.size()) - 1;
    }

    tinygltf::Model model_;
    std::vector<unsigned char> bin_;
};

Value surfaceTag(const char* surface) {
    return Value(Value::Object{{"surface", Value(std::string(surface))}});
}

Value solidTag() { return Value(Value::Object{{"solid", Value(true)}}); }

MeshData boxMesh(vec3 lo, vec3 hi, bool bottom = false) {
    MeshData m;
    m.box(lo, hi, bottom);
    return m;
}

// The race scene of data/README.md: metres, +Y up, the track along +X.
tinygltf::Model raceScene() {
    GltfBuilder b;
    const int grassMat = b.material("grass", {0.22f, 0.42f, 0.16f, 1.0f}, 1.0f);
    const int asphaltMat = b.material("asphalt", {0.17f, 0.17f, 0.19f, 1.0f}, 0.9f);
    const int gravelMat = b.material("gravel", {0.60f, 0.54f, 0.43f, 1.0f}, 1.0f);
    const int kerbRedMat = b.material("kerb_red", {0.75f, 0.08f, 0.06f, 1.0f}, 0.7f);
    const int kerbWhiteMat = b.material("kerb_white", {0.90f, 0.90f, 0.88f, 1.0f}, 0.7f);
    const int concreteMat = b.material("concrete", {0.58f, 0.58f, 0.56f, 1.0f}, 0.9f);
    const int tyreMat = b.material("tyre", {0.12f, 0.12f, 0.13f, 1.0f}, 0.9f);
    const int paintMat = b.material("car_paint", {0.04f, 0.12f, 0.50f, 1.0f}, 0.35f);
    const int glassMat = b.material("car_glass", {0.05f, 0.07f, 0.09f, 1.0f}, 0.1f);
    const int rubberMat = b.material("wheel_rubber", {0.03f, 0.03f, 0.03f, 1.0f}, 0.9f);

    std::vector<int> roots;

    // Ground: grass plane (a single quad), asphalt/gravel as thin slabs just above it.
    MeshData grass;
    grass.quad({-200, 0, -100}, {200, 0, -100}, {200, 0, 100}, {-200, 0, 100}, {0, 1, 0});
    roots.push_back(
        b.node("grass", b.mesh("grass", {{grass, grassMat}}), vec3(0), surfaceTag("grass")));
    roots.push_back(b.node("track",
                           b.mesh("track", {{boxMesh({-150, 0, -6}, {150, 0.02f, 6}), asphaltMat}}),
                           vec3(0), surfaceTag("asphalt")));

    // Kerbs: one mesh (red blocks, white blocks as two primitives) centred on z = 0, instanced
    // at z = +-6.5 so each strip covers z in [6,7] / [-7,-6].
    MeshData red, white;
    for (int k = 0; k < 150; ++k) {
        const float x0 = -150.0f + 2.0f * float(k);
        (k % 2 == 0 ? red : white).box({x0, 0, -0.5f}, {x0 + 2.0f, 0.04f, 0.5f}, false);
    }
    const int kerb = b.mesh("kerb", {{red, kerbRedMat}, {white, kerbWhiteMat}});
    roots.push_back(b.node("kerb_right", kerb, {0, 0, 6.5f}, surfaceTag("kerb")));
    roots.push_back(b.node("kerb_left", kerb, {0, 0, -6.5f}, surfaceTag("kerb")));

    roots.push_back(b.node(
        "runoff_pad", b.mesh("runoff_pad", {{boxMesh({-20, 0, -26}, {20, 0.02f, -7}), asphaltMat}}),
        vec3(0), surfaceTag("asphalt")));
    roots.push_back(
        b.node("gravel_trap",
               b.mesh("gravel_trap", {{boxMesh({60, 0, -20}, {120, 0.02f, -7}), gravelMat}}),
               vec3(0), surfaceTag("gravel")));

    // Barriers: 1 m tall, 0.5 m thick concrete walls.
    roots.push_back(
        b.node("barrier_right",
               b.mesh("barrier_right", {{boxMesh({-150, 0, 8.5f}, {150, 1, 9}), concreteMat}}),
               vec3(0), solidTag()));
    roots.push_back(
        b.node("barrier_runoff",
               b.mesh("barrier_runoff", {{boxMesh({-25, 0, -27}, {25, 1, -26.5f}), concreteMat}}),
               vec3(0), solidTag()));

    // Tyre stacks: one mesh of four r = 0.35, 0.25 m tall tyres, instanced.
    MeshData stack;
    for (int t = 0; t < 4; ++t)
        stack.cylinder({0, 0.125f + 0.25f * float(t), 0}, {0, 1, 0}, 0.35f, 0.25f, 20);
    const int tyreStack = b.mesh("tyre_stack", {{stack, tyreMat}});
    const vec3 stacks[] = {{-22, 0, -8}, {-22, 0, -25}, {22, 0, -8}, {22, 0, -25}, {58, 0, -8}};
    for (size_t i = 0; i < std::size(stacks); ++i) {
        roots.push_back(b.node("tyres_" + std::to_string(i), tyreStack, stacks[i], solidTag()));
    }

    // The car: forward +X, right +Z; the root stays at the origin (the game moves it).
    const int car = b.node("car", -1, vec3(0));
    b.child(car,
            b.node("car_body",
                   b.mesh("car_body",
                          {{boxMesh({-2.2f, -0.3f, -0.9f}, {2.2f, 0.3f, 0.9f}, true), paintMat}}),
                   {0, 0.55f, 0}));
    b.child(
        car,
        b.node("car_cabin",
               b.mesh("car_cabin",
                      {{boxMesh({-1.1f, -0.225f, -0.75f}, {1.1f, 0.225f, 0.75f}, true), glassMat}}),
               {-0.2f, 1.075f, 0}));
    MeshData wheelGeom;
    wheelGeom.cylinder(vec3(0), {0, 0, 1}, 0.33f, 0.25f, 24);
    const int wheel = b.mesh("wheel", {{wheelGeom, rubberMat}});
    const std::pair<const char*, vec3> wheels[] = {{"wheel_FL", {1.35f, 0.33f, -0.8f}},
                                                   {"wheel_FR", {1.35f, 0.33f, 0.8f}},
                                                   {"wheel_RL", {-1.35f, 0.33f, -0.8f}},
                                                   {"wheel_RR", {-1.35f, 0.33f, 0.8f}}};
    for (const auto& [name, at] : wheels) b.child(car, b.node(name, wheel, at));
    roots.push_back(car);

    return b.finish("race", roots);
}

bool writeRace(const std::string& dir) {
    tinygltf::TinyGLTF writer;
    tinygltf::Model model = raceScene();

    model.buffers[0].uri = "race.bin";  // .gltf + external .bin
    if (!writer.WriteGltfSceneToFile(&model, dir + "/race.gltf", false, false, true, false)) {
        std::fprintf(stderr, "make_assets: cannot write %s/race.gltf\n", dir.c_str());
        return false;
    }
    model.buffers[0].uri.clear();  // .glb: buffer 0 becomes the BIN chunk
    if (!writer.WriteGltfSceneToFile(&model, dir + "/race.glb", false, true, false, true)) {
        std::fprintf(stderr, "make_assets: cannot write %s/race.glb\n", dir.c_str());
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : "data";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        std::fprintf(stderr, "make_assets: cannot create %s: %s\n", dir.c_str(),
                     ec.message().c_str());
        return 1;
    }
    if (!writeRace(dir) || !writeSmokeAtlas(dir + "/smoke_atlas.png")) return 1;
    for (const char* f : {"race.gltf", "race.bin", "race.glb", "smoke_atlas.png", "smoke_normals.png"}) {
        const std::string p = dir + "/" + f;
        std::printf("wrote %-28s %8llu bytes\n", p.c_str(),
                    static_cast<unsigned long long>(std::filesystem::file_size(p, ec)));
    }
    return 0;
}
