#pragma once
// Helpers shared by the scene loader tests: temp folders, the race scene as a mutable tinygltf
// model, and the failure check every error test makes.
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


namespace scene_test {


constexpr float kPosTol = 1e-4f;

inline std::string dataPath(const std::string& name) {
    return std::string(CUBE_SOURCE_DIR) + "/data/" + name;
}

inline std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeBytes(const std::string& path, const std::string& bytes) {
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
inline tinygltf::Model raceModel() {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadASCIIFromFile(&model, &err, &warn, dataPath("race.gltf"))) << err;
    return model;
}

// Writes `model` as <dir>/<name>.gltf + <name>.bin (buffer URIs are reset to that .bin).
inline std::string writeModel(const TempDir& dir, tinygltf::Model model, const std::string& name) {
    for (tinygltf::Buffer& b : model.buffers) b.uri = name + ".bin";
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(nullptr, nullptr);  // keep image URIs exactly as given
    const std::string path = dir.file(name + ".gltf");
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&model, path, false, false, true, false));
    return path;
}

inline int meshIndex(const tinygltf::Model& m, const std::string& name) {
    for (size_t i = 0; i < m.meshes.size(); ++i) {
        if (m.meshes[i].name == name) return int(i);
    }
    ADD_FAILURE() << "no mesh " << name;
    return 0;
}

// Loads a file expected to fail; checks the code and that the message names the file.
inline SceneError expectFailure(const std::string& path, SceneErrorCode code) {
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

inline glm::vec3 worldPos(const SceneData& s, const std::string& node) {
    const int i = s.findNode(node);
    EXPECT_GE(i, 0) << node;
    return i >= 0 ? glm::vec3(s.nodes[size_t(i)].world[3]) : glm::vec3(NAN);
}

inline void expectNear(glm::vec3 got, glm::vec3 want, float tol, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, tol) << what;
    EXPECT_NEAR(got.y, want.y, tol) << what;
    EXPECT_NEAR(got.z, want.z, tol) << what;
}

}  // namespace scene_test
