// The plugin's shader loader: #include from the shader directory, errors as "file:line: message"
// naming the file the line is really in, and a renderer that reports a broken shader through
// HostAdapter::log and draws nothing with it instead of crashing.
#include <glad/gl.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "FxTestHost.h"
#include "RunCommand.h"
#include "../../fx_plugin/render/ProgramCache.h"
#include "../../fx_plugin/render/ShaderLoader.h"

namespace fxtest {
namespace {

const std::string kShaders = CUBE_SOURCE_DIR "/shaders";

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
}

// Copies every particle shader into a fresh directory; returns it.
std::string copyShaders(const std::string& name) {
    const std::string dir = scratchDir() + "/" + name;
    std::system(("mkdir -p '" + dir + "'").c_str());
    for (const auto& entry : std::filesystem::directory_iterator(kShaders)) {
        const std::string f = entry.path().filename().string();
        if (f.find("particles") == std::string::npos) continue;
        writeText(dir + "/" + f, cubetest::readFile(kShaders + "/" + f));
    }
    return dir;
}

// Replaces line `line` (1-based) of `path` with `text`.
void replaceLine(const std::string& path, int line, const std::string& text) {
    std::istringstream in(cubetest::readFile(path));
    std::string out, l;
    for (int n = 1; std::getline(in, l); ++n) out += (n == line ? text : l) + "\n";
    writeText(path, out);
}

// The 1-based line of the first occurrence of `needle` in `path`.
int lineOf(const std::string& path, const std::string& needle) {
    std::istringstream in(cubetest::readFile(path));
    std::string l;
    for (int n = 1; std::getline(in, l); ++n) {
        if (l.find(needle) != std::string::npos) return n;
    }
    return -1;
}

class ShaderLoaderTest : public FxHostTest {};

// One 2 m puff 1 m up, set into `particles`, seen from (0, 2, 6) in a w x h graph.
struct OnePuff {
    OnePuff(DirectParticles& p, int w, int h)
        : particles(p), view(makeView(glm::vec3(0, 2, 6), glm::vec3(0, 1, 0), w, h)), graph(w, h) {
        p.set({HandParticle{glm::vec3(0.0f, 1.0f, 0.0f), 2.0f}});
    }
    // One frame of `scene` with the puff; returns how many particles were drawn.
    int draw(TestScene& scene) {
        int drawn = -1;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = particles.declare(view, f); });
        return drawn;
    }
    DirectParticles& particles;
    const fx::ViewInfo view;
    TestFrameGraph graph;
};
class BrokenShaderTest : public FxHostTest {
protected:
    void SetUp() override {
        FxHostTest::SetUp();
        allowShaderCompilerMessages();
    }
};

TEST_F(ShaderLoaderTest, ExpandsIncludesOnceAndKeepsTheFileTable) {
    fx::ShaderSource src;
    std::string error;
    ASSERT_TRUE(fx::loadShaderSource(kShaders, "fs_particles_soft.glsl", "#define FX_X 1\n", &src, &error))
        << error;
    EXPECT_EQ(src.files, (std::vector<std::string>{"fs_particles_soft.glsl", "particles_common.glsl",
                                                   "particles_scene_depth.glsl", "particles_fog.glsl",
                                                   "particles_varyings.glsl"}));
    EXPECT_EQ(src.text.rfind("#version 330 core\n#define FX_X 1\n", 0), 0u);
    EXPECT_NE(src.text.find("float contrastCurve("), std::string::npos);
    EXPECT_EQ(src.text.find("#include"), std::string::npos);
}

TEST_F(ShaderLoaderTest, EveryParticleProgramBuilds) {
    for (const char* fs : {"fs_particles_hard.glsl", "fs_particles_soft.glsl"}) {
        std::string error;
        const uint32_t p = fx::buildProgram(kShaders, "vs_particles.glsl", fs, "", &error);
        EXPECT_NE(p, 0u) << error;
        glDeleteProgram(p);
    }
    std::string error;
    uint32_t p = fx::buildProgram(kShaders, "vs_particles.glsl", "fs_particles_spherical.glsl",
                                  "#define FX_SPHERICAL 1\n", &error);
    EXPECT_NE(p, 0u) << error;
    glDeleteProgram(p);
    for (const char* fs : {"fs_particles_depth_downsample.glsl", "fs_particles_composite.glsl"}) {
        p = fx::buildProgram(kShaders, "vs_particles_fullscreen.glsl", fs, "", &error);
        EXPECT_NE(p, 0u) << error;
        glDeleteProgram(p);
    }
}

