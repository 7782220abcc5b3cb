// Every bad input of the features added after BadInputClassesTest's classes (mega and stateless shaders,
// layered recipes, --explode-at, the platform library overrides, legacy aliases) is a clear
// error, printed once, before the first frame. One test per class, each hostile input made here;
// the plugin-level halves (live shader edits of every technique) are in
// tests/fx_host/ShaderTechniquesTest.cpp. kBoundSeconds only catches a hang: speed is measured
// by bench/bench_loaders.cpp, not here.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "CubeGameRun.h"
#include "RunCommand.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace bad_input_32_test {
namespace {

namespace fs = std::filesystem;

constexpr int kBoundSeconds = 60;

using clitest::Outcome;

Outcome run(const std::string& args, const std::string& env = "") { return clitest::runCubeGame(args, env, kBoundSeconds); }

Outcome runSmall(const std::string& args, const std::string& env = "") {
    return run("--frames 2 --size 64x48 --fixed-dt 0.016 " + args, env);
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

std::string slurp(const std::string& path) { return cubetest::readFile(path); }

class Scratch : public clitest::ScratchDir {
public:
    Scratch() : ScratchDir("cube_bad32_") {}
    // A copy of shaders/ with `file` broken as `how` says; returns the folder.
    std::string brokenShaders(const std::string& name, const std::string& file, const std::string& how) const {
        const std::string dir = path(name);
        fs::remove_all(dir);
        fs::copy(std::string(CUBE_SOURCE_DIR) + "/shaders", dir);
        const std::string original = slurp(dir + "/" + file);
        const size_t found = original.find("void main");
        const size_t main = found == std::string::npos ? original.size() : found;
        std::string text;
        if (how == "syntax") text = original.substr(0, main) + "this is not glsl;\n" + original.substr(main);
        if (how == "include") text = original.substr(0, main) + "#include \"no_such_file.glsl\"\n" + original.substr(main);
        if (how == "version") text = original.substr(original.find('\n') + 1);
        if (how == "power-branch") {  // inside the branch only the contrast powers' own builds compile
            const std::string branch = "#ifdef FX_POWER_STEPS\n";
            const size_t at = original.find(branch);
            EXPECT_NE(at, std::string::npos) << file;
            text = original.substr(0, at + branch.size()) + "this is not glsl;\n" + original.substr(at + branch.size());
        }
        if (how == "garbage") text = std::string("\x7f" "ELF\x02\x01\x01\xff\xfe\x01 garbage\n") + original;
        std::ofstream(dir + "/" + file, std::ios::binary | std::ios::trunc) << text;
        return dir;
    }

};

// The first line of `output` that names `file` with a line number ("file:NN: ..."), or "".
std::string firstLocatedLine(const std::string& output, const std::string& file) {
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) {
        const size_t at = line.find(file + ":");
        if (at != std::string::npos && at + file.size() + 1 < line.size() &&
            std::isdigit(static_cast<unsigned char>(line[at + file.size() + 1]))) {
            return line.substr(at);
        }
    }
    return "";
}

}  // namespace

