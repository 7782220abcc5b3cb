// loadScene on the committed race scene (.gltf and .glb), and one test per error rule: each
// corrupt variant is made at run time in a temp dir, from a tinygltf round-trip of
// data/race.gltf or from a byte/text edit of the generated files.

#include "scene/SceneLoader.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace fs = std::filesystem;
using cube::SceneData;
using cube::SceneError;
using cube::SceneErrorCode;

namespace {

constexpr float kPosTol = 1e-4f;

std::string dataPath(const std::string& name) {
    return std::string(CUBE_SOURCE_DIR) + "/data/" + name;
}

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

// A fresh directory per test, removed afterwards.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string(info->test_suite_name()) + "_" + info->name();
        for (char& c : name) {
            if (c == '/') c = '_';
        }
        path_ =
            fs::temp_directory_path() / ("cube_scene_" + name + "_" + std::to_string(::getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    fs::path path_;
};

// data/race.gltf as a mutable tinygltf model (loaded with tinygltf's own loader).
tinygltf::Model raceModel() {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadASCIIFromFile(&model, &err, &warn, dataPath("race.gltf"))) << err;
    return model;
}

// Writes `model` as <dir>/<name>.gltf + <name>.bin (buffer URIs are reset to that .bin).
std::string writeModel(const TempDir& dir, tinygltf::Model model, const std::string& name) {
    for (tinygltf::Buffer& b : model.buffers) b.uri = name + ".bin";
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(nullptr, nullptr);  // keep image URIs exactly as given
    const std::string path = dir.file(name + ".gltf");
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&model, path, false, false, true, false));
    return path;
}

int meshIndex(const tinygltf::Model& m, const std::string& name) {
    for (size_t i = 0; i < m.meshes.size(); ++i) {
        if (m.meshes[i].name == name) return int(i);
    }
    ADD_FAILURE() << "no mesh " << name;
    return 0;
}

// Loads a file expected to fail; checks the code and that the message names the file.
SceneError expectFailure(const std::string& path, SceneErrorCode code) {
    SceneData scene;
    SceneError err;
    EXPECT_FALSE(cube::loadScene(path, &scene, &err)) << path;
    EXPECT_EQ(err.code, code) << err.str();
    EXPECT_EQ(err.file, path);
    EXPECT_NE(err.message.find(fs::path(path).filename().string()), std::string::npos)
        << err.message;
    EXPECT_TRUE(scene.nodes.empty() && scene.meshes.empty()) << "output touched on failure";
    return err;
}

glm::vec3 worldPos(const SceneData& s, const std::string& node) {
    const int i = s.findNode(node);
    EXPECT_GE(i, 0) << node;
    return i >= 0 ? glm::vec3(s.nodes[size_t(i)].world[3]) : glm::vec3(NAN);
}

void expectNear(glm::vec3 got, glm::vec3 want, float tol, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, tol) << what;
    EXPECT_NEAR(got.y, want.y, tol) << what;
    EXPECT_NEAR(got.z, want.z, tol) << what;
}

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
    // Wheel: r = 0.33 cylinder, 0.25 wide along Z, touching the ground.
    const cube::SceneNode& fl = scene.nodes[size_t(scene.findNode("wheel_FL"))];
    ASSERT_EQ(fl.meshes.size(), 1u);
    EXPECT_NEAR(fl.aabbMin.y, 0.0f, kPosTol);
    EXPECT_NEAR(fl.aabbMax.y, 0.66f, kPosTol);
    EXPECT_NEAR(fl.aabbMax.z - fl.aabbMin.z, 0.25f, kPosTol);
    // Body: 4.4 x 1.8, y from 0.25 to 0.85, deep blue.
    const cube::SceneNode& body = scene.nodes[size_t(scene.findNode("car_body"))];
    expectNear(body.aabbMin, {-2.2f, 0.25f, -0.9f}, kPosTol, "car_body min");
    expectNear(body.aabbMax, {2.2f, 0.85f, 0.9f}, kPosTol, "car_body max");
    const glm::vec4 paint = scene.meshes[size_t(body.meshes[0])].baseColor;
    EXPECT_GT(paint.b, 2.0f * paint.r);
    EXPECT_GT(paint.b, 2.0f * paint.g);
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
    for (const char* f : {"race.gltf", "race.bin", "race.glb", "smoke_atlas.png"}) {
        EXPECT_TRUE(readBytes(out + "/" + f) == readBytes(dataPath(f)))
            << f << " differs: run `build/bin/make_assets data` and commit the result";
    }
}

// ---- one test per error rule -------------------------------------------------------------------

TEST(SceneLoaderErrors, MissingFileIsFileNotFound) {
    const SceneError err =
        expectFailure("/nonexistent/dir/nothere.gltf", SceneErrorCode::FileNotFound);
    EXPECT_NE(err.str().find("FileNotFound"), std::string::npos);
}