// The quarter-res downsample and the composites gather their four depths where the context has
// ARB_texture_gather, and only they declare it (an #extension the driver does not know is a
// warning on the host's debug output); the depth-aware composite gathers the farthest depths too
// (FX_GATHER_FARTHEST) where it has ARB_gpu_shader5 as well. Every context the suite runs them in
// has both, but for the runs that hide one (QuarterResTest.WithoutTextureGather and
// .WithoutGpuShader5, tests/CMakeLists.txt).
TEST_F(ShaderLoaderTest, TheQuarterResProgramsGatherWhereTheContextCan) {
    TestHostAdapter host;
    DirectParticles direct(&host);  // loads the plugin's GL entry points and extension flags
    bool listed = false, shader5 = false;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        listed = listed || (name && std::string(name) == "GL_ARB_texture_gather");
        shader5 = shader5 || (name && std::string(name) == "GL_ARB_gpu_shader5");
    }
    if (!std::getenv("MESA_EXTENSION_OVERRIDE")) {
        EXPECT_TRUE(listed);
        EXPECT_TRUE(shader5);
    }
    using PC = fx::ProgramCache;
    for (PC::Program program : {PC::DepthDownsample, PC::Composite, PC::CompositeBilinear, PC::MegaComposite}) {
        const std::string defines = PC::Key::of(program).defines();
        const bool farthest = program == PC::Composite && listed && shader5;
        EXPECT_EQ(defines.find("#define FX_GATHER_FARTHEST 1") != std::string::npos, farthest) << defines;
        EXPECT_EQ(defines.find("GL_ARB_gpu_shader5") != std::string::npos, farthest) << defines;
    }
    using PC = fx::ProgramCache;
    for (PC::Program program : {PC::DepthDownsample, PC::Composite, PC::CompositeBilinear, PC::MegaComposite}) {
        const std::string defines = PC::Key::of(program).defines();
        EXPECT_EQ(defines.find("#define FX_GATHER 1") != std::string::npos, listed) << defines;
        EXPECT_EQ(defines.find("#extension GL_ARB_texture_gather : require") != std::string::npos, listed);
    }
    for (PC::Program program : {PC::HalfZ, PC::LinearizeDepth, PC::MegaSpheres}) {
        EXPECT_EQ(PC::Key::of(program).defines().find("texture_gather"), std::string::npos);
    }
}

TEST_F(BrokenShaderTest, CompileErrorNamesTheFileAndLine) {
    const std::string dir = copyShaders("error_in_main");
    const int line = lineOf(dir + "/fs_particles_soft.glsl", "float coverage = texel.a * fade;");
    ASSERT_GT(line, 0);
    replaceLine(dir + "/fs_particles_soft.glsl", line, "    float coverage = texel.a * fade +;");
    std::string error;
    EXPECT_EQ(fx::buildProgram(dir, "vs_particles.glsl", "fs_particles_soft.glsl", "", &error), 0u);
    EXPECT_NE(error.find("fs_particles_soft.glsl:" + std::to_string(line) + ":"), std::string::npos)
        << error;
}

TEST_F(BrokenShaderTest, CompileErrorInAnIncludeNamesTheInclude) {
    const std::string dir = copyShaders("error_in_include");
    const int line = lineOf(dir + "/particles_common.glsl", "float rampU(float life) {");
    ASSERT_GT(line, 0);
    replaceLine(dir + "/particles_common.glsl", line + 1, "    return undeclaredThing;");
    std::string error;
    EXPECT_EQ(fx::buildProgram(dir, "vs_particles.glsl", "fs_particles_hard.glsl", "", &error), 0u);
    EXPECT_NE(error.find("particles_common.glsl:" + std::to_string(line + 1) + ":"), std::string::npos)
        << error;
    EXPECT_EQ(error.find("fs_particles_hard.glsl:"), std::string::npos) << error;
}

