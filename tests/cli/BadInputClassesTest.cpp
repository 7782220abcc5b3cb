// Every bad input a clear error. One test per class (legacy data, glTF, reaction
// folders, shaders, CLI and signals). Each hostile input is generated here at run time; each
// case must end within kBoundSeconds (a generous bound for 2 slow cores and ASan) with a non-zero
// exit and a message naming the file or flag and the rule broken, or with the last good state.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "CubeGameRun.h"

namespace fs = std::filesystem;

namespace {

constexpr int kBoundSeconds = 20;

using clitest::Outcome;

std::string bin() { return std::string(CUBE_TEST_BIN_DIR) + "/cube_game"; }

// cube_game with `args`, killed after kBoundSeconds.
Outcome run(const std::string& args, const std::string& env = "") { return clitest::runCubeGame(args, env, kBoundSeconds); }

// A run that renders nothing much: tiny, two frames, the fixed step.
Outcome runSmall(const std::string& args, const std::string& env = "") {
    return run("--frames 2 --size 64x48 --fixed-dt 0.016 " + args, env);
}

class Scratch : public clitest::ScratchDir {
public:
    Scratch() : ScratchDir("cube_bad_") {}
    std::string symlinkLoop(const std::string& name) const {
        // a -> b -> a
        fs::create_symlink(path(name + ".other"), path(name));
        fs::create_symlink(path(name), path(name + ".other"));
        return path(name);
    }
};

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// A clear rejection: exit 1 (or `code`), in time, naming each of `mentions`.
void expectRejected(const Outcome& r, std::initializer_list<std::string> mentions, const std::string& what, int code = 1) {
    EXPECT_EQ(r.status, code) << what << " (124 = hung until the bound)\n" << r.output;
    EXPECT_LT(r.seconds, kBoundSeconds) << what;
    for (const std::string& m : mentions)
        EXPECT_NE(r.output.find(m), std::string::npos) << what << ": message should name '" << m << "'\n" << r.output;
}

std::string sourceFile(const std::string& rel) {
    std::ifstream in(std::string(CUBE_SOURCE_DIR) + "/" + rel, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A minimal valid glTF: one triangle in an embedded buffer, `nodes` and extra top-level members
// spliced in as JSON text.
std::string triangleGltf(const std::string& nodes = R"([{"name":"tri","mesh":0}])", const std::string& extra = "",
                         const std::string& asset = R"({"version":"2.0"})") {
    // Three vertices (0,0,0) (1,0,0) (0,1,0) as float32, base64.
    const std::string data = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    return R"({"asset":)" + asset + R"(,"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
           R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" + data + R"("}])" + extra + "}";
}

std::string glbOf(const std::string& json) {
    std::string j = json;
    while (j.size() % 4) j += ' ';
    auto le = [](uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; };
    return "glTF" + le(2) + le(uint32_t(12 + 8 + j.size())) + le(uint32_t(j.size())) + "JSON" + j;
}

}  // namespace

// Class 1: the legacy data file gets the reaction loader's rigour and codes.
TEST(BadInputClasses, LegacyDataFile) {
    Scratch s;
    const std::string good = sourceFile("data/legacy_smoke.yaml");
    ASSERT_FALSE(good.empty());
    const std::string folder = s.path("legacy_folder");
    fs::create_directories(folder);
    const struct {
        std::string path;
        std::string code;
        std::string also;
    } cases[] = {
        {folder, "FileNotFound", "a directory"},
        {s.fifo("legacy_fifo.yaml"), "FileNotFound", "a FIFO"},
        {s.symlinkLoop("legacy_loop.yaml"), "FileNotFound", "symlink loop"},
        {s.write("legacy_big.yaml", std::string(2u << 20, '#')), "FileTooLarge", "at most"},
        {s.write("legacy_dupkey.yaml", "reactions:\n  - name: a\n    rate: 4\n    rate: 5\n"), "DuplicateKey", "legacy_dupkey.yaml:4:"},
        {s.write("legacy_twodocs.yaml", good + "---\n" + good), "SyntaxError", "second one"},
        {s.write("legacy_fraction.yaml", "reactions:\n  - name: a\n    capacity: 12.5\n"), "WrongType", "reactions[0].capacity"},
        {s.write("legacy_negative.yaml", "reactions:\n  - name: a\n    capacity: -3\n"), "NegativeCount", "legacy_negative.yaml:3:"},
        {s.write("legacy_nan.yaml", "reactions:\n  - name: a\n    alpha: .nan\n"), "NotFinite", "reactions[0].alpha"},
        {s.write("legacy_deep.yaml", std::string(5000, '[') + std::string(5000, ']')), "", "legacy_deep.yaml"},
        {s.write("legacy_dupname.yaml", "reactions:\n  - name: a\n  - name: a\n"), "DuplicateName", "legacy_dupname.yaml:3:"},
    };
    for (const auto& c : cases) {
        const Outcome r = runSmall("--fx legacy --legacy-reactions " + c.path);
        expectRejected(r, {fs::path(c.path).filename().string(), c.also}, c.path);
        if (!c.code.empty()) {
            EXPECT_EQ(count(r.output, "error[" + c.code + "]"), 1u) << c.path << ": printed once\n" << r.output;
        }
    }
    // The legacy sprites' atlas goes through the same opener: a FIFO in its place is named.
    const std::string root = s.path("root");
    fs::create_directories(root + "/data");
    for (const char* f : {"race.gltf", "race.bin", "legacy_smoke.yaml"})
        fs::copy_file(std::string(CUBE_SOURCE_DIR) + "/data/" + f, root + "/data/" + f);
    fs::create_directory_symlink(std::string(CUBE_SOURCE_DIR) + "/shaders", root + "/shaders");
    ASSERT_EQ(::mkfifo((root + "/data/smoke_atlas.png").c_str(), 0644), 0);
    expectRejected(runSmall("--fx legacy", "CUBE_ROOT=" + root), {"smoke_atlas.png", "a FIFO"}, "FIFO atlas");

    // Every problem of a file is reported, not just the first, each with line and key.
    const Outcome many = runSmall("--fx legacy --legacy-reactions " +
                                  s.write("legacy_many.yaml", "reactions:\n  - name: a\n    rate: x\n    bogus: 1\n    alpha: 7\n"));
    EXPECT_EQ(many.status, 1);
    for (const char* m : {"legacy_many.yaml:3:", "legacy_many.yaml:4:", "legacy_many.yaml:5:", "reactions[0].rate",
                          "reactions[0].bogus", "reactions[0].alpha"})
        EXPECT_NE(many.output.find(m), std::string::npos) << m << "\n" << many.output;
}

// Class 2: glTF. Limits before parsing, validation rules named, features ignored named once,
// and any valid model renders.
TEST(BadInputClasses, GltfFiles) {
    Scratch s;
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    std::string chain = "[";
    for (int i = 0; i < 100000; ++i) chain += R"({"children":[)" + std::to_string(i + 1) + "]},";
    chain += R"({"mesh":0}])";
    const struct {
        std::string file;
        std::string bytes;
        std::string code;
        std::string also;
    } cases[] = {
        {"deep_extras.gltf", triangleGltf(R"([{"name":"tri","mesh":0}])", R"(,"extras":)" + deep), "TooDeep", "128 levels"},
        {"deep_extras.glb", glbOf(triangleGltf(R"([{"name":"tri","mesh":0}])", R"(,"extras":)" + deep)), "TooDeep", "128 levels"},
        {"chain.gltf", triangleGltf(chain), "TooDeep", "4096 levels"},
        {"matrix_trs.gltf", triangleGltf(R"([{"mesh":0,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],"translation":[1,2,3]}])"),
         "BadNode", "NODE_MATRIX_TRS"},
        {"text_translation.gltf", triangleGltf(R"([{"mesh":0,"translation":[1,"two",3]}])"), "BadNode", "ARRAY_TYPE_MISMATCH"},
        {"version3.gltf", triangleGltf(R"([{"mesh":0}])", "", R"({"version":"3.0"})"), "InvalidGltf", "UNKNOWN_ASSET_MAJOR_VERSION"},
        {"draco.gltf", triangleGltf(R"([{"mesh":0}])", R"(,"extensionsUsed":["KHR_draco_mesh_compression"],"extensionsRequired":["KHR_draco_mesh_compression"])"),
         "Unsupported", "KHR_draco_mesh_compression"},
        {"escape.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../../etc/passwd","byteLength":16}]})", "BadUri", "'..'"},
    };
    for (const auto& c : cases) {
        const Outcome r = runSmall("--scene " + s.write(c.file, c.bytes));
        expectRejected(r, {c.file, c.code, c.also}, c.file);
        EXPECT_EQ(count(r.output, c.code + ":"), 1u) << c.file << ": printed once\n" << r.output;
    }
    expectRejected(runSmall("--scene " + s.fifo("pipe.gltf")), {"pipe.gltf", "FileNotFound", "a FIFO"}, "FIFO scene");

