#pragma once
// Shared by the make_assets sources (one tool, several files): triangle geometry (MeshData) and
// the glTF model being written (GltfBuilder). Everything is in metres, +Y up; flat-shaded (each
// face carries its own normal), so every primitive reads well under one sun.

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace assets {

using glm::vec3;
using glm::vec4;
using tinygltf::Value;

constexpr float kPi = 3.14159265358979f;

// One primitive's worth of triangles, before it goes into the buffer.
struct MeshData {
    std::vector<vec3> pos, nrm;
    std::vector<uint32_t> idx;

    // Quad p0..p3 (a convex loop) facing `n`: the winding is fixed up to be counter-clockwise seen
    // from the side `n` points to, so callers list corners in any rotational order.
    void quad(vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec3 n);
    // Axis-aligned box; the bottom face is left out when it lies on the ground.
    void box(vec3 lo, vec3 hi, bool bottom = true);
    // A box with moved corners (tapers, slopes, rotated blocks), corners in box() order:
    // c[0..3] at the -Z end (lo, +X, +X+Y, +Y), c[4..7] the same at the +Z end. Each face gets
    // the normal of its diagonals, pointing away from the centre; faces that collapse to a line
    // are left out.
    void hexa(const vec3 c[8], bool bottom = true);
    // Closed cylinder around `axis` (a unit X/Y/Z vector) through `centre`.
    void cylinder(vec3 centre, vec3 axis, float radius, float length, int segments);
    // Part of a thick tube around +Z through `centre` (z from z0 to z1, radii rIn..rOut), from
    // angle a0 to a1 (radians, from +X toward +Y): outer and inner skins, the two flat rings, and
    // end caps unless it closes (a full turn). Tyres, rim rings and wheel arches.
    void tubeArc(vec3 centre, float rIn, float rOut, float z0, float z1, float a0, float a1, int segments);
    // Vertical cone frustum standing on `base` (radius r0 at the bottom, r1 at the top, h tall),
    // with a top cap when r1 > 0 and no bottom.
    void frustum(vec3 base, float r0, float r1, float h, int segments);
    // Appends another mesh's triangles.
    void append(const MeshData& other);
};

inline Value surfaceTag(const char* surface) {
    return Value(Value::Object{{"surface", Value(std::string(surface))}});
}
inline Value solidTag() { return Value(Value::Object{{"solid", Value(true)}}); }

inline MeshData boxMesh(vec3 lo, vec3 hi, bool bottom = false) {
    MeshData m;
    m.box(lo, hi, bottom);
    return m;
}

// The glTF model under construction: materials, meshes (one primitive per (geometry,
// material) pair), nodes with a translation, one buffer.
class GltfBuilder {
public:
    GltfBuilder();
    int material(const std::string& name, vec4 rgba, float roughness = 0.8f, float metallic = 0.0f);
    int mesh(const std::string& name, const std::vector<std::pair<MeshData, int>>& parts);
    int node(const std::string& name, int meshIndex, vec3 translation, Value extras = Value());
    void child(int parent, int childNode) { model_.nodes[size_t(parent)].children.push_back(childNode); }
    tinygltf::Model finish(const std::string& sceneName, const std::vector<int>& roots);

private:
    int view(const void* data, size_t bytes, int target);
    int vec3Accessor(const std::vector<vec3>& v, bool withBounds);
    int indexAccessor(const std::vector<uint32_t>& idx, size_t vertexCount);

    tinygltf::Model model_;
    std::vector<unsigned char> bin_;
};

// Every material of the scene, one index each: the glTF material index is the enumerator
// (kMaterials in make_assets.cpp writes them in this order). The track's, the trackside
// furniture's, the car's.
enum Material : int {
    kGrass, kAsphalt, kGravel, kKerbRed, kKerbWhite, kConcrete, kTyre, kTyreWhite,
    kSteel, kPaintWhite, kPaintOrange, kPaintYellow, kPaintRed, kPanelDark, kStandConcrete, kStandSeats,
    kCarPaint, kCarTrim, kCarHeadlight, kCarTaillight, kCarGlass, kWheelRubber, kWheelRim,
    kMaterialCount
};

// The race car (make_assets_car.cpp): the "car" node with car_body, car_cabin and wheel_FL,
// wheel_FR, wheel_RL, wheel_RR (data/README.md). Returns the car node.
int buildCar(GltfBuilder& b);
// Trackside furniture (make_assets_trackside.cpp): guard rails, debris fence, marshal posts,
// boards, a grandstand, a gantry and cones; appends their root nodes.
void buildTrackside(GltfBuilder& b, std::vector<int>* roots);

}  // namespace assets