TEST_F(ShaderLoaderTest, MissingIncludeIsReportedWhereItIsIncluded) {
    const std::string dir = copyShaders("missing_include");
    const int line = lineOf(dir + "/fs_particles_hard.glsl", "#include \"particles_common.glsl\"");
    replaceLine(dir + "/fs_particles_hard.glsl", line, "#include \"no_such_file.glsl\"");
    std::string error;
    EXPECT_EQ(fx::buildProgram(dir, "vs_particles.glsl", "fs_particles_hard.glsl", "", &error), 0u);
    EXPECT_NE(error.find("fs_particles_hard.glsl:" + std::to_string(line) + ": cannot open"),
              std::string::npos)
        << error;
}

TEST_F(ShaderLoaderTest, IncludeCycleStopsAtTheDepthLimit) {
    const std::string dir = scratchDir() + "/cycle";
    std::system(("mkdir -p '" + dir + "'").c_str());
    writeText(dir + "/a.glsl", "#version 330 core\n#include \"b.glsl\"\n");
    // Each file is expanded once, so a cycle ends without an error.
    writeText(dir + "/b.glsl", "#include \"a.glsl\"\nvoid main() {}\n");
    fx::ShaderSource src;
    std::string error;
    EXPECT_TRUE(fx::loadShaderSource(dir, "a.glsl", "", &src, &error)) << error;
    std::string deep = "#version 330 core\n";
    for (int i = 0; i <= fx::kMaxIncludeDepth + 1; ++i) {
        writeText(dir + "/d" + std::to_string(i) + ".glsl", "#include \"d" + std::to_string(i + 1) + ".glsl\"\n");
    }
    writeText(dir + "/deep.glsl", deep + "#include \"d0.glsl\"\n");
    EXPECT_FALSE(fx::loadShaderSource(dir, "deep.glsl", "", &src, &error));
    EXPECT_NE(error.find("nested deeper"), std::string::npos) << error;
}

TEST_F(ShaderLoaderTest, TranslatesTheCommonDriverLogFormats) {
    const std::vector<std::string> files{"main.glsl", "common.glsl"};
    EXPECT_EQ(fx::translateInfoLog("1:12(5): error: `x' undeclared", files, "main.glsl"),
              "common.glsl:12: error: `x' undeclared");
    EXPECT_EQ(fx::translateInfoLog("0(7) : error C1008: undefined variable", files, "main.glsl"),
              "main.glsl:7: error C1008: undefined variable");
    EXPECT_EQ(fx::translateInfoLog("ERROR: 1:3: 'y' : undeclared identifier", files, "main.glsl"),
              "common.glsl:3: 'y' : undeclared identifier");
    EXPECT_EQ(fx::translateInfoLog("something odd", files, "main.glsl"), "main.glsl:0: something odd");
    // The loader's own markers put file k's line n at k * 10000 + n, whatever source number comes back.
    EXPECT_EQ(fx::translateInfoLog("0:10039(9): error: `z' undeclared", files, "main.glsl"),
              "common.glsl:39: error: `z' undeclared");
}

// A broken soft shader: the renderer logs file:line, draws no soft particle and still draws hard ones.
TEST_F(BrokenShaderTest, RendererReportsABrokenShaderAndDrawsNothingWithIt) {
    const std::string dir = copyShaders("broken_soft");
    const int line = lineOf(dir + "/fs_particles_soft.glsl", "float coverage = texel.a * fade;");
    replaceLine(dir + "/fs_particles_soft.glsl", line, "    float coverage = vViewPos;");
    TestHostAdapter host;
    DirectParticles particles(&host, dir);
    TestScene scene;
    scene.quads = {TestScene::ground(20.0f, glm::vec3(0.2f))};
    OnePuff puff(particles, 128, 96);

    EXPECT_EQ(puff.draw(scene), 0);
    EXPECT_EQ(puff.graph.executed(), std::vector<std::string>{"opaque"});
    EXPECT_TRUE(host.logged("fs_particles_soft.glsl:" + std::to_string(line) + ":"))
        << (host.errors().empty() ? std::string("no error logged") : host.errors().front());
    EXPECT_EQ(particles.renderer.state(), fx::ParticleRenderer::State::Ready);

    particles.settings.options.techniqueOverride = fx::Technique::Hard;
    EXPECT_EQ(puff.draw(scene), 1);
    EXPECT_TRUE(puff.graph.ran("particles"));
}