// Class 1 (and 3): a broken shader of every technique stops start-up (exit 1) naming file:line,
// each line once: mega under --mode mega (no mega reaction loaded), stateless (the default set's
// sparks), and the billboard techniques that already did.
TEST(BadInputClasses32, ShadersOfEveryTechniqueFailStartUpOnce) {
    Scratch s;
    const struct {
        const char* file;
        const char* how;
        const char* args;
        const char* named;  ///< the file:line the message must give (the includer for a bad include)
    } cases[] = {
        {"fs_mega_blur.glsl", "syntax", "--mode mega", "fs_mega_blur.glsl"},
        {"fs_mega_spheres.glsl", "include", "--mode mega", "fs_mega_spheres.glsl"},
        {"fs_mega_composite.glsl", "version", "--mode mega", "fs_mega_composite.glsl"},
        {"vs_mega.glsl", "garbage", "--mode mega", "vs_mega.glsl"},
        {"mega_shade.glsl", "syntax", "--mode mega", "mega_shade.glsl"},
        {"fs_mega_depth.glsl", "syntax", "--mode mega", "fs_mega_depth.glsl"},
        {"vs_stateless_particles.glsl", "syntax", "", "vs_stateless_particles.glsl"},
        {"fs_stateless_particles.glsl", "include", "", "fs_stateless_particles.glsl"},
        {"fs_particles_soft.glsl", "syntax", "", "fs_particles_soft.glsl"},
        {"fs_particles_hard.glsl", "include", "--mode hard", "fs_particles_hard.glsl"},
        {"fs_particles_spherical.glsl", "syntax", "--mode spherical", "fs_particles_spherical.glsl"},
        {"particles_common.glsl", "syntax", "", "particles_common.glsl"},
        // An error that only one variant's #if branch holds (the reactions' contrast
        // powers, ProgramCache::Key::powerSteps) stops start-up too, not the first frame with smoke.
        {"particles_common.glsl", "power-branch", "", "particles_common.glsl"},
    };
    for (const auto& c : cases) {
        const std::string what = std::string(c.file) + " " + c.how + " " + c.args;
        const std::string dir = s.brokenShaders("shaders", c.file, c.how);
        const Outcome r = runSmall(c.args, "CUBE_SHADER_DIR=" + dir);
        EXPECT_EQ(r.status, 1) << what << "\n" << r.output;
        const std::string line = firstLocatedLine(r.output, c.named);
        ASSERT_FALSE(line.empty()) << what << ": no " << c.named << ":line\n" << r.output;
        EXPECT_EQ(count(r.output, line), 1u) << what << ": '" << line << "' printed more than once\n" << r.output;
        EXPECT_EQ(r.output.find("particles alive"), std::string::npos) << what << ": the run went on\n" << r.output;
    }
    // Without the override and with no mega reaction, a broken mega file is not the run's concern.
    const Outcome unused = runSmall("", "CUBE_SHADER_DIR=" + s.brokenShaders("unused", "fs_mega_blur.glsl", "syntax"));
    EXPECT_EQ(unused.status, 0) << unused.output;
}

// Class 3: one cause, one message. Before: 4 lines for the soft syntax error, 2 for a recipe's
// bad trigger.
TEST(BadInputClasses32, EachProblemIsPrintedOnce) {
    Scratch s;
    const Outcome soft = runSmall("", "CUBE_SHADER_DIR=" + s.brokenShaders("soft", "fs_particles_soft.glsl", "syntax"));
    EXPECT_EQ(soft.status, 1);
    const std::string line = firstLocatedLine(soft.output, "fs_particles_soft.glsl");
    ASSERT_FALSE(line.empty()) << soft.output;
    EXPECT_EQ(count(soft.output, line), 1u) << soft.output;

    const Outcome trigger = runSmall("--reactions " + std::string(CUBE_SOURCE_DIR) +
                                     "/fuzz/seeds/reactions/recipe_bad_trigger.yaml");
    EXPECT_EQ(trigger.status, 1) << trigger.output;
    EXPECT_EQ(count(trigger.output, "reactions[0].trigger.slip_treshold"), 1u) << trigger.output;
    EXPECT_EQ(count(trigger.output, "error[UnknownKey]"), 1u) << trigger.output;
}

// Class 4: errors inside recipes name the key the author wrote, at the line it is on.
TEST(BadInputClasses32, RecipeErrorsNameTheAuthorsKey) {
    const std::string seeds = std::string(CUBE_SOURCE_DIR) + "/fuzz/seeds/reactions/";
    const Outcome dup = runSmall("--reactions " + seeds + "recipe_duplicate_layer.yaml");
    EXPECT_EQ(dup.status, 1);
    EXPECT_NE(dup.output.find("recipe_duplicate_layer.yaml:9:15: error[DuplicateName] reactions[0].layers[1].name"),
              std::string::npos) << dup.output;
    const Outcome cap = runSmall("--reactions " + seeds + "recipe_capacity.yaml");
    EXPECT_EQ(cap.status, 1);
    EXPECT_NE(cap.output.find("recipe_capacity.yaml:23:40: error[OutOfRange] reactions[0].layers[4].emission.capacity"),
              std::string::npos) << cap.output;

    // Across files: a clash after a 3-layer recipe is the file's reactions[1], not the merged
    // set's reactions[3].
    Scratch s;
    const std::string dir = s.path("set");
    fs::create_directories(dir);
    const std::string plain = "  - name: puff\n    type: on_demand\n    emission: {burst: 2, capacity: 4}\n";
    std::ofstream(dir + "/a.yaml") << "reactions:\n" << plain;
    std::ofstream(dir + "/b.yaml") << "reactions:\n  - name: blast\n    layers:\n"
                                      "      - {name: l0, type: on_demand, emission: {burst: 2, capacity: 4}}\n"
                                      "      - {name: l1, type: on_demand, emission: {burst: 2, capacity: 4}}\n"
                                      "      - {name: l2, type: on_demand, emission: {burst: 2, capacity: 4}}\n"
                                   << plain;
    const Outcome clash = runSmall("--reactions " + dir);
    EXPECT_EQ(clash.status, 1);
    EXPECT_NE(clash.output.find("b.yaml:7: error[DuplicateName] reactions[1].name"), std::string::npos) << clash.output;
    EXPECT_EQ(clash.output.find("reactions[3]"), std::string::npos) << clash.output;
}