    // A model without a car node renders: one warning per ignored feature, exit 0, a picture.
    const std::string png = s.path("model.png");
    const Outcome ok = run("--frames 3 --size 96x72 --fixed-dt 0.016 --screenshot " + png + " --scene " +
                           s.write("model.gltf", triangleGltf(R"([{"name":"tri","mesh":0}])",
                                                              R"(,"animations":[{"channels":[],"samplers":[]}],"cameras":[{"type":"perspective","perspective":{"yfov":1,"znear":0.1}}])")));
    EXPECT_EQ(ok.status, 0) << ok.output;
    EXPECT_TRUE(fs::exists(png)) << ok.output;
    EXPECT_EQ(count(ok.output, "no node named 'car'"), 1u) << ok.output;
    EXPECT_EQ(count(ok.output, "animation(s) ignored"), 1u) << ok.output;
    EXPECT_EQ(count(ok.output, "camera(s) ignored"), 1u) << ok.output;
    // --car-node naming an absent node is the user's error, not a warning.
    expectRejected(runSmall("--car-node truck --scene " + s.path("model.gltf")), {"--car-node", "truck"}, "--car-node");
}

// Class 3: reaction folders report every *.yaml entry they cannot read, by name and kind.
TEST(BadInputClasses, ReactionFolders) {
    Scratch s;
    const std::string dir = s.path("reactions");
    fs::create_directories(dir);
    std::ofstream(dir + "/good.yaml") << sourceFile("reactions/burnout_smoke.yaml");
    ASSERT_EQ(::mkfifo((dir + "/pipe.yaml").c_str(), 0644), 0);
    fs::create_symlink(dir + "/loop_b.yaml", dir + "/loop_a.yaml");
    fs::create_symlink(dir + "/loop_a.yaml", dir + "/loop_b.yaml");
    const Outcome r = runSmall("--reactions " + dir);
    expectRejected(r, {"pipe.yaml", "a FIFO", "loop_a.yaml", "symlink loop"}, "folder with a FIFO and a symlink loop");
    EXPECT_EQ(r.output.find("no *.yaml"), std::string::npos) << r.output;

    // Only unreadable entries: still each named, never "holds no *.yaml".
    const std::string only = s.path("only_fifo");
    fs::create_directories(only);
    ASSERT_EQ(::mkfifo((only + "/smoke.yaml").c_str(), 0644), 0);
    const Outcome r2 = runSmall("--reactions " + only);
    expectRejected(r2, {"smoke.yaml", "a FIFO"}, "folder with only a FIFO");
    EXPECT_EQ(r2.output.find("no *.yaml"), std::string::npos) << r2.output;
}