// With quarterRes the tiled path takes the views it can draw (Tiling::On here); where its
// programs do not build, the renderer logs file:line, and quarter res, not full res, draws the
// heavy smoke it would have taken: the first frame (the programs tried) at full res, the next at
// quarter res.
TEST_F(BrokenShaderTest, BrokenTiledProgramsLeaveHeavySmokeToQuarterRes) {
    const std::string dir = copyShaders("broken_tiled");
    const int line = lineOf(dir + "/cs_particles_tiled.glsl", "const float kOpaque");
    ASSERT_GT(line, 0);
    replaceLine(dir + "/cs_particles_tiled.glsl", line, "const float kOpaque = ;");
    TestHostAdapter host;
    DirectParticles particles(&host, dir);
    std::vector<HandParticle> bank;
    for (int i = 0; i < 60; ++i) {  // one bank, 60 layers deep
        bank.push_back(HandParticle{glm::vec3(0.01f * float(i % 7), 1.0f + 0.01f * float(i % 5), -0.01f * float(i)), 2.0f,
                                    0.5f, 0.3f * float(i)});
    }
    particles.set(bank);
    particles.settings.options.techniqueOverride = fx::Technique::Soft;
    particles.settings.options.quarterRes = true;
    particles.settings.options.tiling = fx::Tiling::On;
    TestScene scene;
    scene.quads = {TestScene::ground(20.0f, glm::vec3(0.2f))};
    const fx::ViewInfo view = makeView(glm::vec3(0, 2, 6), glm::vec3(0, 1, 0), 128, 96);
    TestFrameGraph graph(128, 96);
    int drawn = 0;
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = particles.declare(view, f); });
    EXPECT_EQ(drawn, 60);
    EXPECT_TRUE(host.logged("cs_particles_tiled.glsl:" + std::to_string(line) + ":"))
        << (host.errors().empty() ? std::string("no error logged") : host.errors().front());
    EXPECT_FALSE(graph.ran("particles_tiled"));
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = particles.declare(view, f); });
    EXPECT_EQ(drawn, 60);
    EXPECT_TRUE(graph.ran("particles_quarter")) << "the smoke is heavy enough for quarter res";
    EXPECT_FALSE(graph.ran("particles_tiled"));
}

