// make_assets: writes the committed data/ files (see data/README.md).
//
//   make_assets [out_dir=data]
//
// Output is deterministic: the same build produces the same bytes on every run (fixed seeds, no
// clocks, sorted JSON from tinygltf's writer). The race track is built in raceScene(), the car
// in make_assets_car.cpp, the trackside furniture in make_assets_trackside.cpp (shapes and the
// glTF writer: make_assets.h, make_assets_mesh.cpp), the smoke atlas in make_assets_smoke.cpp.

#include "make_assets.h"

#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

// Defined in make_assets_smoke.cpp.
bool writeSmokeAtlas(const std::string& path);

namespace {

using namespace assets;

// The scene's materials, in Material order: name, base colour, roughness, metallic.
struct MaterialSpec {
    const char* name;
    vec4 rgba;
    float roughness;
    float metallic;
};
const MaterialSpec kMaterials[kMaterialCount] = {
    {"grass", {0.22f, 0.42f, 0.16f, 1.0f}, 1.0f, 0.0f},  // kGrass
    {"asphalt", {0.17f, 0.17f, 0.19f, 1.0f}, 0.9f, 0.0f},  // kAsphalt
    {"gravel", {0.60f, 0.54f, 0.43f, 1.0f}, 1.0f, 0.0f},  // kGravel
    {"kerb_red", {0.75f, 0.08f, 0.06f, 1.0f}, 0.7f, 0.0f},  // kKerbRed
    {"kerb_white", {0.90f, 0.90f, 0.88f, 1.0f}, 0.7f, 0.0f},  // kKerbWhite
    {"concrete", {0.58f, 0.58f, 0.56f, 1.0f}, 0.9f, 0.0f},  // kConcrete
    {"tyre", {0.12f, 0.12f, 0.13f, 1.0f}, 0.9f, 0.0f},  // kTyre
    {"tyre_white", {0.85f, 0.85f, 0.83f, 1.0f}, 0.9f, 0.0f},  // kTyreWhite
    {"steel", {0.55f, 0.57f, 0.60f, 1.0f}, 0.5f, 1.0f},  // kSteel
    {"paint_white", {0.88f, 0.88f, 0.86f, 1.0f}, 0.8f, 0.0f},  // kPaintWhite
    {"paint_orange", {0.95f, 0.42f, 0.05f, 1.0f}, 0.7f, 0.0f},  // kPaintOrange
    {"paint_yellow", {0.95f, 0.80f, 0.10f, 1.0f}, 0.7f, 0.0f},  // kPaintYellow
    {"paint_red", {0.72f, 0.08f, 0.07f, 1.0f}, 0.7f, 0.0f},  // kPaintRed
    {"panel_dark", {0.08f, 0.08f, 0.10f, 1.0f}, 0.6f, 0.0f},  // kPanelDark
    {"stand_concrete", {0.62f, 0.61f, 0.58f, 1.0f}, 0.9f, 0.0f},  // kStandConcrete
    {"stand_seats", {0.10f, 0.30f, 0.70f, 1.0f}, 0.7f, 0.0f},  // kStandSeats
    {"car_paint", {0.04f, 0.12f, 0.50f, 1.0f}, 0.35f, 0.0f},  // kCarPaint
    {"car_trim", {0.06f, 0.06f, 0.07f, 1.0f}, 0.6f, 0.0f},  // kCarTrim
    {"car_headlight", {0.95f, 0.93f, 0.80f, 1.0f}, 0.2f, 0.0f},  // kCarHeadlight
    {"car_taillight", {0.70f, 0.03f, 0.03f, 1.0f}, 0.3f, 0.0f},  // kCarTaillight
    {"car_glass", {0.10f, 0.14f, 0.19f, 1.0f}, 0.05f, 0.0f},  // kCarGlass
    {"wheel_rubber", {0.03f, 0.03f, 0.03f, 1.0f}, 0.9f, 0.0f},  // kWheelRubber
    {"wheel_rim", {0.78f, 0.79f, 0.82f, 1.0f}, 0.3f, 1.0f},  // kWheelRim
};

// The race scene of data/README.md: metres, +Y up, the track along +X.
tinygltf::Model raceScene() {
    GltfBuilder b;
    for (const MaterialSpec& m : kMaterials) b.material(m.name, m.rgba, m.roughness, m.metallic);

    std::vector<int> roots;

    // Ground: grass plane (a single quad), asphalt/gravel as thin slabs just above it.
    MeshData grass;
    grass.quad({-200, 0, -100}, {200, 0, -100}, {200, 0, 100}, {-200, 0, 100}, {0, 1, 0});
    roots.push_back(
        b.node("grass", b.mesh("grass", {{grass, kGrass}}), vec3(0), surfaceTag("grass")));
    roots.push_back(b.node("track",
                           b.mesh("track", {{boxMesh({-150, 0, -6}, {150, 0.02f, 6}), kAsphalt}}),
                           vec3(0), surfaceTag("asphalt")));

    // Kerbs: one mesh (red blocks, white blocks as two primitives) centred on z = 0, instanced
    // at z = +-6.5 so each strip covers z in [6,7] / [-7,-6].
    MeshData red, white;
    for (int k = 0; k < 150; ++k) {
        const float x0 = -150.0f + 2.0f * float(k);
        (k % 2 == 0 ? red : white).box({x0, 0, -0.5f}, {x0 + 2.0f, 0.04f, 0.5f}, false);
    }
    const int kerb = b.mesh("kerb", {{red, kKerbRed}, {white, kKerbWhite}});
    roots.push_back(b.node("kerb_right", kerb, {0, 0, 6.5f}, surfaceTag("kerb")));
    roots.push_back(b.node("kerb_left", kerb, {0, 0, -6.5f}, surfaceTag("kerb")));

    roots.push_back(b.node(
        "runoff_pad", b.mesh("runoff_pad", {{boxMesh({-20, 0, -26}, {20, 0.02f, -7}), kAsphalt}}),
        vec3(0), surfaceTag("asphalt")));
    roots.push_back(
        b.node("gravel_trap",
               b.mesh("gravel_trap", {{boxMesh({60, 0, -20}, {120, 0.02f, -7}), kGravel}}),
               vec3(0), surfaceTag("gravel")));

    // Barriers: 1 m tall, 0.5 m thick concrete walls.
    roots.push_back(
        b.node("barrier_right",
               b.mesh("barrier_right", {{boxMesh({-150, 0, 8.5f}, {150, 1, 9}), kConcrete}}),
               vec3(0), solidTag()));
    roots.push_back(
        b.node("barrier_runoff",
               b.mesh("barrier_runoff", {{boxMesh({-25, 0, -27}, {25, 1, -26.5f}), kConcrete}}),
               vec3(0), solidTag()));

    // Tyre stacks: one mesh of four r = 0.35, 0.25 m tall tyres, black and painted white in
    // turn (two primitives), instanced.
    MeshData stack[2];
    for (int t = 0; t < 4; ++t)
        stack[t % 2].cylinder({0, 0.125f + 0.25f * float(t), 0}, {0, 1, 0}, 0.35f, 0.25f, 20);
    const int tyreStack = b.mesh("tyre_stack", {{stack[0], kTyre}, {stack[1], kTyreWhite}});
    const vec3 stacks[] = {{-22, 0, -8}, {-22, 0, -25}, {22, 0, -8}, {22, 0, -25}, {58, 0, -8}};
    for (size_t i = 0; i < std::size(stacks); ++i) {
        roots.push_back(b.node("tyres_" + std::to_string(i), tyreStack, stacks[i], solidTag()));
    }

    buildTrackside(b, &roots);
    roots.push_back(buildCar(b));

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