// Class 4 (engine shaders): a shader that cannot be read or compiled fails start-up naming the
// file (and line), never blocks on a FIFO.
TEST(BadInputClasses, EngineShaders) {
    Scratch s;
    const std::string copy = s.path("shaders");
    fs::copy(std::string(CUBE_SOURCE_DIR) + "/shaders", copy);
    fs::remove(copy + "/fs_sky.glsl");
    ASSERT_EQ(::mkfifo((copy + "/fs_sky.glsl").c_str(), 0644), 0);
    expectRejected(runSmall("", "CUBE_SHADER_DIR=" + copy), {"fs_sky.glsl", "a FIFO"}, "FIFO shader");

    fs::remove(copy + "/fs_sky.glsl");
    fs::copy_file(std::string(CUBE_SOURCE_DIR) + "/shaders/fs_sky.glsl", copy + "/fs_sky.glsl");
    std::ofstream(copy + "/common.glsl", std::ios::app) << "\nthis is not glsl;\n";
    const Outcome r = runSmall("", "CUBE_SHADER_DIR=" + copy);
    expectRejected(r, {"common.glsl:"}, "broken include");
}

// Class 5: every CLI value is checked before the run; signals end it with its results.
TEST(BadInputClasses, CommandLine) {
    Scratch s;
    const clitest::RefusedArgs cases[] = {
        {"--frames 0", "--window"},
        {"--scene ''", "--scene: expected a path"},
        {"--reactions ''", "--reactions: expected a path"},
        {"--legacy-reactions ''", "--legacy-reactions: expected a path"},
        {"--stats-json ''", "--stats-json: expected a path"},
        {"--screenshot ''", "--screenshot: expected a path"},
        {"--screenshot " + s.path("missing/folder/f.png"), "does not exist"},
        {"--stats-json " + s.path("missing/s.json"), "--stats-json"},
        {"--screenshot-every 2 " + s.path("nowhere"), "--screenshot-every"},
        {"--camera 1,2,3,1,2,3", "eye is on the target"},
        {"--camera 0,5,0,0,0,0", "parallel to the up axis"},
        {"--camera 0,nan,0,1,1,1", "--camera"},
        {"--camera 0,1e400,0,1,1,1", "--camera"},
        {"--car-node ''", "--car-node"},
    };
    for (const auto& c : cases) {
        const Outcome r = run("--size 64x48 " + c.args);
        expectRejected(r, {c.mention}, c.args, 2);
        // Refused before the run: no context was made, nothing rendered.
        EXPECT_EQ(r.output.find("osmesa on"), std::string::npos) << c.args << "\n" << r.output;
    }
}

