// The plugin's contract with its host (fx/Plugin.h, fx/HostAdapter.h), checked through the public
// API only: every invalid call gets its named error and changes nothing, in every build type; GL
// state after every plugin call equals the state before; the scene-depth background may be 0;
// a reversed-Z host gets the same picture; the embedded shaders and atlas draw exactly what the
// files on disk draw.
#include <glad/gl.h>

#include <chrono>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <limits>

#include "FxTestHost.h"
#include "render/TileSort.h"
#include "render/TiledPath.h"

namespace fxtest {
namespace {

constexpr int kW = 192, kH = 144;
constexpr float kDt = 1.0f / 60.0f;

class ContractTest : public FxHostTest {
protected:
    void SetUp() override {
        FxHostTest::SetUp();
        plugin = create();
        ASSERT_TRUE(plugin);
        scene.quads = {TestScene::ground(40.0f, glm::vec3(0.2f)),
                       TestScene::wallZ(-2.0f, -20.0f, 20.0f, 0.0f, 1.2f, glm::vec3(0.4f, 0.3f, 0.3f))};
    }

    std::unique_ptr<fx::Plugin> create(const std::string& shaderDir = {}, const std::string& dataDir = {}) {
        fx::PluginImports imports;
        imports.host = &host;
        imports.shaderDir = shaderDir;
        imports.dataDir = dataDir;
        auto p = fxCreatePlugin(imports);
        if (!p || !p->loadReactions(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml", nullptr)) return nullptr;
        return p;
    }

    static void simulate(fx::Plugin& p, TestHostAdapter& h, int steps) {
        h.setRearSlip(1.0f);
        for (int s = 0; s < steps; ++s) {
            for (int r = 0; r < p.reactionCount(); ++r) p.continueReaction(r, kDt, nullptr);
        }
    }

    Image render(fx::Plugin* p, const fx::ViewInfo& v) {
        renderFrame(graph, scene, v, [&](fx::FrameBuilder& f) {
            if (p) p->declarePasses(v, f);
        });
        return graph.readColor();
    }

    TestHostAdapter host;
    std::unique_ptr<fx::Plugin> plugin;
    TestScene scene;
    fx::ViewInfo view = makeView(glm::vec3(3.0f, 1.6f, 6.0f), glm::vec3(0.0f, 0.6f, 1.0f), kW, kH);
    TestFrameGraph graph{kW, kH};
};

int countDiffering(const Image& a, const Image& b, int tolerance) {
    int n = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) {
            if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > tolerance) {
                ++n;
                break;
            }
        }
    }
    return n;
}

TEST_F(ContractTest, VersionAndNullHostAreRefusedWithTheirCode) {
    EXPECT_EQ(fxApiVersion(), fx::kApiVersion);
    fx::PluginImports imports;
    imports.host = &host;
    fx::ErrorCode code = fx::ErrorCode::None;
    imports.apiVersion = fx::kApiVersion + (1u << 16);  // next major
    EXPECT_EQ(fxCreatePlugin(imports, &code), nullptr);
    EXPECT_EQ(code, fx::ErrorCode::VersionMismatch);
    EXPECT_TRUE(host.logged("error[VersionMismatch] fxCreatePlugin"));
    imports.apiVersion = fx::kApiVersion + 1;  // a newer minor than the plugin offers
    EXPECT_EQ(fxCreatePlugin(imports, &code), nullptr);
    EXPECT_EQ(code, fx::ErrorCode::VersionMismatch);
    imports.apiVersion = fx::kApiVersion;
    imports.host = nullptr;
    EXPECT_EQ(fxCreatePlugin(imports, &code), nullptr);
    EXPECT_EQ(code, fx::ErrorCode::NullArgument);
    imports.host = &host;
    EXPECT_NE(fxCreatePlugin(imports, &code), nullptr);
    EXPECT_EQ(code, fx::ErrorCode::None);
}

TEST_F(ContractTest, InvalidCallsGetTheirCodeAndChangeNothing) {
    simulate(*plugin, host, 30);
    const fx::Stats before = plugin->stats();
    ASSERT_GT(before.particlesAlive, 0);
    const int n = plugin->reactionCount();
    float amount = 1.0f;
    EXPECT_EQ(plugin->continueReaction(-1, kDt, &amount), fx::ErrorCode::IndexOutOfRange);
    EXPECT_EQ(plugin->continueReaction(n, kDt, &amount), fx::ErrorCode::IndexOutOfRange);
    EXPECT_EQ(plugin->continueReaction(0, std::numeric_limits<float>::quiet_NaN(), nullptr),
              fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->continueReaction(0, std::numeric_limits<float>::infinity(), nullptr),
              fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->continueReaction(0, -kDt, nullptr), fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->reactionName(n), "");
    EXPECT_TRUE(host.logged("error[IndexOutOfRange] continueReaction"));
    EXPECT_TRUE(host.logged("error[IndexOutOfRange] reactionName"));
    EXPECT_TRUE(host.logged("error[InvalidValue] continueReaction"));

    fx::RenderOptions bad;
    bad.techniqueOverride = static_cast<fx::Technique>(9);
    bad.quarterRes = true;
    EXPECT_EQ(plugin->setRenderOptions(bad), fx::ErrorCode::InvalidValue);
    EXPECT_FALSE(plugin->renderOptions().quarterRes);  // the old options stay

    const fx::Stats after = plugin->stats();
    EXPECT_EQ(after.particlesAlive, before.particlesAlive);  // no step was taken
    EXPECT_EQ(after.apiErrors, before.apiErrors + 7);  // 5 steps, 1 name, 1 options
    const fx::ParticleCheck check = plugin->checkParticles();
    EXPECT_EQ(check.nonFinite, 0);
    EXPECT_EQ(check.alive, before.particlesAlive);
}

TEST_F(ContractTest, InvalidViewsDeclareNothing) {
    simulate(*plugin, host, 30);
    auto expectRefused = [&](fx::ViewInfo v, const char* what) {
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            EXPECT_EQ(plugin->declarePasses(v, f), fx::ErrorCode::InvalidView) << what;
        });
        EXPECT_FALSE(graph.ran("particles")) << what;
        EXPECT_EQ(graph.targetsCreated(), 0) << what;
    };
    fx::ViewInfo v = view;
    v.width = 0;
    expectRefused(v, "zero width");
    v = view;
    v.height = -4;
    expectRefused(v, "negative height");
    v = view;
    v.nearPlane = 0.0f;
    expectRefused(v, "near 0");
    v = view;
    v.farPlane = v.nearPlane;
    expectRefused(v, "far == near");
    v = view;
    v.proj[2][2] = std::numeric_limits<float>::quiet_NaN();
    expectRefused(v, "NaN projection");
    v = view;
    v.eye.x = std::numeric_limits<float>::infinity();
    expectRefused(v, "infinite eye");
    EXPECT_TRUE(host.logged("error[InvalidView] declarePasses"));
    // A valid view still draws afterwards.
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
        EXPECT_EQ(plugin->declarePasses(view, f), fx::ErrorCode::None);
    });
    EXPECT_TRUE(graph.ran("particles"));
}