TEST(SceneLoaderErrors, CorruptJsonIsParseError) {
    TempDir dir;
    std::string text = readBytes(dataPath("race.gltf"));
    const size_t at = text.find("\"accessors\"");
    ASSERT_NE(at, std::string::npos);
    text.insert(at, "\"broken\": [1, 2,, }");
    writeBytes(dir.file("race.gltf"), text);
    writeBytes(dir.file("race.bin"), readBytes(dataPath("race.bin")));
    const SceneError err = expectFailure(dir.file("race.gltf"), SceneErrorCode::ParseError);
    EXPECT_NE(err.message.find("tinygltf"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, TruncatedGltfIsParseError) {
    TempDir dir;
    const std::string text = readBytes(dataPath("race.gltf"));
    writeBytes(dir.file("race.gltf"), text.substr(0, text.size() / 2));
    writeBytes(dir.file("race.bin"), readBytes(dataPath("race.bin")));
    expectFailure(dir.file("race.gltf"), SceneErrorCode::ParseError);
}

TEST(SceneLoaderErrors, TruncatedGlbIsParseError) {
    TempDir dir;
    const std::string glb = readBytes(dataPath("race.glb"));
    for (size_t keep : {size_t(0), size_t(3), size_t(12), size_t(19), size_t(200), glb.size() / 2,
                        glb.size() - 1}) {
        SCOPED_TRACE("kept " + std::to_string(keep) + " bytes");
        writeBytes(dir.file("race.glb"), glb.substr(0, keep));
        expectFailure(dir.file("race.glb"), SceneErrorCode::ParseError);
    }
}

TEST(SceneLoaderErrors, MissingBinIsMissingBufferNamingTheFile) {
    TempDir dir;
    std::string text = readBytes(dataPath("race.gltf"));
    const size_t at = text.find("\"race.bin\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 10, "\"missing_race.bin\"");
    writeBytes(dir.file("race.gltf"), text);
    const SceneError err = expectFailure(dir.file("race.gltf"), SceneErrorCode::MissingBuffer);
    EXPECT_NE(err.message.find("missing_race.bin"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, ShortBinIsMissingBuffer) {
    TempDir dir;
    writeBytes(dir.file("race.gltf"), readBytes(dataPath("race.gltf")));
    const std::string bin = readBytes(dataPath("race.bin"));
    writeBytes(dir.file("race.bin"), bin.substr(0, bin.size() - 100));
    expectFailure(dir.file("race.gltf"), SceneErrorCode::MissingBuffer);
}

TEST(SceneLoaderErrors, AccessorCountTooLargeIsAccessorOutOfRange) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const int position =
        m.meshes[size_t(meshIndex(m, "car_body"))].primitives[0].attributes.at("POSITION");
    m.accessors[size_t(position)].count *= 2;
    const SceneError err =
        expectFailure(writeModel(dir, m, "race"), SceneErrorCode::AccessorOutOfRange);
    EXPECT_NE(err.message.find("accessor " + std::to_string(position)), std::string::npos)
        << err.message;
    EXPECT_NE(err.message.find("car_body"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, HugeAccessorCountIsRejectedWithoutAllocating) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const int position =
        m.meshes[size_t(meshIndex(m, "wheel"))].primitives[0].attributes.at("POSITION");
    m.accessors[size_t(position)].count = size_t(1) << 62;  // count * stride overflows 64 bits
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::AccessorOutOfRange);
}

TEST(SceneLoaderErrors, BufferViewPastItsBufferIsAccessorOutOfRange) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    m.bufferViews.back().byteLength += 4096;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::AccessorOutOfRange);
}

TEST(SceneLoaderErrors, IndexPastVertexCountIsIndexOutOfRange) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const tinygltf::Primitive& prim = m.meshes[size_t(meshIndex(m, "car_cabin"))].primitives[0];
    const tinygltf::Accessor& acc = m.accessors[size_t(prim.indices)];
    ASSERT_EQ(acc.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    const tinygltf::BufferView& bv = m.bufferViews[size_t(acc.bufferView)];
    const uint16_t bad = 60000;
    std::memcpy(&m.buffers[0].data[bv.byteOffset + acc.byteOffset + 2 * 5], &bad, 2);  // element 5
    const SceneError err =
        expectFailure(writeModel(dir, m, "race"), SceneErrorCode::IndexOutOfRange);
    EXPECT_NE(err.message.find("60000"), std::string::npos) << err.message;
    EXPECT_NE(err.message.find("car_cabin"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, MissingImageIsMissingTexture) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    tinygltf::Image img;
    img.uri = "no_such_smoke.png";
    m.images.push_back(img);
    tinygltf::Texture tex;
    tex.source = 0;
    m.textures.push_back(tex);
    m.materials[0].pbrMetallicRoughness.baseColorTexture.index = 0;
    const SceneError err =
        expectFailure(writeModel(dir, m, "race"), SceneErrorCode::MissingTexture);
    EXPECT_NE(err.message.find("no_such_smoke.png"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, ImageThatIsNotAnImageIsMissingTexture) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    tinygltf::Image img;
    img.uri = "smoke.png";
    m.images.push_back(img);
    writeBytes(dir.file("smoke.png"), "this is not a png");
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::MissingTexture);
}

TEST(SceneLoaderErrors, PresentImageLoads) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    tinygltf::Image img;
    img.uri = "smoke.png";
    m.images.push_back(img);
    writeBytes(dir.file("smoke.png"), readBytes(dataPath("smoke_atlas.png")));
    SceneData scene;
    SceneError err;
    EXPECT_TRUE(cube::loadScene(writeModel(dir, m, "race"), &scene, &err)) << err.str();
}

TEST(SceneLoaderErrors, MissingWheelIsMissingNode) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    for (tinygltf::Node& n : m.nodes) {
        if (n.name == "wheel_RR") n.name = "wheel_spare";
    }
    const std::string path = writeModel(dir, m, "race");
    SceneData scene;
    SceneError err;
    ASSERT_TRUE(cube::loadScene(path, &scene, &err)) << err.str();
    EXPECT_FALSE(cube::requireNodes(scene, {"wheel_FL", "wheel_FR", "wheel_RL", "wheel_RR"}, &err));
    EXPECT_EQ(err.code, SceneErrorCode::MissingNode);
    EXPECT_NE(err.message.find("wheel_RR"), std::string::npos) << err.message;
    EXPECT_NE(err.message.find("race.gltf"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, MissingPositionIsBadAttribute) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    m.meshes[size_t(meshIndex(m, "track"))].primitives[0].attributes.erase("POSITION");
    const SceneError err = expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadAttribute);
    EXPECT_NE(err.message.find("POSITION"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, WrongPositionTypeIsBadAttribute) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const int position =
        m.meshes[size_t(meshIndex(m, "track"))].primitives[0].attributes.at("POSITION");
    m.accessors[size_t(position)].type = TINYGLTF_TYPE_VEC2;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadAttribute);
    m.accessors[size_t(position)].type = TINYGLTF_TYPE_VEC3;
    m.accessors[size_t(position)].componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadAttribute);
}