TEST(BadInputClasses, SignalsFinishTheFrameAndWriteResults) {
    for (const int sig : {SIGINT, SIGTERM}) {
        Scratch s;
        const std::string png = s.path("last.png"), stats = s.path("stats.json"), log = s.path("log.txt");
        const pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            const std::string cmd = "exec " + bin() + " --frames 100000000 --size 64x48 --fixed-dt 0.016 --screenshot " + png +
                                    " --stats-json " + stats + " > " + log + " 2>&1";
            ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));
        ASSERT_EQ(::kill(pid, sig), 0);
        int st = 0;
        const auto start = std::chrono::steady_clock::now();
        pid_t done = 0;
        while ((done = ::waitpid(pid, &st, WNOHANG)) == 0 &&
               std::chrono::steady_clock::now() - start < std::chrono::seconds(kBoundSeconds))
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (done == 0) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &st, 0);
            FAIL() << "cube_game did not stop within " << kBoundSeconds << " s of signal " << sig;
        }
        std::ifstream in(log);
        const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_TRUE(WIFEXITED(st)) << "killed by the signal instead of stopping cleanly\n" << output;
        EXPECT_EQ(WEXITSTATUS(st), 128 + sig) << output;
        EXPECT_TRUE(fs::exists(png) && fs::file_size(png) > 0) << output;
        EXPECT_TRUE(fs::exists(stats) && fs::file_size(stats) > 0) << output;
        EXPECT_NE(output.find(sig == SIGINT ? "SIGINT" : "SIGTERM"), std::string::npos) << output;
    }
}