TEST_F(ContractTest, TargetsOfAnotherSizeThanTheViewDrawNothing) {
    simulate(*plugin, host, 60);
    const Image without = render(nullptr, view);
    fx::ViewInfo half = makeView(glm::vec3(3.0f, 1.6f, 6.0f), glm::vec3(0.0f, 0.6f, 1.0f), kW / 2, kH / 2);
    const Image mismatched = render(plugin.get(), half);
    EXPECT_EQ(countDiffering(mismatched, without, 0), 0);
    EXPECT_TRUE(host.logged("error[SizeMismatch] particle pass"));
    EXPECT_GT(plugin->stats().apiErrors, 0);
    // The matching view draws smoke.
    EXPECT_GT(countDiffering(render(plugin.get(), view), without, 2), 100);
}

TEST_F(ContractTest, EveryPluginCallLeavesTheGlStateAsItFoundIt) {
    // Scrambled host state before each call that may touch GL, compared after it.
    auto check = [](const char* what, const std::function<void()>& call) {
        applyDirtyHostState();
        const GlStateSnapshot before = captureGlState();
        call();
        EXPECT_EQ(before.diff(captureGlState()), "") << what;
        applyDefaultHostState();
    };
    std::unique_ptr<fx::Plugin> p;
    check("fxCreatePlugin", [&] {
        fx::PluginImports imports;
        imports.host = &host;
        p = fxCreatePlugin(imports);
    });
    ASSERT_TRUE(p);
    check("loadReactions", [&] { p->loadReactions(CUBE_SOURCE_DIR "/reactions", nullptr); });
    check("prepareGl", [&] { EXPECT_TRUE(p->prepareGl(nullptr)); });
    check("continueReaction", [&] { simulate(*p, host, 20); });
    check("pollHotReload", [&] { p->pollHotReload(nullptr); });
    check("destruction", [&] { p.reset(); });
    EXPECT_EQ(glErrorCount(), 0) << glErrorLog();
}

