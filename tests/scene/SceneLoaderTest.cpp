// loadScene on the committed race scene (.gltf and .glb) and on a small hand-built file.
// The error rules are in SceneLoaderErrorsTest.cpp.

#include "SceneTestUtil.h"

using namespace scene_test;

namespace {

// ---- the committed race scene -------------------------------------------------------------------

class RaceScene : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override {
        SceneError err;
        ASSERT_TRUE(cube::loadScene(dataPath(GetParam()), &scene, &err)) << err.str();
    }
    SceneData scene;
};

TEST_P(RaceScene, WheelsSitAtTheirCornersUnderTheCar) {
    SceneError err;
    ASSERT_TRUE(cube::requireNodes(
        scene, {"car", "car_body", "car_cabin", "wheel_FL", "wheel_FR", "wheel_RL", "wheel_RR"},
        &err))
        << err.str();
    expectNear(worldPos(scene, "wheel_FL"), {1.35f, 0.33f, -0.8f}, kPosTol, "wheel_FL");
    expectNear(worldPos(scene, "wheel_FR"), {1.35f, 0.33f, 0.8f}, kPosTol, "wheel_FR");
    expectNear(worldPos(scene, "wheel_RL"), {-1.35f, 0.33f, -0.8f}, kPosTol, "wheel_RL");
    expectNear(worldPos(scene, "wheel_RR"), {-1.35f, 0.33f, 0.8f}, kPosTol, "wheel_RR");

    const int car = scene.findNode("car");
    EXPECT_EQ(scene.nodes[size_t(car)].parent, -1);
    EXPECT_EQ(scene.nodes[size_t(car)].world, glm::mat4(1.0f));
    for (const char* w :
         {"wheel_FL", "wheel_FR", "wheel_RL", "wheel_RR", "car_body", "car_cabin"}) {
        EXPECT_TRUE(scene.isDescendant(scene.findNode(w), car)) << w;
    }
    // Wheel: r = 0.33, 0.25 wide along Z (the axle), touching the ground; a tyre and a rim
    // (two primitives of different colours: the rim's spokes show the wheel turning).
    const cube::SceneNode& fl = scene.nodes[size_t(scene.findNode("wheel_FL"))];
    ASSERT_EQ(fl.meshes.size(), 2u);
    EXPECT_NEAR(fl.aabbMin.y, 0.0f, kPosTol);
    EXPECT_NEAR(fl.aabbMax.y, 0.66f, kPosTol);
    EXPECT_NEAR(fl.aabbMax.z - fl.aabbMin.z, 0.25f, kPosTol);
    const glm::vec4 tyre = scene.meshes[size_t(fl.meshes[0])].baseColor;
    const glm::vec4 rim = scene.meshes[size_t(fl.meshes[1])].baseColor;
    EXPECT_GT(rim.r + rim.g + rim.b, 4.0f * (tyre.r + tyre.g + tyre.b)) << "a bright rim on a dark tyre";
    // Body: about 4.5 m long and 1.8 m wide, its first primitive deep blue paint.
    const cube::SceneNode& body = scene.nodes[size_t(scene.findNode("car_body"))];
    EXPECT_NEAR(body.aabbMax.x - body.aabbMin.x, 4.5f, 0.3f);
    EXPECT_LE(body.aabbMax.z - body.aabbMin.z, 1.9f);
    EXPECT_LT(body.aabbMin.y, 0.25f);
    const glm::vec4 paint = scene.meshes[size_t(body.meshes[0])].baseColor;
    EXPECT_GT(paint.b, 2.0f * paint.r);
    EXPECT_GT(paint.b, 2.0f * paint.g);
    // The cabin has a glass primitive besides its shell.
    const cube::SceneNode& cabin = scene.nodes[size_t(scene.findNode("car_cabin"))];
    ASSERT_EQ(cabin.meshes.size(), 2u);
    EXPECT_NE(scene.meshes[size_t(cabin.meshes[0])].baseColor, scene.meshes[size_t(cabin.meshes[1])].baseColor);
}