// Soft programs per contrast power: a cache key of their own (ProgramCache::Key::powerSteps),
// built when asked for, once, with the power's bits folded (no uPowerWhole left in the program);
// get() never builds: an unbuilt power draws with the general soft program.
TEST_F(ShaderLoaderTest, SoftProgramsForOnePowerAreKeysOfTheCache) {
    using Cache = fx::ProgramCache;
    Cache programs(fx::snapshotShaderReader(fx::shaderReader(kShaders)));
    std::vector<std::string> errors;
    EXPECT_EQ(programs.build({Cache::Key{Cache::Soft}, Cache::Key{Cache::SoftGeneralPower}}, &errors), 2);
    ASSERT_TRUE(errors.empty()) << errors.front();
    const fx::ParticleProgram& general = programs.get(Cache::Soft, false);
    ASSERT_NE(general.program, 0u);
    EXPECT_GE(general.powerWhole, 0);
    const uint64_t before = fx::programBuildCounts().built;
    EXPECT_EQ(programs.get(Cache::Soft, false, 2.0f).program, general.program);  // not built: the general one
    EXPECT_EQ(fx::programBuildCounts().built, before);                           // and get() compiled nothing

    std::vector<Cache::Key> keys;
    Cache::addDrawKeys(fx::Technique::Soft, 2.0f, false, &keys);
    Cache::addDrawKeys(fx::Technique::Soft, 1.5f, false, &keys);
    Cache::addDrawKeys(fx::Technique::Soft, 1.5f, false, &keys);  // added once
    EXPECT_EQ(keys.size(), 6u);  // Soft and Soft at power 2, 1.5; lit and unlit
    EXPECT_EQ(programs.build(keys, &errors), 5);  // Soft lit and the four powered builds (Soft was built)
    EXPECT_EQ(fx::programBuildCounts().built, before + 5);
    const uint32_t two = programs.get(Cache::Soft, false, 2.0f).program;
    EXPECT_NE(two, 0u);
    EXPECT_NE(two, general.program);
    EXPECT_EQ(programs.get(Cache::Soft, false, 2.0f).powerWhole, -1);  // folded
    EXPECT_EQ(programs.build(keys, &errors), 0);                        // each key tried once
    EXPECT_EQ(programs.get(Cache::Soft, false, 2.0f).program, two);
    const uint32_t litOneAndAHalf = programs.get(Cache::Soft, true, 1.5f).program;
    EXPECT_NE(litOneAndAHalf, 0u);
    EXPECT_NE(litOneAndAHalf, programs.get(Cache::Soft, true).program);
    EXPECT_EQ(programs.keys().size(), 7u);  // every key tried, for a reload to build anew
    // Other powers and variants are what get(v, lit) gives.
    EXPECT_EQ(programs.get(Cache::SoftGeneralPower, false, 1.3f).program,
              programs.get(Cache::SoftGeneralPower, false).program);
    EXPECT_EQ(programs.get(Cache::Soft, false, 1.3f).program, general.program);
    EXPECT_EQ(programs.get(Cache::HardZBuffer, false, 2.0f).program, 0u);  // not asked for
    EXPECT_TRUE(errors.empty());
    // The key packs every field: no two of the variant space share bits.
    std::vector<uint32_t> bits;
    for (int v = 0; v < Cache::VariantCount; ++v) {
        for (int lit = 0; lit < 2; ++lit) {
            for (int s = -1; s <= Cache::kMaxPowerSteps; ++s) {
                bits.push_back(Cache::Key{Cache::Variant(v), lit == 1, s}.bits());
            }
        }
    }
    std::sort(bits.begin(), bits.end());
    EXPECT_EQ(std::unique(bits.begin(), bits.end()), bits.end());
}