TEST_F(ContractTest, ZeroAsTheDepthBackgroundKeepsSmokeAgainstTheSky) {
    // Look up so that most of the smoke is seen against the sky.
    view = makeView(glm::vec3(3.0f, 0.5f, 6.0f), glm::vec3(0.0f, 2.5f, 1.0f), kW, kH);
    simulate(*plugin, host, 120);
    for (bool quarter : {false, true}) {
        fx::RenderOptions o;
        o.techniqueOverride = fx::Technique::Soft;
        o.quarterRes = quarter;
        o.quarterResAlways = quarter;
        plugin->setRenderOptions(o);
        scene.depthBackground = -1.0f;  // the far plane
        const Image far = render(plugin.get(), view);
        scene.depthBackground = 0.0f;
        const Image zero = render(plugin.get(), view);
        const Image without = render(nullptr, view);
        EXPECT_GT(countDiffering(far, without, 2), 500) << "quarter " << quarter;
        EXPECT_EQ(countDiffering(zero, far, 1), 0) << "quarter " << quarter;
    }
}

TEST_F(ContractTest, AReversedZHostGetsTheSamePicture) {
    // Hard particles are the technique that tests the host's z-buffer; the wall hides part of them.
    simulate(*plugin, host, 90);
    fx::RenderOptions o;
    o.techniqueOverride = fx::Technique::Hard;
    plugin->setRenderOptions(o);
    const Image standard = render(plugin.get(), view);
    const Image without = render(nullptr, view);
    fx::ViewInfo reversed = view;
    useReversedZ(&reversed);
    scene.reversedZ = true;
    const Image reversedImage = render(plugin.get(), reversed);
    scene.reversedZ = false;
    const int smoke = countDiffering(standard, without, 2);
    ASSERT_GT(smoke, 500);
    // The two depth mappings round differently where smoke meets the ground: allow 0.5 % of
    // the smoke's pixels to differ by more than 2/255.
    EXPECT_LE(countDiffering(reversedImage, standard, 2), smoke / 200);
    // Without the convention the plugin would test LEQUAL against a buffer cleared to 0 and
    // draw nothing: the picture must really contain the smoke.
    EXPECT_GT(countDiffering(reversedImage, without, 2), smoke * 9 / 10);
}