TEST_P(RaceScene, BarriersAndTyreStacksAreSolid) {
    const std::vector<int> barriers = scene.nodesWithPrefix("barrier");
    const std::vector<int> tyres = scene.nodesWithPrefix("tyres");
    EXPECT_GE(barriers.size(), 2u);
    EXPECT_GE(tyres.size(), 4u);
    for (int i : barriers) EXPECT_TRUE(scene.nodes[size_t(i)].solid) << scene.nodes[size_t(i)].name;
    for (int i : tyres) EXPECT_TRUE(scene.nodes[size_t(i)].solid) << scene.nodes[size_t(i)].name;

    const cube::SceneNode& wall = scene.nodes[size_t(scene.findNode("barrier_right"))];
    expectNear(wall.aabbMin, {-150.0f, 0.0f, 8.5f}, kPosTol, "barrier_right min");
    expectNear(wall.aabbMax, {150.0f, 1.0f, 9.0f}, kPosTol, "barrier_right max");

    // A 0.5 m sphere centred 0.2 m in front of the wall's face overlaps it by 0.3 m.
    int hit = -1;
    EXPECT_NEAR(scene.penetrationDepth({10.0f, 0.5f, 8.3f}, 0.5f, &hit), 0.3f, kPosTol);
    EXPECT_EQ(hit, scene.findNode("barrier_right"));
    // Tyre stack at (22, -8): r = 0.35, 1 m tall.
    EXPECT_NEAR(scene.penetrationDepth({22.0f, 0.5f, -8.0f + 0.35f + 0.4f}, 0.5f, &hit), 0.1f,
                1e-3f);
    EXPECT_EQ(scene.nodes[size_t(hit)].name.rfind("tyres", 0), 0u);
    // The middle of the track touches nothing solid.
    EXPECT_EQ(scene.penetrationDepth({0.0f, 0.5f, 0.0f}, 0.5f, &hit), 0.0f);
    EXPECT_EQ(hit, -1);
}

TEST_P(RaceScene, SurfacesUnderTheWheels) {
    EXPECT_EQ(scene.surfaceAt(0.0f, 0.0f), "asphalt");
    EXPECT_EQ(scene.surfaceAt(10.0f, 6.5f), "kerb");
    EXPECT_EQ(scene.surfaceAt(10.0f, -6.5f), "kerb");
    EXPECT_EQ(scene.surfaceAt(90.0f, -15.0f), "gravel");
    EXPECT_EQ(scene.surfaceAt(0.0f, 50.0f), "grass");
    EXPECT_EQ(scene.surfaceAt(0.0f, -20.0f), "asphalt");  // run-off pad
    EXPECT_EQ(scene.surfaceAt(0.0f, 150.0f), "");         // off the world
}

TEST_P(RaceScene, MeshesAreValidTriangleLists) {
    ASSERT_FALSE(scene.meshes.empty());
    for (const cube::SceneMesh& m : scene.meshes) {
        ASSERT_FALSE(m.vertices.empty()) << m.name;
        EXPECT_EQ(m.indices.size() % 3, 0u) << m.name;
        for (uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size()) << m.name;
        for (const cube::SceneVertex& v : m.vertices) {
            ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f) << m.name;
        }
    }
    // The kerb mesh has a red and a white primitive: two SceneMeshes on each kerb node.
    const cube::SceneNode& kerb = scene.nodes[size_t(scene.findNode("kerb_right"))];
    ASSERT_EQ(kerb.meshes.size(), 2u);
    EXPECT_NE(scene.meshes[size_t(kerb.meshes[0])].baseColor,
              scene.meshes[size_t(kerb.meshes[1])].baseColor);
    expectNear(kerb.aabbMin, {-150.0f, 0.0f, 6.0f}, kPosTol, "kerb_right min");
    expectNear(kerb.aabbMax, {150.0f, 0.04f, 7.0f}, kPosTol, "kerb_right max");
}

INSTANTIATE_TEST_SUITE_P(GltfAndGlb, RaceScene, ::testing::Values("race.gltf", "race.glb"));

TEST(SceneLoader, GltfAndGlbGiveTheSameScene) {
    SceneData a, b;
    SceneError err;
    ASSERT_TRUE(cube::loadScene(dataPath("race.gltf"), &a, &err)) << err.str();
    ASSERT_TRUE(cube::loadScene(dataPath("race.glb"), &b, &err)) << err.str();
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_EQ(a.nodes[i].name, b.nodes[i].name);
        EXPECT_EQ(a.nodes[i].world, b.nodes[i].world) << a.nodes[i].name;
        EXPECT_EQ(a.nodes[i].surface, b.nodes[i].surface);
    }
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices) << a.meshes[i].name;
        EXPECT_EQ(a.meshes[i].vertices.size(), b.meshes[i].vertices.size()) << a.meshes[i].name;
    }
}