// Quarter-res draws ask for builds of their own (Key::halfRes: the half-res depth read without the
// decode), powers included; where such a build is missing the full-res one stands in (it reads the
// half-res depth through the identity decode the quarter-res pass sets). Hard at quarter res is
// its own variant, half-res by its defines.
TEST_F(ShaderLoaderTest, QuarterResDrawsTakeTheirHalfResBuildsOrTheFullResOnes) {
    using Cache = fx::ProgramCache;
    Cache programs(fx::snapshotShaderReader(fx::shaderReader(kShaders)));
    std::vector<std::string> errors;
    ASSERT_EQ(programs.build(Cache::techniqueKeys(), &errors), 2 * Cache::VariantCount);
    ASSERT_TRUE(errors.empty()) << errors.front();

    const Cache::Key soft = Cache::drawKey(fx::Technique::Soft, true, 2.0f, false);
    EXPECT_TRUE(soft.halfRes);
    EXPECT_NE(soft.bits(), Cache::drawKey(fx::Technique::Soft, false, 2.0f, false).bits());
    const Cache::Key hard = Cache::drawKey(fx::Technique::Hard, true, 1.0f, false);
    EXPECT_EQ(hard.variant, Cache::HardLinearDepth);
    EXPECT_FALSE(hard.halfRes);
    EXPECT_NE(Cache::Key{Cache::HardLinearDepth}.defines().find("FX_HALF_RES_DEPTH"), std::string::npos);
    EXPECT_NE(soft.defines().find("FX_HALF_RES_DEPTH"), std::string::npos);
    EXPECT_EQ(Cache::drawKey(fx::Technique::Soft, false, 2.0f, false).defines().find("FX_HALF_RES_DEPTH"),
              std::string::npos);

    // Nothing half-res built yet: the full-res general builds stand in.
    for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical}) {
        for (bool lit : {false, true}) {
            const Cache::Key wanted = Cache::drawKey(t, true, 2.0f, lit);
            const Cache::Key got = programs.filter(wanted);
            EXPECT_FALSE(got.halfRes);
            EXPECT_EQ(got.lit, lit);
            ASSERT_NE(programs.find(got), nullptr);
            EXPECT_EQ(programs.find(got)->program, programs.get(got.variant, lit).program);
        }
    }

    // What prepareGl builds while quarter res is on, and a power's: then each draw has its own.
    std::vector<Cache::Key> keys = Cache::halfResKeys();
    EXPECT_EQ(keys.size(), 6u);  // Soft, SoftGeneralPower, Spherical; lit and unlit
    Cache::addDrawKeys(fx::Technique::Soft, 2.0f, true, &keys);
    EXPECT_EQ(keys.size(), 8u);  // the power's own two
    EXPECT_EQ(programs.build(keys, &errors), 8);
    ASSERT_TRUE(errors.empty()) << errors.front();
    for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical}) {
        for (bool lit : {false, true}) {
            const Cache::Key got = programs.filter(Cache::drawKey(t, true, 2.0f, lit));
            EXPECT_TRUE(got.halfRes);
            EXPECT_EQ(got.lit, lit);
            ASSERT_NE(programs.find(got), nullptr);
            EXPECT_NE(programs.find(got)->program, programs.get(got.variant, lit).program);
        }
    }
    EXPECT_EQ(programs.filter(soft).powerSteps, 4);  // the power's own half-res build
    // The general power at quarter res: its half-res build.
    const Cache::Key general = programs.filter(Cache::drawKey(fx::Technique::Soft, true, 1.3f, false));
    EXPECT_EQ(general.variant, Cache::SoftGeneralPower);
    EXPECT_TRUE(general.halfRes);
    // A full-res draw never takes a half-res build.
    EXPECT_FALSE(programs.filter(Cache::drawKey(fx::Technique::Soft, false, 2.0f, false)).halfRes);
}

// Puffs sunk into the ground, 0.3 .. 1.1 m in front of a wall that ends 2.2 m up, sky above it
// (reversed-Z): the ground fades their lower halves gradually, the wall each one by its own
// amount, and their tops stand against the sky.
EdgeScene sunkenPuffs(int width, int height) {
    EdgeScene edge;
    for (int i = 0; i < 7; ++i) {
        edge.puffs.push_back(HandParticle{glm::vec3(-3.0f + float(i), 0.4f + 0.3f * float(i % 3), -0.4f * float(i % 3)),
                                          2.6f, 0.5f, 0.7f * float(i), 1.0f, i & 3});
    }
    edge.scene.sky = glm::vec3(0.08f, 0.1f, 0.2f);
    edge.scene.reversedZ = true;
    edge.scene.quads = {TestScene::ground(60.0f, glm::vec3(0.1f)),
                        TestScene::wallZ(-1.5f, -10.0f, 10.0f, 0.0f, 2.2f, glm::vec3(0.2f, 0.1f, 0.1f))};
    edge.view = makeView(glm::vec3(0.0f, 1.6f, 7.0f), glm::vec3(0.0f, 0.6f, 0.0f), width, height);
    useReversedZ(&edge.view);
    edge.softness = 1.5f;
    return edge;
}

// Breaks only the per-power build (FX_POWER_STEPS) of a copy of the shaders. Returns the copy
// and the broken line.
std::pair<std::string, int> shadersWithABrokenPowerBuild(const std::string& name) {
    const std::string dir = copyShaders(name);
    const int line = lineOf(dir + "/particles_common.glsl", "const int kPowerWhole = FX_POWER_STEPS / 2;");
    if (line > 0) replaceLine(dir + "/particles_common.glsl", line, "const int kPowerWhole = undeclaredPower;");
    return {dir, line};
}

