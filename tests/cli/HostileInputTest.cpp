// Hostile input at start-up: cube_game must say where and what, then exit non-zero, never crash.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "RunCommand.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace hostile_input_test {
namespace {

using Outcome = cubetest::CommandResult;

Outcome launch(const std::string& args, const std::string& env = "") {
    // A crash shows as a signal (WIFSIGNALED: status 200) or as the shell's 128+N.
    return cubetest::runCommand(
        env + " " + std::string(CUBE_TEST_BIN_DIR) + "/cube_game --frames 2 --size 64x48 " + args + " 2>&1", 200);
}

std::string dir() {
    static std::string d;
    if (d.empty()) {
        d = "/tmp/cube_hostile_" + std::to_string(::getpid());
        EXPECT_EQ(std::system(("mkdir -p " + d).c_str()), 0);
    }
    return d;
}

std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = dir() + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

void expectRejected(const Outcome& r, const std::string& mustMention, const char* what) {
    EXPECT_EQ(r.status, 1) << what << "\n" << r.output;
    EXPECT_NE(r.output.find(mustMention), std::string::npos) << what << ": message should name " << mustMention
                                                             << "\n" << r.output;
}

}  // namespace

TEST(HostileInput, ReactionFiles) {
    const struct {
        const char* name;
        std::string text;
        const char* mention;
    } cases[] = {
        {"empty.yaml", "", "empty.yaml"},
        {"truncated.yaml", "reactions:\n  - name: smoke\n    type: wheel_smoke\n    emission: {rate: 4", "truncated.yaml:"},
        {"malformed.yaml", "reactions: [ {name: a, type: dust}\n  - : :\n", "malformed.yaml:"},
        {"wrongtype.yaml", "reactions:\n  - name: a\n    type: dust\n    emission: {capacity: lots}\n", "wrongtype.yaml:4:"},
        {"huge.yaml", "reactions:\n  - name: a\n    type: dust\n    emission: {capacity: 1e300}\n", "capacity"},
        {"deep.yaml", std::string(200, '[') + std::string(200, ']'), "deep.yaml"},
        {"garbage.yaml", std::string("\x00\xff\xfe\x01\x02garbage\x7f", 13), "garbage.yaml"},
    };
    for (const auto& c : cases) {
        const std::string path = write(c.name, c.text);
        expectRejected(launch("--reactions " + path), c.mention, c.name);
    }
}

TEST(HostileInput, LegacySmokeFiles) {
    for (const auto& c : {std::make_pair(std::string("scalar.yaml"), std::string("hello\n")),
                          std::make_pair(std::string("list.yaml"), std::string("- 1\n- 2\n")),
                          std::make_pair(std::string("badsize.yaml"), std::string("reactions:\n  - {name: a, size: {x: 1}}\n")),
                          std::make_pair(std::string("garbage.yaml"), std::string("\x01\x02{{{[[[\n"))}) {
        const std::string path = write("legacy_" + c.first, c.second);
        expectRejected(launch("--fx legacy --legacy-reactions " + path), "legacy_" + c.first, c.first.c_str());
    }
}

TEST(HostileInput, SceneFiles) {
    std::ifstream in(std::string(CUBE_SOURCE_DIR) + "/data/race.glb", std::ios::binary);
    const std::string glb((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(glb.size(), 1000u);
    expectRejected(launch("--scene " + write("truncated.glb", glb.substr(0, glb.size() / 2))), "truncated.glb",
                   "truncated glb");
    expectRejected(launch("--scene " + write("corrupt.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [")),
                   "corrupt.gltf", "corrupt gltf");
    expectRejected(launch("--scene " + write("nobuffer.gltf",
                                             "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":\"missing.bin\","
                                             "\"byteLength\":64}]}")),
                   "missing.bin", "missing buffer");
    expectRejected(launch("--scene " + write("empty.gltf", "")), "empty.gltf", "empty gltf");
}

TEST(HostileInput, MissingShaderNamesTheFile) {
    const std::string empty = dir() + "/no_shaders";
    ASSERT_EQ(std::system(("mkdir -p " + empty).c_str()), 0);
    expectRejected(launch("", "CUBE_SHADER_DIR=" + empty), "vs_mesh.glsl", "missing shader");
}

TEST(HostileInput, ShaderThatFailsToCompileNamesFileAndLine) {
    const std::string copy = dir() + "/broken_shaders";
    ASSERT_EQ(std::system(("rm -rf " + copy + " && cp -r " + std::string(CUBE_SOURCE_DIR) + "/shaders " + copy).c_str()), 0);
    // Line 4 of fs_sky.glsl becomes a syntax error.
    ASSERT_EQ(std::system(("sed -i '4s/.*/this is not glsl;/' " + copy + "/fs_sky.glsl").c_str()), 0);
    expectRejected(launch("", "CUBE_SHADER_DIR=" + copy), "fs_sky.glsl:4", "broken shader");
}
}  // namespace hostile_input_test
