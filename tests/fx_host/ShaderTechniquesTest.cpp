// At the plugin's API: the programs of every technique (billboards, mega,
// stateless) are built by prepareGl when a loaded reaction or the options can use them, a live
// edit of any technique's file is one transaction (a broken one keeps every last good program
// and is reported once, never announced as reloaded), and a program built after a rejected edit
// (a contrast power built later) comes from the source that went live.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "FxTestHost.h"
#include "RunCommand.h"
#include "FileEdits.h"
#include "../../fx_plugin/render/ProgramCache.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace fxtest {
namespace shader_techniques_test {

std::string freshCopy(const std::string& name) {
    const std::string dir = scratchDir() + "/" + name;
    EXPECT_EQ(std::system(("rm -rf '" + dir + "' && cp -r " CUBE_SOURCE_DIR "/shaders '" + dir + "'").c_str()), 0);
    return dir;
}

int countIn(const std::vector<std::string>& lines, const std::string& fragment) {
    int n = 0;
    for (const std::string& l : lines) {
        for (size_t at = l.find(fragment); at != std::string::npos; at = l.find(fragment, at + 1)) ++n;
    }
    return n;
}

// One way to break one file, as a user's edit would.
struct Breakage {
    const char* file;
    const char* how;  ///< "syntax", "include", "version", "garbage", "huge"
};

std::string broken(const std::string& original, const std::string& how) {
    const size_t found = original.find("void main");
    const size_t main = found == std::string::npos ? original.size() : found;  // an include file: at its end
    if (how == "syntax") return original.substr(0, main) + "this is not glsl;\n" + original.substr(main);
    if (how == "include") return original.substr(0, main) + "#include \"no_such_file.glsl\"\n" + original.substr(main);
    if (how == "version") return original.substr(original.find('\n') + 1);
    if (how == "garbage") {
        static const char kBinary[] = "\x7f" "ELF\x01\x02\x00\xff\xfe garbage";
        return std::string(kBinary, sizeof kBinary - 1) + original;
    }
    return original + std::string((1u << 20) + 16, ' ');  // "huge": past the 1 MiB limit
}

// Every technique's files, and its neighbours (a stage's include, each way of breaking).
const Breakage kBreakages[] = {
    {"fs_particles_soft.glsl", "syntax"},      {"fs_particles_hard.glsl", "include"},
    {"fs_particles_spherical.glsl", "version"}, {"vs_particles.glsl", "garbage"},
    {"particles_common.glsl", "syntax"},       {"vs_stateless_particles.glsl", "syntax"},
    {"fs_stateless_particles.glsl", "include"}, {"fs_mega_blur.glsl", "syntax"},
    {"fs_mega_spheres.glsl", "huge"},          {"fs_mega_composite.glsl", "version"},
    {"vs_mega.glsl", "garbage"},               {"mega_shade.glsl", "syntax"},
};

class ShaderTechniquesTest : public FxHostTest {
protected:
    // The whole reactions/ folder: soft, hard and spherical billboards and stateless sparks; the
    // Mega override adds the mega programs.
    std::unique_ptr<fx::Plugin> create(const std::string& shaderDir, bool mega) {
        fx::PluginImports imports;
        imports.host = &host;
        imports.shaderDir = shaderDir;
        auto p = fxCreatePlugin(imports);
        if (!p || !p->loadReactions(CUBE_SOURCE_DIR "/reactions", nullptr)) return nullptr;
        fx::RenderOptions o;
        if (mega) o.techniqueOverride = fx::Technique::Mega;
        p->setRenderOptions(o);
        return p;
    }
    TestHostAdapter host;
};

// Item 1: a broken file of any technique fails prepareGl (start-up), naming the file, once.
TEST_F(ShaderTechniquesTest, PrepareGlBuildsEveryTechniqueInUseAndNamesTheBrokenFileOnce) {
    allowShaderCompilerMessages();
    for (const Breakage& b : kBreakages) {
        SCOPED_TRACE(std::string(b.file) + " " + b.how);
        const std::string dir = freshCopy("prepare_every_technique");
        cubetest::writeAhead(dir + "/" + b.file, broken(cubetest::readFile(dir + "/" + b.file), b.how), 0);
        host = TestHostAdapter();
        auto p = create(dir, true);
        ASSERT_TRUE(p);
        fx::Diagnostics diags;
        EXPECT_FALSE(p->prepareGl(&diags));
        ASSERT_FALSE(diags.empty());
        EXPECT_EQ(diags.front().code, fx::ErrorCode::ShaderBuild);
        // The file (for a bad include, the file that includes it, with the line).
        bool named = false;
        for (const fx::Diagnostic& d : diags) named = named || d.file == b.file || d.message.find(b.file) != std::string::npos;
        EXPECT_TRUE(named) << diags.front().str();
        // Each distinct line of the failure once in the log, however many programs share the file.
        const std::string first = diags.front().file.empty() ? diags.front().message
                                                             : diags.front().file + ":" + std::to_string(diags.front().line) +
                                                                   ": " + diags.front().message;
        EXPECT_EQ(countIn(host.errors(), first), 1) << first;
    }
    resetGlErrors();
}

// The same files, intact, build for every technique (the ones that passed before still do).
TEST_F(ShaderTechniquesTest, IntactFilesBuildEveryTechnique) {
    auto p = create(freshCopy("prepare_intact"), true);
    ASSERT_TRUE(p);
    fx::Diagnostics diags;
    EXPECT_TRUE(p->prepareGl(&diags));
    EXPECT_TRUE(diags.empty()) << diags.front().str();
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

// Item 2 (and 3): a broken edit of any technique's file is reported once, never as "reloaded";
// the last good programs stay; putting the file back goes live.
TEST_F(ShaderTechniquesTest, ABrokenEditOfAnyTechniqueIsReportedOnceAndKeepsTheLastGoodPrograms) {
    allowShaderCompilerMessages();
    for (const Breakage& b : kBreakages) {
        SCOPED_TRACE(std::string(b.file) + " " + b.how);
        const std::string dir = freshCopy("reload_every_technique");
        const std::string path = dir + "/" + b.file;
        const std::string original = cubetest::readFile(path);
        host = TestHostAdapter();
        auto p = create(dir, true);
        ASSERT_TRUE(p);
        ASSERT_TRUE(p->prepareGl(nullptr));
        EXPECT_FALSE(p->pollShaderReload(nullptr));  // nothing changed

        cubetest::writeAhead(path, broken(original, b.how), 10);
        fx::Diagnostics diags;
        EXPECT_FALSE(p->pollShaderReload(&diags));
        ASSERT_FALSE(diags.empty());
        EXPECT_EQ(diags.front().code, fx::ErrorCode::ShaderBuild);
        EXPECT_EQ(countIn(host.errors(), "the last good programs are kept"), 1);
        EXPECT_FALSE(host.logged("particle shaders reloaded"));
        const std::string first = diags.front().file.empty() ? diags.front().message
                                                             : diags.front().file + ":" + std::to_string(diags.front().line) +
                                                                   ": " + diags.front().message;
        EXPECT_EQ(countIn(host.errors(), first), 1) << first;
        EXPECT_FALSE(p->pollShaderReload(nullptr));  // the same edit: not reported again
        EXPECT_EQ(countIn(host.errors(), "the last good programs are kept"), 1);

        cubetest::writeAhead(path, original, 20);
        EXPECT_TRUE(p->pollShaderReload(nullptr));
        EXPECT_TRUE(host.logged("particle shaders reloaded"));
    }
    resetGlErrors();
}

// A FIFO put in a shader's place under --watch: named once, never blocks.
TEST_F(ShaderTechniquesTest, AFifoInAShadersPlaceIsReportedOnce) {
    for (const char* file : {"fs_particles_soft.glsl", "fs_mega_blur.glsl", "vs_stateless_particles.glsl"}) {
        SCOPED_TRACE(file);
        const std::string dir = freshCopy("reload_fifo");
        host = TestHostAdapter();
        auto p = create(dir, true);
        ASSERT_TRUE(p);
        ASSERT_TRUE(p->prepareGl(nullptr));
        const std::string path = dir + "/" + file;
        std::filesystem::remove(path);
        ASSERT_EQ(std::system(("mkfifo '" + path + "'").c_str()), 0);
        EXPECT_FALSE(p->pollShaderReload(nullptr));
        EXPECT_EQ(countIn(host.errors(), "a FIFO"), 1);
        EXPECT_EQ(countIn(host.errors(), "the last good programs are kept"), 1);
    }
}

// Item 2's variant: a soft program for a contrast power first asked for after a rejected edit is
// built from the source that went live, not from the broken file on disk.
TEST_F(ShaderTechniquesTest, APowerBuiltAfterARejectedEditComesFromTheGoodSource) {
    const std::string dir = freshCopy("power_snapshot");
    using Cache = fx::ProgramCache;
    Cache programs(fx::snapshotShaderReader(fx::shaderReader(dir)));
    std::vector<std::string> errors;
    programs.build({Cache::Key{Cache::Soft}, Cache::Key{Cache::SoftGeneralPower}}, &errors);
    ASSERT_TRUE(errors.empty()) << errors.front();
    const std::string soft = dir + "/fs_particles_soft.glsl";
    cubetest::writeAhead(soft, broken(cubetest::readFile(soft), "syntax"), 10);
    allowShaderCompilerMessages();
    programs.build({Cache::Key{Cache::Soft, false, 5}}, &errors);
    EXPECT_TRUE(errors.empty()) << errors.front();
    const fx::ParticleProgram& twoAndAHalf = programs.get(Cache::Soft, false, 2.5f);
    ASSERT_NE(twoAndAHalf.program, 0u);
    EXPECT_NE(twoAndAHalf.program, programs.get(Cache::Soft, false).program);
    resetGlErrors();
}

}  // namespace shader_techniques_test
}  // namespace fxtest
