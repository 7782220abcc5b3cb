// glTF at the loader level: limits checked before parsing (JSON nesting, hierarchy
// depth), the validation rules tinygltf accepts silently (each with its code and the Khronos
// validator's rule name), required extensions named, uris confined to the model's folder,
// ignored features listed once, and a node tree of any shape assembled in linear time.
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using cube::SceneData;
using cube::SceneError;
using cube::SceneErrorCode;

namespace {

class Folder {
public:
    Folder() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("cube_gltf_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "model");
    }
    ~Folder() {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    /// Writes into <dir>/model/ (the model's folder); `name` may go up with "../".
    std::string write(const std::string& name, const std::string& bytes) const {
        const fs::path p = dir_ / "model" / name;
        std::ofstream(p, std::ios::binary) << bytes;
        return p.string();
    }

private:
    fs::path dir_;
};

const char* kTriangle = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

std::string gltf(const std::string& nodes, const std::string& extra = "", const std::string& version = "2.0",
                 const std::string& bufferUri = std::string("data:application/octet-stream;base64,") + kTriangle) {
    return R"({"asset":{"version":")" + version + R"("},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
           R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":")" + bufferUri + R"("}])" +
           extra + "}";
}

std::string chain(int levels) {
    std::string s = "[";
    for (int i = 0; i + 1 < levels; ++i) s += R"({"children":[)" + std::to_string(i + 1) + "]},";
    return s + R"({"name":"leaf","mesh":0}])";
}

SceneError expectCode(const std::string& path, SceneErrorCode code, const std::string& mention) {
    SceneData scene;
    SceneError err;
    EXPECT_FALSE(cube::loadScene(path, &scene, &err)) << path;
    EXPECT_EQ(err.code, code) << err.str();
    EXPECT_NE(err.message.find(fs::path(path).filename().string()), std::string::npos) << err.str();
    EXPECT_NE(err.message.find(mention), std::string::npos) << "should mention '" << mention << "': " << err.str();
    return err;
}

}  // namespace

TEST(GltfValidation, DeepJsonIsTooDeepBeforeAnyParserSeesIt) {
    Folder f;
    for (const int depth : {129, 10000, 200000}) {
        const std::string deep = std::string(size_t(depth), '[') + std::string(size_t(depth), ']');
        expectCode(f.write("deep.gltf", gltf(R"([{"mesh":0}])", R"(,"extras":)" + deep)), SceneErrorCode::TooDeep,
                   "128 levels");
        // Unbalanced (truncated) nesting is refused the same way.
        expectCode(f.write("open.gltf", std::string(size_t(depth), '{')), SceneErrorCode::TooDeep, "line 1");
    }
    // Brackets inside strings (with escaped quotes) do not count.
    const std::string inString = "\"\\\"" + std::string(5000, '[') + "\"";
    SceneData scene;
    SceneError err;
    EXPECT_TRUE(cube::loadScene(f.write("strings.gltf", gltf(R"([{"mesh":0,"name":)" + inString + "}]")), &scene, &err))
        << err.str();
    // 128 levels are accepted.
    const std::string ok = std::string(120, '[') + std::string(120, ']');
    EXPECT_TRUE(cube::loadScene(f.write("ok.gltf", gltf(R"([{"mesh":0}])", R"(,"extras":)" + ok)), &scene, &err))
        << err.str();
}

TEST(GltfValidation, NodeRulesNameTheKhronosRule) {
    Folder f;
    const std::string identity = "[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]";
    expectCode(f.write("mtrs.gltf", gltf(R"([{"mesh":0,"matrix":)" + identity + R"(,"scale":[1,1,1]}])")),
               SceneErrorCode::BadNode, "[NODE_MATRIX_TRS]");
    const SceneError text = expectCode(f.write("text.gltf", gltf(R"([{"mesh":0,"translation":[0,"up",0]}])")),
                                       SceneErrorCode::BadNode, "translation[1]");
    EXPECT_NE(text.message.find("[ARRAY_TYPE_MISMATCH]"), std::string::npos) << text.str();
    expectCode(f.write("obj.gltf", gltf(R"([{"mesh":0,"rotation":{"x":0}}])")), SceneErrorCode::BadNode,
               "[TYPE_MISMATCH]");
    expectCode(f.write("len.gltf", gltf(R"([{"mesh":0,"scale":[1,1]}])")), SceneErrorCode::BadNode,
               "[ARRAY_LENGTH_NOT_IN_LIST]");
    expectCode(f.write("child.gltf", gltf(R"([{"mesh":0,"children":["one"]}])")), SceneErrorCode::BadNode,
               "children");
}

TEST(GltfValidation, AssetVersionAndRequiredExtensions) {
    Folder f;
    expectCode(f.write("v3.gltf", gltf(R"([{"mesh":0}])", "", "3.0")), SceneErrorCode::InvalidGltf,
               "[UNKNOWN_ASSET_MAJOR_VERSION]");
    expectCode(f.write("vx.gltf", gltf(R"([{"mesh":0}])", "", "two")), SceneErrorCode::InvalidGltf, "[PATTERN_MISMATCH]");
    expectCode(f.write("noasset.gltf", R"({"nodes":[]})"), SceneErrorCode::InvalidGltf, "asset");
    const SceneError e = expectCode(
        f.write("draco.gltf", gltf(R"([{"mesh":0}])", R"(,"extensionsUsed":["KHR_draco_mesh_compression","EXT_meshopt_compression"],)"
                                                      R"("extensionsRequired":["KHR_draco_mesh_compression","EXT_meshopt_compression"])")),
        SceneErrorCode::Unsupported, "KHR_draco_mesh_compression");
    EXPECT_NE(e.message.find("EXT_meshopt_compression"), std::string::npos) << e.str();
    EXPECT_NE(e.message.find("Draco"), std::string::npos) << e.str();
}

TEST(GltfValidation, UrisStayInTheModelsFolder) {
    Folder f;
    f.write("../secret.bin", std::string(36, '\0'));
    expectCode(f.write("up.gltf", gltf(R"([{"mesh":0}])", "", "2.0", "../secret.bin")), SceneErrorCode::BadUri, "'..'");
    expectCode(f.write("up2.gltf", gltf(R"([{"mesh":0}])", "", "2.0", "sub/%2E%2E/%2e%2e/secret.bin")),
               SceneErrorCode::BadUri, "'..'");
    expectCode(f.write("abs.gltf", gltf(R"([{"mesh":0}])", "", "2.0", "/etc/passwd")), SceneErrorCode::BadUri,
               "absolute");
    expectCode(f.write("scheme.gltf", gltf(R"([{"mesh":0}])", "", "2.0", "file:///etc/passwd")), SceneErrorCode::BadUri,
               "scheme");
    // A symlink in the folder that points out of it is not followed.
    fs::create_symlink("../secret.bin", fs::path(f.write("x", "")).parent_path() / "link.bin");
    expectCode(f.write("link.gltf", gltf(R"([{"mesh":0}])", "", "2.0", "link.bin")), SceneErrorCode::MissingBuffer,
               "outside the model's folder");
    // The same bytes inside the folder load.
    f.write("inside.bin", std::string(kTriangle).empty() ? "" : std::string(36, '\0'));
    SceneData scene;
    SceneError err;
    EXPECT_TRUE(cube::loadScene(f.write("inside.gltf", gltf(R"([{"mesh":0}])", "", "2.0", "inside.bin")), &scene, &err))
        << err.str();
}

TEST(GltfValidation, IgnoredFeaturesAreListedOnce) {
    Folder f;
    SceneData scene;
    SceneError err;
    ASSERT_TRUE(cube::loadScene(
        f.write("features.gltf",
                gltf(R"([{"mesh":0}])", R"(,"extensionsUsed":["KHR_materials_unlit"],"animations":[{"channels":[],"samplers":[]}],)"
                                        R"("skins":[{"joints":[0]}],"cameras":[{"type":"perspective","perspective":{"yfov":1,"znear":0.1}}])")),
        &scene, &err))
        << err.str();
    ASSERT_EQ(scene.warnings.size(), 4u);
    for (const char* w : {"KHR_materials_unlit", "animation", "skin", "camera"}) {
        int n = 0;
        for (const std::string& line : scene.warnings) n += line.find(w) != std::string::npos;
        EXPECT_EQ(n, 1) << w;
    }
    for (const std::string& line : scene.warnings) EXPECT_NE(line.find("features.gltf: "), std::string::npos) << line;
}

TEST(GltfValidation, HierarchyDepthIsBoundedAndAssemblyIsLinear) {
    Folder f;
    // Past the limit: refused by name, whatever the length, before tinygltf builds a model.
    for (const int levels : {4097, 100000}) {
        expectCode(f.write("chain.gltf", gltf(chain(levels))), SceneErrorCode::TooDeep, "4096 levels");
    }
    // A cycle under a deep branch is still reported as the cycle, not as depth.
    std::string cyc = R"([{"children":[1]},{"children":[2]},{"children":[1,3]},{"mesh":0}])";
    expectCode(f.write("cycle.gltf", gltf(cyc)), SceneErrorCode::BadNode, "node");
    // Up to the limit: loads, parents precede children, the leaf's world is the product.
    SceneData scene;
    SceneError err;
    ASSERT_TRUE(cube::loadScene(f.write("ok.gltf", gltf(chain(4096))), &scene, &err)) << err.str();
    ASSERT_EQ(scene.nodes.size(), 4096u);
    for (size_t i = 1; i < scene.nodes.size(); ++i) ASSERT_EQ(scene.nodes[i].parent, int(i) - 1);
    EXPECT_TRUE(scene.isDescendant(4095, 0));
    // Wide: 100,000 siblings under one root.
    std::string wide = R"([{"children":[)";
    for (int i = 1; i <= 100000; ++i) wide += std::to_string(i) + (i < 100000 ? "," : "");
    wide += "]}";
    for (int i = 1; i <= 100000; ++i) wide += R"(,{"mesh":0})";
    wide += "]";
    ASSERT_TRUE(cube::loadScene(f.write("wide.gltf", gltf(wide)), &scene, &err)) << err.str();
    EXPECT_EQ(scene.nodes.size(), 100001u);
}

TEST(GltfValidation, NonRegularFilesAreRefusedWithoutBlocking) {
    Folder f;
    const std::string pipe = fs::path(f.write("x", "")).parent_path() / "pipe.gltf";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0644), 0);
    expectCode(pipe, SceneErrorCode::FileNotFound, "a FIFO");
    expectCode(fs::path(pipe).parent_path().string(), SceneErrorCode::FileNotFound, "a directory");
}