// A host that steps or reloads the reactions after declaring a view, before its passes run, gets
// the particles as they were declared: rasterised, tiled, and tiled where the GPU orders and bins
// the view, whose first pass writes the particles from the pools (DrawList::gatherPending: the
// plugin writes them out before the pools change). The next frame shows the step.
TEST_F(ContractTest, ParticlesChangedBetweenDeclaringAndThePassesDrawAsDeclared) {
    struct LimitBack {
        ~LimitBack() {
            fx::TileSort::resetOrderLimit();
            fx::TiledPath::resetCpuListLimit();
        }
    } limitBack;
    for (int way = 0; way < 3; ++way) {
        SCOPED_TRACE(way == 0 ? "rasterised" : way == 1 ? "tiled" : "tiled, the GPU's order and bins");
        ASSERT_TRUE(plugin = create());
        simulate(*plugin, host, 60);
        fx::RenderOptions o;
        o.tiling = way == 0 ? fx::Tiling::Off : fx::Tiling::On;
        ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
        if (way == 2) {  // what a GPU does from 16,384 particles on
            fx::TileSort::setOrderLimit(0);
            fx::TiledPath::setCpuListLimit(0);
        } else {
            fx::TileSort::setOrderLimit(UINT32_MAX);  // the CPU orders, whatever the environment says
        }
        const Image declared = render(plugin.get(), view);
        const uint64_t gathered = fx::TiledPath::gatheredViews();
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            plugin->declarePasses(view, f);
            simulate(*plugin, host, 20);
        });
        EXPECT_EQ(maxAbsDiff(declared, graph.readColor()), 0) << "stepped after declaring";
        const Image stepped = render(plugin.get(), view);
        EXPECT_GT(countDiffering(declared, stepped, 2), 100) << "the step shows in the next frame";
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            plugin->declarePasses(view, f);
            ASSERT_TRUE(plugin->loadReactions(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml", nullptr));
            simulate(*plugin, host, 20);
        });
        EXPECT_EQ(maxAbsDiff(stepped, graph.readColor()), 0) << "reloaded and stepped after declaring";
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + (way == 2 ? 1 : 0))
            << "the first pass wrote the particles of the frame nothing changed under";
    }
}

TEST_F(ContractTest, EmbeddedShadersAndAtlasDrawWhatTheFilesDraw) {
    TestHostAdapter otherHost;
    fx::PluginImports imports;
    imports.host = &otherHost;
    imports.shaderDir = CUBE_SOURCE_DIR "/shaders";
    imports.dataDir = CUBE_SOURCE_DIR "/data";
    auto fromFiles = fxCreatePlugin(imports);
    ASSERT_TRUE(fromFiles && fromFiles->loadReactions(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml", nullptr));
    simulate(*plugin, host, 60);
    simulate(*fromFiles, otherHost, 60);
    for (fx::Technique t : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        fx::RenderOptions o;
        o.techniqueOverride = t;
        plugin->setRenderOptions(o);
        fromFiles->setRenderOptions(o);
        const Image embedded = render(plugin.get(), view);
        const Image files = render(fromFiles.get(), view);
        EXPECT_EQ(countDiffering(embedded, files, 0), 0) << int(t);
    }
    EXPECT_TRUE(plugin->prepareGl(nullptr));
}

TEST_F(ContractTest, PrepareGlReportsABrokenShaderAsDiagnostics) {
    const std::string dir = testing::TempDir() + "/contract_broken_shaders";
    ASSERT_EQ(std::system(("rm -rf " + dir + " && cp -r " CUBE_SOURCE_DIR "/shaders " + dir).c_str()), 0);
    {
        std::FILE* f = std::fopen((dir + "/fs_particles_soft.glsl").c_str(), "a");
        ASSERT_TRUE(f);
        std::fputs("this is not GLSL\n", f);
        std::fclose(f);
    }
    allowShaderCompilerMessages();
    auto broken = create(dir);
    ASSERT_TRUE(broken);
    fx::Diagnostics diags;
    EXPECT_FALSE(broken->prepareGl(&diags));
    ASSERT_FALSE(diags.empty());
    EXPECT_EQ(diags.front().code, fx::ErrorCode::ShaderBuild);
    EXPECT_EQ(diags.front().file, "fs_particles_soft.glsl");
    EXPECT_GT(diags.front().line, 0);
}

}  // namespace
}  // namespace fxtest