TEST(SceneLoaderErrors, SparseAccessorIsUnsupported) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const int position =
        m.meshes[size_t(meshIndex(m, "track"))].primitives[0].attributes.at("POSITION");
    tinygltf::Accessor& acc = m.accessors[size_t(position)];
    acc.sparse.isSparse = true;
    acc.sparse.count = 1;
    acc.sparse.indices.bufferView = 0;
    acc.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    acc.sparse.values.bufferView = 0;
    const SceneError err = expectFailure(writeModel(dir, m, "race"), SceneErrorCode::Unsupported);
    EXPECT_NE(err.message.find("sparse"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, NonTrianglePrimitiveIsUnsupported) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    m.meshes[0].primitives[0].mode = TINYGLTF_MODE_LINE;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::Unsupported);
}

TEST(SceneLoaderErrors, HierarchyCycleIsBadNode) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const int car = int(std::find_if(m.nodes.begin(), m.nodes.end(),
                                     [](const tinygltf::Node& n) { return n.name == "car"; }) -
                        m.nodes.begin());
    const int body = m.nodes[size_t(car)].children[0];
    m.nodes[size_t(body)].children.push_back(car);  // car -> car_body -> car
    const SceneError err = expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadNode);
    EXPECT_NE(err.message.find("node"), std::string::npos) << err.message;
}

TEST(SceneLoaderErrors, BadChildIndexIsBadNode) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    m.nodes[0].children.push_back(int(m.nodes.size()) + 7);
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadNode);
    m.nodes[0].children.back() = -3;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadNode);
}

TEST(SceneLoaderErrors, MalformedTransformIsBadNode) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    m.nodes[0].translation = {1.0, 2.0};
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadNode);
}

TEST(SceneLoaderErrors, DanglingMeshIndexIsBadReference) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    m.nodes[0].mesh = 999;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadReference);
}

TEST(SceneLoaderErrors, NoMeshesIsEmpty) {
    TempDir dir;
    tinygltf::Model m;
    m.asset.version = "2.0";
    tinygltf::Node n;
    n.name = "lonely";
    m.nodes.push_back(n);
    tinygltf::Scene s;
    s.nodes = {0};
    m.scenes.push_back(s);
    m.defaultScene = 0;
    expectFailure(writeModel(dir, m, "empty"), SceneErrorCode::Empty);
}

TEST(SceneLoaderErrors, FailureLeavesThePreviousSceneUntouched) {
    SceneData scene;
    SceneError err;
    ASSERT_TRUE(cube::loadScene(dataPath("race.glb"), &scene, &err)) << err.str();
    const size_t nodes = scene.nodes.size(), meshes = scene.meshes.size();
    EXPECT_FALSE(cube::loadScene("/nonexistent/nothere.glb", &scene, &err));
    EXPECT_EQ(scene.nodes.size(), nodes);
    EXPECT_EQ(scene.meshes.size(), meshes);
    EXPECT_EQ(scene.sourcePath, dataPath("race.glb"));
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
