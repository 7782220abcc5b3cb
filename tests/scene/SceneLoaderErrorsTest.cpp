// One test per loadScene error rule: each corrupt variant is made at run time in a temp dir,
// from a tinygltf round-trip of data/race.gltf or from a byte/text edit of the generated files.

#include "SceneTestUtil.h"

using namespace scene_test;

namespace {

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

// The index of the POSITION accessor of mesh `mesh`'s first primitive.
int positionAccessor(const tinygltf::Model& m, const std::string& mesh) {
    return m.meshes[size_t(meshIndex(m, mesh))].primitives[0].attributes.at("POSITION");
}

TEST(SceneLoaderErrors, AccessorCountTooLargeIsAccessorOutOfRange) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const int position = positionAccessor(m, "car_body");
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
    const int position = positionAccessor(m, "wheel");
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

// The race model with one more image, at `uri` beside the .gltf.
tinygltf::Model raceModelWithImage(const std::string& uri) {
    tinygltf::Model m = raceModel();
    tinygltf::Image img;
    img.uri = uri;
    m.images.push_back(img);
    return m;
}

TEST(SceneLoaderErrors, MissingImageIsMissingTexture) {
    TempDir dir;
    tinygltf::Model m = raceModelWithImage("no_such_smoke.png");
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
    tinygltf::Model m = raceModelWithImage("smoke.png");
    writeBytes(dir.file("smoke.png"), "this is not a png");
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::MissingTexture);
}

TEST(SceneLoaderErrors, PresentImageLoads) {
    TempDir dir;
    tinygltf::Model m = raceModelWithImage("smoke.png");
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
    const int position = positionAccessor(m, "track");
    m.accessors[size_t(position)].type = TINYGLTF_TYPE_VEC2;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadAttribute);
    m.accessors[size_t(position)].type = TINYGLTF_TYPE_VEC3;
    m.accessors[size_t(position)].componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    expectFailure(writeModel(dir, m, "race"), SceneErrorCode::BadAttribute);
}

TEST(SceneLoaderErrors, SparseAccessorIsUnsupported) {
    TempDir dir;
    tinygltf::Model m = raceModel();
    const int position = positionAccessor(m, "track");
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

}  // namespace