// The per-power programs draw what the general one (uniform bits) draws, within 1/255, for
// powers whose curves differ (0.5 .. 16, power 1 taking no curve at all), over puffs that the
// wall and ground fade. The general program stands in where a power's build fails: a copy of
// the shaders breaks only that build, so it draws every power there, and says so once (the same
// file:line breaks each power's build: one message, as for any other shader error).
TEST_F(BrokenShaderTest, SoftProgramsForOnePowerDrawWhatTheGeneralOneDraws) {
    constexpr int kW = 160, kH = 120;
    const auto [brokenDir, line] = shadersWithABrokenPowerBuild("broken_power");
    ASSERT_GT(line, 0);
    EdgeScene edge = sunkenPuffs(kW, kH);
    TestFrameGraph graph(kW, kH, true);
    TestHostAdapter host, brokenHost;
    DirectParticles perPower(&host);
    DirectParticles general(&brokenHost, brokenDir);
    for (DirectParticles* d : {&perPower, &general}) {
        d->desc.render.softness = edge.softness;  // wide fades: every part of the curve is on screen
        d->settings.options.techniqueOverride = fx::Technique::Soft;
        d->set(edge.puffs);
    }
    int logged = 0;
    Image linearCurve, steepCurve;
    for (float power : {1.0f, 0.5f, 1.5f, 2.0f, 3.5f, 16.0f}) {
        Image images[2];
        int k = 0;
        for (DirectParticles* d : {&perPower, &general}) {
            d->desc.render.contrastPower = power;
            int drawn = 0;
            renderFrame(graph, edge.scene, edge.view, [&](fx::FrameBuilder& f) { drawn = d->declare(edge.view, f); });
            ASSERT_EQ(drawn, int(edge.puffs.size()));
            images[k++] = graph.readColor();
        }
        const int diff = maxAbsDiff(images[0], images[1]);
        std::printf("[ measured ] contrast %.1f: per-power against general program, max diff %d/255\n",
                    double(power), diff);
        EXPECT_LE(diff, 1) << "contrast " << power;
        if (power == 1.0f) linearCurve = images[0];
        if (power == 16.0f) steepCurve = images[0];
        logged = 1;  // one cause, one message, whichever powers it breaks (ShaderErrorLog)
        EXPECT_EQ(int(brokenHost.errors().size()), logged) << "one message for the broken line";
        EXPECT_TRUE(brokenHost.logged("particles_common.glsl:" + std::to_string(line) + ":"));
    }
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
    // The curve shows: power 16 against power 1.
    const int curveDiff = maxAbsDiff(linearCurve, steepCurve);
    std::printf("[ measured ] contrast 16 against 1: max diff %d/255\n", curveDiff);
    EXPECT_GT(curveDiff, 20);
    // Drawn again: no new build, no new message.
    renderFrame(graph, edge.scene, edge.view, [&](fx::FrameBuilder& f) { general.declare(edge.view, f); });
    EXPECT_EQ(int(brokenHost.errors().size()), logged);
}

// The scene depth is read through the renderer's own nearest sampler, whatever sampling state
// the host left on its linear-depth texture: linear filtering (textureLod reads texel centres),
// or GL's defaults, a mipmapped minification filter with levels up to 1000 that the texture does
// not have. That one makes the texture incomplete (reads return 0, "nothing drawn" everywhere),
// for texelFetch too, unless a sampler object with a plain filter is bound.
TEST_F(ShaderLoaderTest, TheHostsDepthSamplingStateDoesNotChangeThePicture) {
    constexpr int kW = 157, kH = 113;  // 1/157 and 1/113 are not exact: texel centres round
    EdgeScene edge = sunkenPuffs(kW, kH);
    TestFrameGraph graph(kW, kH, true);
    TestHostAdapter host;
    DirectParticles direct(&host);
    direct.desc.render.softness = edge.softness;
    direct.set(edge.puffs);
    auto frame = [&](fx::Technique t, bool quarter) {
        direct.settings.options.techniqueOverride = t;
        direct.settings.options.quarterRes = quarter;
        direct.settings.options.quarterResAlways = quarter;
        renderFrame(graph, edge.scene, edge.view, [&](fx::FrameBuilder& f) { direct.declare(edge.view, f); });
        return graph.readColor();
    };
    for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical, fx::Technique::Hard}) {  // mega: MegaTest
        for (bool quarter : {false, true}) {
            graph.setSceneDepthSampling(GL_NEAREST, GL_NEAREST, 0);
            const Image nearest = frame(t, quarter);
            graph.setSceneDepthSampling(GL_LINEAR, GL_LINEAR, 0);
            EXPECT_EQ(maxAbsDiff(nearest, frame(t, quarter)), 0)
                << "linear, technique " << int(t) << (quarter ? " quarter" : "");
            graph.setSceneDepthSampling(GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, 1000);
            EXPECT_EQ(maxAbsDiff(nearest, frame(t, quarter)), 0)
                << "GL defaults, technique " << int(t) << (quarter ? " quarter" : "");
            graph.setSceneDepthSampling(GL_NEAREST, GL_NEAREST, 0);
        }
    }
}