// Class 5: --explode-at that can never act is refused before the first frame, exit 2.
TEST(BadInputClasses32, ExplodeAtThatCanNeverActIsRefused) {
    Scratch s;
    const std::string calm = s.write("calm_recipe.yaml",
                                     "reactions:\n  - name: explosion\n    layers:\n"
                                     "      - {name: smoke, type: wheel_smoke}\n");
    const clitest::RefusedArgs cases[] = {
        {"--start 1 --explode-at 0.5", "--start 1"},
        {"--explode-at 100", "the run ends at drive time 0.032"},
        {"--fx legacy --explode-at 0.02", "--fx legacy"},
        {"--reactions " + std::string(CUBE_SOURCE_DIR) + "/reactions/none.yaml --explode-at 0.02", "no on_demand"},
        {"--reactions " + calm + " --explode-at 0.02", "no on_demand"},
    };
    for (const auto& c : cases) {
        const Outcome r = runSmall(c.args);
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find("--explode-at"), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.mention), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(r.output.find("frames,"), std::string::npos) << c.args << ": a frame ran\n" << r.output;
    }
    // One that can act runs (the default set has the explosion recipe); so does T = --start,
    // which fires in the first frame.
    for (const std::string args : {"--explode-at 0.02", "--explode-at 0", "--start 1 --explode-at 1"}) {
        const Outcome ok = runSmall(args);
        EXPECT_EQ(ok.status, 0) << args << "\n" << ok.output;
        EXPECT_EQ(ok.output.find("fireReaction"), std::string::npos) << args << "\n" << ok.output;
    }
}

// Class 6: a library override naming a FIFO or a folder is an error naming it, never a hang; a
// plain name still goes through the system search.
TEST(BadInputClasses32, LibraryOverridesNeverBlock) {
    Scratch s;
    ASSERT_EQ(::mkfifo(s.path("lib.fifo").c_str(), 0644), 0);
    fs::create_directories(s.path("lib.dir"));
    const struct {
        const char* env;
        const char* backend;
    } overrides[] = {{"CUBE_OSMESA_LIBRARY", "osmesa"}, {"CUBE_EGL_LIBRARY", "egl"}, {"CUBE_GLFW_LIBRARY", "glfw"}};
    for (const auto& o : overrides) {
        for (const auto& [path, kind] : {std::pair<std::string, std::string>{s.path("lib.fifo"), "a FIFO"},
                                         std::pair<std::string, std::string>{s.path("lib.dir"), "a directory"}}) {
            const Outcome r = runSmall(std::string("--backend ") + o.backend, std::string(o.env) + "=" + path);
            const std::string what = std::string(o.env) + "=" + kind;
            EXPECT_EQ(r.status, 1) << what << " (124 = hung)\n" << r.output;
            EXPECT_EQ(count(r.output, std::string("named by ") + o.env), 1u) << what << "\n" << r.output;
            EXPECT_NE(r.output.find(kind), std::string::npos) << what << "\n" << r.output;
        }
    }
    // A plain soname that is not installed: the loader's search, named as before.
    const Outcome soname = runSmall("", "CUBE_OSMESA_LIBRARY=libno_such_library.so.9");
    EXPECT_EQ(soname.status, 1);
    EXPECT_NE(soname.output.find("libno_such_library.so.9"), std::string::npos) << soname.output;
}

// Class 7: the legacy loader's alias bomb is refused with TooDeep, once (its time is in
// bench_loaders, BM_LegacyAliasBomb).
TEST(BadInputClasses32, LegacyAliasBombIsTooDeep) {
    const Outcome r = runSmall("--fx legacy --legacy-reactions " + std::string(CUBE_SOURCE_DIR) +
                               "/fuzz/seeds/legacy/alias_bomb_9x10.yaml");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_EQ(count(r.output, "error[TooDeep]"), 1u) << r.output;
    EXPECT_NE(r.output.find("alias_bomb_9x10.yaml:2:"), std::string::npos) << r.output;
}

}  // namespace bad_input_32_test
