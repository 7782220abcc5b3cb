// A deterministic mutation sweep over the committed scene: truncations, byte flips and number
// edits must each either load or fail with a named code and a message naming the file, never
// crash (run under -DCUBE_SANITIZE=ON to also catch out-of-bounds reads). Not a replacement for
// a libFuzzer target, but it runs on every test pass.

#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace {

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

uint32_t nextRandom(uint32_t* state) {  // xorshift32: fixed seed, same sweep every run
    *state ^= *state << 13;
    *state ^= *state >> 17;
    *state ^= *state << 5;
    return *state;
}

class MutationSweep : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("cube_scene_fuzz_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    // Loads `bytes` written as `name`; returns true when it loaded.
    bool tryLoad(const std::string& name, const std::string& bytes) {
        const std::string path = (dir_ / name).string();
        writeBytes(path, bytes);
        cube::SceneData scene;
        cube::SceneError err;
        const bool ok = cube::loadScene(path, &scene, &err);
        if (ok) {
            EXPECT_FALSE(scene.meshes.empty());
            for (const cube::SceneMesh& m : scene.meshes) {
                for (uint32_t i : m.indices) EXPECT_LT(i, m.vertices.size());
            }
        } else {
            EXPECT_NE(err.code, cube::SceneErrorCode::None);
            EXPECT_EQ(err.message.rfind(path, 0), 0u) << err.message;
        }
        return ok;
    }

    fs::path dir_;
};

TEST_F(MutationSweep, GlbTruncationsAndByteFlips) {
    const std::string glb = readBytes(std::string(CUBE_SOURCE_DIR) + "/data/race.glb");
    ASSERT_GT(glb.size(), 1000u);
    int failures = 0, runs = 0;
    for (size_t keep = 0; keep < glb.size(); keep += 997, ++runs) {
        failures += !tryLoad("cut.glb", glb.substr(0, keep));
    }
    EXPECT_EQ(failures, runs) << "every truncation must fail";

    uint32_t rng = 0x1234567u;
    for (int i = 0; i < 300; ++i) {
        std::string m = glb;
        const int flips = 1 + int(nextRandom(&rng) % 4);
        for (int f = 0; f < flips; ++f) {
            // Bias towards the header and JSON chunk, where structure lives.
            const size_t limit =
                (nextRandom(&rng) & 1) ? m.size() : std::min<size_t>(m.size(), 20000);
            m[nextRandom(&rng) % limit] = char(nextRandom(&rng) & 0xff);
        }
        tryLoad("flip.glb", m);
    }
}

TEST_F(MutationSweep, GltfNumberEdits) {
    const std::string text = readBytes(std::string(CUBE_SOURCE_DIR) + "/data/race.gltf");
    writeBytes((dir_ / "race.bin").string(),
               readBytes(std::string(CUBE_SOURCE_DIR) + "/data/race.bin"));
    const char* replacements[] = {"4294967295", "-1",    "0", "18446744073709551615",
                                  "1e39",       "65535", "7"};
    uint32_t rng = 0x9e3779b9u;
    int loaded = 0;
    for (int i = 0; i < 400; ++i) {
        // Replace one number in the JSON with an extreme value.
        size_t at = nextRandom(&rng) % text.size();
        while (at < text.size() && !(text[at] >= '0' && text[at] <= '9')) ++at;
        if (at == text.size()) continue;
        size_t end = at;
        while (end < text.size() &&
               (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.'))
            ++end;
        std::string m = text;
        m.replace(at, end - at, replacements[nextRandom(&rng) % std::size(replacements)]);
        loaded += tryLoad("race.gltf", m);
    }
    EXPECT_GT(loaded, 0);  // some edits (colours, min/max) are harmless and must still load
}

}  // namespace