TEST_F(ShaderLoaderTest, MissingAtlasDisablesTheRendererWithAMessage) {
    TestHostAdapter host;
    DirectParticles particles(&host, std::string(), scratchDir() + "/no_data_here");
    TestScene scene;
    OnePuff puff(particles, 64, 48);
    EXPECT_EQ(puff.draw(scene), 0);
    EXPECT_EQ(puff.graph.executed(), std::vector<std::string>{"opaque"});
    EXPECT_EQ(particles.renderer.state(), fx::ParticleRenderer::State::Failed);
    EXPECT_TRUE(host.logged("smoke_atlas.png"));
}

}  // namespace
}  // namespace fxtest

// The one source loader's named codes, through an in-memory reader (what the engine, the plugin
// and the harness share; no GL, no files).
TEST(ShaderSource, EachFailureHasItsNamedCode) {
    std::map<std::string, std::string> files = {
        {"top.glsl", "#version 330 core\n#include \"mid.glsl\"\nvoid main() {}\n"},
        {"mid.glsl", "float f() { return 1.0; }\n"},
        {"noversion.glsl", "void main() {}\n"},
        {"badinclude.glsl", "#version 330 core\n#include mid.glsl\n"},
        {"missing.glsl", "#version 330 core\n#include \"nowhere.glsl\"\n"},
        {"loop.glsl", "#version 330 core\n#include \"loop1.glsl\"\n"},
    };
    for (int i = 1; i <= fx::kMaxIncludeDepth + 2; ++i) {
        files["loop" + std::to_string(i) + ".glsl"] = "#include \"loop" + std::to_string(i + 1) + ".glsl\"\n";
    }
    const fx::ShaderReader read = [&](const std::string& name, std::string* text, std::string* why) {
        auto it = files.find(name);
        if (it == files.end()) {
            *why = "not in the test's table";
            return false;
        }
        *text = it->second;
        return true;
    };
    fx::ShaderSource src;
    std::string error;
    EXPECT_EQ(fx::expandShaderSource(read, "top.glsl", "", &src, &error), fx::ShaderError::None) << error;
    EXPECT_EQ(src.files, (std::vector<std::string>{"top.glsl", "mid.glsl"}));
    EXPECT_EQ(src.text.rfind("#version 330 core\n", 0), 0u);
    EXPECT_EQ(fx::expandShaderSource(read, "noversion.glsl", "", &src, &error), fx::ShaderError::MissingVersion);
    EXPECT_EQ(fx::expandShaderSource(read, "noversion.glsl", "", &src, &error, fx::VersionLine::Implied),
              fx::ShaderError::None);
    EXPECT_EQ(src.text.rfind("#version 330 core\n", 0), 0u);  // supplied by the loader
    EXPECT_EQ(fx::expandShaderSource(read, "badinclude.glsl", "", &src, &error), fx::ShaderError::MalformedInclude);
    EXPECT_NE(error.find("badinclude.glsl:2"), std::string::npos) << error;
    EXPECT_EQ(fx::expandShaderSource(read, "missing.glsl", "", &src, &error), fx::ShaderError::FileNotFound);
    EXPECT_NE(error.find("missing.glsl:2"), std::string::npos) << error;
    EXPECT_EQ(fx::expandShaderSource(read, "loop.glsl", "", &src, &error), fx::ShaderError::IncludeTooDeep);
    EXPECT_STREQ(fx::shaderErrorName(fx::ShaderError::IncludeTooDeep), "IncludeTooDeep");
}