// The committed data/ must be what the generator makes today (skipped when make_assets is not
// built).
TEST(SceneLoader, CommittedDataMatchesTheGenerator) {
    const std::string tool = std::string(CUBE_TEST_BIN_DIR) + "/make_assets";
    if (!fs::exists(tool)) GTEST_SKIP() << "make_assets not built";
    TempDir dir;
    const std::string out = dir.file("gen");
    ASSERT_EQ(std::system((tool + " " + out + " > /dev/null").c_str()), 0);
    for (const char* f : {"race.gltf", "race.bin", "race.glb", "smoke_atlas.png", "smoke_normals.png"}) {
        EXPECT_TRUE(readBytes(out + "/" + f) == readBytes(dataPath(f)))
            << f << " differs: run `build/bin/make_assets data` and commit the result";
    }
}
// ---- transforms of a small hand-built file
// -------------------------------------------------------

TEST(SceneLoader, ComposesTrsAndMatrixTransformsDownTheHierarchy) {
    TempDir dir;
    tinygltf::Model m;
    m.asset.version = "2.0";
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 0, 1};
    tinygltf::Buffer buf;
    buf.data.resize(sizeof tri);
    std::memcpy(buf.data.data(), tri, sizeof tri);
    m.buffers.push_back(buf);
    tinygltf::BufferView bv;
    bv.buffer = 0;
    bv.byteLength = sizeof tri;
    m.bufferViews.push_back(bv);
    tinygltf::Accessor acc;
    acc.bufferView = 0;
    acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    acc.type = TINYGLTF_TYPE_VEC3;
    acc.count = 3;
    m.accessors.push_back(acc);
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = 0;  // no NORMAL, no indices: the loader makes both
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = "tri";
    mesh.primitives.push_back(prim);
    m.meshes.push_back(mesh);

    tinygltf::Node parent, child, matrixChild;
    parent.name = "parent";
    parent.translation = {1, 2, 3};
    parent.rotation = {0, std::sqrt(0.5), 0, std::sqrt(0.5)};  // +90 degrees about +Y: +X -> -Z
    parent.scale = {2, 2, 2};
    parent.children = {1, 2};
    child.name = "child";
    child.translation = {1, 0, 0};
    child.mesh = 0;
    matrixChild.name = "matrix_child";
    matrixChild.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1};  // column-major: +5 in Y
    m.nodes = {parent, child, matrixChild};
    tinygltf::Scene s;
    s.nodes = {0};
    m.scenes.push_back(s);
    m.defaultScene = 0;

    SceneData scene;
    SceneError err;
    ASSERT_TRUE(cube::loadScene(writeModel(dir, m, "trs"), &scene, &err)) << err.str();
    ASSERT_EQ(scene.nodes.size(), 3u);
    EXPECT_EQ(scene.nodes[0].name, "parent");
    EXPECT_EQ(scene.nodes[1].parent, 0);
    expectNear(worldPos(scene, "child"), {1.0f, 2.0f, 1.0f}, kPosTol, "child");
    expectNear(worldPos(scene, "matrix_child"), {1.0f, 12.0f, 3.0f}, kPosTol, "matrix_child");
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2}));
    // (1,0,0) x (0,0,1) = (0,-1,0): the generated normal follows the counter-clockwise winding.
    expectNear(scene.meshes[0].vertices[0].normal, {0.0f, -1.0f, 0.0f}, kPosTol, "normal");
    // World box of the child's triangle: local x,z in [0,1] -> scaled by 2, rotated, moved.
    const cube::SceneNode& c = scene.nodes[size_t(scene.findNode("child"))];
    expectNear(c.aabbMin, {1.0f, 2.0f, -1.0f}, kPosTol, "child min");
    expectNear(c.aabbMax, {3.0f, 2.0f, 1.0f}, kPosTol, "child max");
}

}  // namespace