namespace fxtest {
namespace {

TEST_F(ContractTest, AFifoInTheShaderOrDataFolderFailsByNameWithoutBlocking) {
    // Override folders are read through SafeFile: a FIFO where a shader or the atlas should be
    // is refused at once (a plain open would wait for a writer forever).
    const std::string dir = testing::TempDir() + "/contract_fifo";
    ASSERT_EQ(std::system(("rm -rf " + dir + " && mkdir -p " + dir + "/data && cp -r " CUBE_SOURCE_DIR
                           "/shaders " + dir + "/shaders && rm " + dir + "/shaders/vs_particles.glsl && mkfifo " +
                           dir + "/shaders/vs_particles.glsl && mkfifo " + dir + "/data/smoke_atlas.png")
                              .c_str()),
              0);
    auto shaders = create(dir + "/shaders");
    ASSERT_TRUE(shaders);
    fx::Diagnostics diags;
    EXPECT_FALSE(shaders->prepareGl(&diags));
    ASSERT_FALSE(diags.empty());
    EXPECT_NE(diags.front().str().find("vs_particles.glsl"), std::string::npos) << diags.front().str();

    TestHostAdapter otherHost;
    fx::PluginImports imports;
    imports.host = &otherHost;
    imports.dataDir = dir + "/data";
    auto atlas = fxCreatePlugin(imports);
    ASSERT_TRUE(atlas);
    diags.clear();
    EXPECT_FALSE(atlas->prepareGl(&diags));
    ASSERT_FALSE(diags.empty());
    EXPECT_EQ(diags.front().code, fx::ErrorCode::ResourceMissing);
    EXPECT_NE(diags.front().message.find("a FIFO"), std::string::npos) << diags.front().message;
}

}  // namespace
}  // namespace fxtest

namespace fxtest {
namespace {

// Live shader edits (PluginImports::shaderDir): a broken edit keeps the last good programs and
// is reported once; a good edit goes live.
TEST_F(ContractTest, ABrokenShaderEditKeepsTheLastGoodProgramsAndSaysSoOnce) {
    const std::string dir = testing::TempDir() + "/contract_shader_reload";
    ASSERT_EQ(std::system(("rm -rf " + dir + " && cp -r " CUBE_SOURCE_DIR "/shaders " + dir).c_str()), 0);
    const std::string soft = dir + "/fs_particles_soft.glsl";
    std::string original;
    {
        std::ifstream in(soft);
        std::stringstream ss;
        ss << in.rdbuf();
        original = ss.str();
    }
    auto write = [&](const std::string& text, int secondsAhead) {
        {
            std::ofstream out(soft, std::ios::trunc);
            out << text;
        }
        // A distinct modification time for each edit, whatever the file system's clock step.
        const auto t = std::filesystem::file_time_type::clock::now() + std::chrono::seconds(secondsAhead);
        std::filesystem::last_write_time(soft, t);
    };
    auto live = create(dir);
    ASSERT_TRUE(live);
    ASSERT_TRUE(live->prepareGl(nullptr));
    fx::RenderOptions o;
    o.techniqueOverride = fx::Technique::Soft;
    live->setRenderOptions(o);
    simulate(*live, host, 60);
    const Image good = render(live.get(), view);
    const Image without = render(nullptr, view);
    ASSERT_GT(countDiffering(good, without, 2), 500);
    EXPECT_FALSE(live->pollShaderReload(nullptr));  // nothing changed

    allowShaderCompilerMessages();
    write(original + "\nthis line is not GLSL\n", 10);
    fx::Diagnostics diags;
    EXPECT_FALSE(live->pollShaderReload(&diags));
    ASSERT_FALSE(diags.empty());
    EXPECT_EQ(diags.front().code, fx::ErrorCode::ShaderBuild);
    EXPECT_EQ(diags.front().file, "fs_particles_soft.glsl");
    auto count = [&](const std::string& fragment) {
        int n = 0;
        for (const std::string& e : host.errors()) n += e.find(fragment) != std::string::npos;
        return n;
    };
    EXPECT_EQ(count("the last good programs are kept"), 1);
    EXPECT_EQ(countDiffering(render(live.get(), view), good, 0), 0);  // still the good programs
    EXPECT_FALSE(live->pollShaderReload(nullptr));  // the same broken edit: not reported again
    EXPECT_EQ(count("the last good programs are kept"), 1);

    // A good edit that visibly changes the smoke (half the alpha) goes live.
    std::string dimmed = original;
    ASSERT_NE(dimmed.rfind("oColor"), std::string::npos);
    dimmed.insert(dimmed.rfind('}'), "    oColor *= 0.5;\n");
    write(dimmed, 20);
    diags.clear();
    EXPECT_TRUE(live->pollShaderReload(&diags));
    EXPECT_TRUE(diags.empty());
    EXPECT_TRUE(host.logged("particle shaders reloaded"));
    EXPECT_GT(countDiffering(render(live.get(), view), good, 2), 500);
}

}  // namespace
}  // namespace fxtest
