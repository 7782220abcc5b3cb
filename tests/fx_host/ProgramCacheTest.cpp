// One program cache (fx_plugin/render/ProgramCache.h) filled by prepareGl and
// by shader reloads; no program is compiled inside a pass, and none while a frame is declared
// when the host calls prepareGl again after changing options or reactions (as engine_stub does).
// The counts are the library's own (ShaderLoader.h: programBuildCounts), taken around every
// call, through the C boundary a real host uses.
#include <glad/gl.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>

#include "FxTestHost.h"
#include "RunCommand.h"
#include "FileEdits.h"
#include "../../fx_plugin/render/ShaderLoader.h"

namespace fxtest {
namespace program_cache_test {  // named: the fx_host tests build as unity batches

constexpr int kW = 96, kH = 72;

std::string copyOf(const std::string& from, const std::string& name) {
    const std::string dir = scratchDir() + "/" + name;
    EXPECT_EQ(std::system(("rm -rf '" + dir + "' && cp -r '" + from + "' '" + dir + "'").c_str()), 0);
    return dir;
}

class ProgramCacheTest : public FxHostTest {
protected:
    void SetUp() override {
        FxHostTest::SetUp();
        shaders = copyOf(CUBE_SOURCE_DIR "/shaders", "cache_shaders");
        reactions = copyOf(CUBE_SOURCE_DIR "/reactions", "cache_reactions");
        fx::PluginImports imports;
        imports.host = &host;
        imports.shaderDir = shaders;
        plugin = fxCreatePlugin(imports);
        ASSERT_TRUE(plugin);
        ASSERT_TRUE(plugin->loadReactions(reactions, nullptr));
        scene.quads = {TestScene::ground(40.0f, glm::vec3(0.2f)), TestScene::wallZ(-4.0f, -6.0f, 6.0f, 0.0f, 3.0f,
                                                                                    glm::vec3(0.4f))};
        host.setRearSlip(1.0f);
    }

    // Steps the simulation and draws two frames (shadow passes, then the particle passes) and
    // returns how many programs were compiled while they were declared or ran.
    uint64_t frames() {
        const uint64_t before = fx::programBuildCounts().inFrame;
        for (int f = 0; f < 2; ++f) {
            for (int s = 0; s < 10; ++s) {
                for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, nullptr);
            }
            renderFrame(graph, scene, view, [&](fx::FrameBuilder& frame) {
                plugin->declareShadowPasses(view, frame);
                EXPECT_EQ(plugin->declarePasses(view, frame), fx::ErrorCode::None);
            });
            drawn += plugin->stats().particlesDrawn;
        }
        return fx::programBuildCounts().inFrame - before;
    }

    // prepareGl, then frames: returns the programs prepareGl built (the frames must build none).
    uint64_t prepareThenDraw(const std::string& label) {
        const uint64_t before = fx::programBuildCounts().built;
        EXPECT_TRUE(plugin->prepareGl(nullptr)) << label;
        const uint64_t prepared = fx::programBuildCounts().built - before;
        EXPECT_EQ(frames(), 0u) << label << ": a program was compiled during a frame";
        return prepared;
    }

    // Edits burnout_smoke.yaml to a contrast power no reaction drew with (2.0 -> 3.5) and waits
    // until the plugin's hot reload has taken it.
    void reloadWithContrastPower35() {
        const std::string burnout = reactions + "/burnout_smoke.yaml";
        std::string yaml = cubetest::readFile(burnout);
        const size_t at = yaml.find("contrast_power: 2.0");
        ASSERT_NE(at, std::string::npos);
        yaml.replace(at, 19, "contrast_power: 3.5");
        cubetest::writeAhead(burnout, yaml, 10);
        bool reloaded = false;  // the library looks at the disk at most every 0.1 s
        for (int i = 0; i < 100 && !reloaded; ++i) {
            reloaded = plugin->pollHotReload(nullptr);
            if (!reloaded) std::this_thread::sleep_for(std::chrono::milliseconds(15));
        }
        ASSERT_TRUE(reloaded);
    }

    // Appends a comment to the copy's shader `file` and reloads the shaders: programs are built.
    void editAndReloadShader(const std::string& file) {
        const std::string path = shaders + "/" + file;
        cubetest::writeAhead(path, cubetest::readFile(path) + "\n// an edit that changes nothing\n", 20);
        const uint64_t before = fx::programBuildCounts().built;
        ASSERT_TRUE(plugin->pollShaderReload(nullptr));
        EXPECT_GT(fx::programBuildCounts().built, before);
    }

    TestHostAdapter host;
    std::string shaders, reactions;
    std::unique_ptr<fx::Plugin> plugin;
    TestScene scene;
    TestFrameGraph graph{kW, kH};
    fx::ViewInfo view = makeView(glm::vec3(3.0f, 1.6f, 6.0f), glm::vec3(0.0f, 0.6f, 1.0f), kW, kH);
    int drawn = 0;
};

// Every option a host can switch at run time, one after another, each followed by prepareGl:
// prepareGl builds what the switch reaches (> 0 where it reaches something new; nothing for a
// deprecated switch), the frames compile nothing, and no pass ever does.
TEST_F(ProgramCacheTest, NoFrameCompilesAcrossOptionSwitchesWhenTheHostPreparesAgain) {
    const uint64_t passBuildsBefore = fx::programBuildCounts().inPass;
    EXPECT_GT(prepareThenDraw("start"), 0u);
    ASSERT_GT(drawn, 0) << "no particle drawn: the test would prove nothing";

    struct Switch {
        const char* label;
        std::function<void()> apply;
        bool reachesNew;            ///< prepareGl must build something for it
        bool buildsNothing = false;  ///< prepareGl must build nothing for it (a switch with no effect)
    };
    fx::RenderOptions o;
    const Switch switches[] = {
        {"spherical override", [&] { o.techniqueOverride = fx::Technique::Spherical; plugin->setRenderOptions(o); },
         false},
        {"hard override", [&] { o.techniqueOverride = fx::Technique::Hard; plugin->setRenderOptions(o); }, false},
        // The soft override reaches the contrast powers of reactions drawn hard or spherical so far.
        {"soft override", [&] { o.techniqueOverride = fx::Technique::Soft; plugin->setRenderOptions(o); }, false},
        {"mega override", [&] { o.techniqueOverride = fx::Technique::Mega; plugin->setRenderOptions(o); }, true},
        // Quarter res reaches the quarter-res builds (ProgramCache::halfResKeys).
        {"quarter res", [&] { o = fx::RenderOptions{}; o.quarterRes = true; plugin->setRenderOptions(o); }, true},
        {"bilinear upsample", [&] { o.bilinearUpsample = true; plugin->setRenderOptions(o); }, false},
        {"full res, quads", [&] {
             o = fx::RenderOptions{};
             plugin->setRenderOptions(o);
             plugin->setParticleShape(fx::ParticleShape::Quad);
         }, false},
        {"scene light on", [&] {
             fx::SceneLight light;
             light.toSun = glm::vec3(0.3f, 1.0f, 0.2f);
             light.sunColor = glm::vec3(1.0f);
             light.ambient = glm::vec3(0.3f);
             ASSERT_EQ(plugin->setSceneLight(light), fx::ErrorCode::None);
         }, false},
        // Fade classification has no effect since API 2.4: no program of its own (nor in 2.1).
        {"fade classification", [&] {
             ASSERT_EQ(plugin->setFadeClassification(fx::FadeClassification::On), fx::ErrorCode::None);
         }, false, true},
    };
    for (const Switch& s : switches) {
        s.apply();
        const int drawnBefore = drawn;
        const uint64_t built = prepareThenDraw(s.label);
        EXPECT_GT(drawn, drawnBefore) << s.label << ": nothing drawn";
        if (s.reachesNew) {
            EXPECT_GT(built, 0u) << s.label << ": prepareGl built nothing for it";
        }
        if (s.buildsNothing) {
            EXPECT_EQ(built, 0u) << s.label << ": prepareGl built programs for a switch with no effect";
        }
        std::printf("[ measured ] %-26s prepareGl built %llu programs, frames 0\n", s.label,
                    static_cast<unsigned long long>(built));
    }
    EXPECT_EQ(fx::programBuildCounts().inPass, passBuildsBefore);
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

// Hot reloads: a reaction edit that reaches a contrast power no reaction drew with before (its own
// soft program), and a shader edit (a new cache, the same keys): built by prepareGl and by the
// reload, never by a frame.
TEST_F(ProgramCacheTest, NoFrameCompilesAcrossHotReloads) {
    const uint64_t passBuildsBefore = fx::programBuildCounts().inPass;
    prepareThenDraw("start");
    ASSERT_NO_FATAL_FAILURE(reloadWithContrastPower35());
    EXPECT_EQ(prepareThenDraw("reaction reload"), 2u) << "contrast_power 3.5: its soft program, lit and unlit";

    ASSERT_NO_FATAL_FAILURE(editAndReloadShader("fs_particles_soft.glsl"));
    EXPECT_EQ(frames(), 0u) << "after the shader reload";
    EXPECT_EQ(prepareThenDraw("after the shader reload"), 0u) << "the reload built every key the old cache had";
    EXPECT_EQ(fx::programBuildCounts().inPass, passBuildsBefore);
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

// Quarter res draws with builds of its own (ProgramCache::Key::halfRes): prepareGl builds them,
// a shader reload rebuilds them with every other key, and no frame compiles either time.
TEST_F(ProgramCacheTest, AShaderReloadRebuildsTheQuarterResProgramsAndNoFrameCompiles) {
    const uint64_t passBuildsBefore = fx::programBuildCounts().inPass;
    fx::RenderOptions o;
    o.quarterRes = true;
    o.quarterResAlways = true;
    plugin->setRenderOptions(o);
    EXPECT_GT(prepareThenDraw("quarter res"), 0u);
    ASSERT_GT(drawn, 0);
    ASSERT_TRUE(graph.ran("particles_quarter"));
    ASSERT_NO_FATAL_FAILURE(editAndReloadShader("particles_common.glsl"));
    const int drawnBefore = drawn;
    EXPECT_EQ(frames(), 0u) << "after the shader reload";
    EXPECT_GT(drawn, drawnBefore) << "nothing drawn after the reload";
    EXPECT_TRUE(graph.ran("particles_quarter"));
    EXPECT_EQ(prepareThenDraw("after the shader reload"), 0u) << "the reload built every key the old cache had";
    EXPECT_EQ(fx::programBuildCounts().inPass, passBuildsBefore);
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

// The mega and stateless programs are keys of the same cache: an edit to a mega file rebuilds
// them with every other key in one swap, the renderers take the new builds (a stale program would
// raise a GL error, which the fixture checks), and no frame compiles.
TEST_F(ProgramCacheTest, AShaderReloadSwapsTheMegaProgramsWithTheRestAndNoFrameCompiles) {
    const uint64_t passBuildsBefore = fx::programBuildCounts().inPass;
    fx::RenderOptions o;
    o.techniqueOverride = fx::Technique::Mega;
    plugin->setRenderOptions(o);
    EXPECT_GT(prepareThenDraw("mega"), 0u);
    ASSERT_NO_FATAL_FAILURE(editAndReloadShader("fs_mega_blur.glsl"));
    const int drawnBefore = drawn;
    EXPECT_EQ(frames(), 0u) << "after the shader reload";
    EXPECT_GT(drawn, drawnBefore) << "nothing drawn after the reload";
    EXPECT_EQ(prepareThenDraw("after the shader reload"), 0u) << "the reload built every key the old cache had";
    EXPECT_EQ(fx::programBuildCounts().inPass, passBuildsBefore);
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

// A host that changes reactions without calling prepareGl again: the programs the change reaches
// (a new contrast power's soft program) are built while the next frame is declared (told once, as
// a warning), never inside a pass.
TEST_F(ProgramCacheTest, AHostThatDoesNotPrepareAgainCompilesBeforeThePassesNeverInside) {
    prepareThenDraw("start");
    ASSERT_NO_FATAL_FAILURE(reloadWithContrastPower35());
    const fx::ProgramBuildCounts before = fx::programBuildCounts();
    EXPECT_EQ(frames(), 2u) << "contrast_power 3.5: its soft program, lit and unlit";
    EXPECT_EQ(fx::programBuildCounts().inPass, before.inPass);
    EXPECT_TRUE(host.logged("built while declaring a frame"));
    EXPECT_EQ(frames(), 0u) << "built once";
}

// The immediate path: prepareGl builds its linearise program too, so the first renderView that
// copies the host's z-buffer compiles nothing.
TEST_F(ProgramCacheTest, TheFirstRenderViewCompilesNothingAfterPrepareGl) {
    ASSERT_TRUE(plugin->prepareGl(nullptr));
    for (int s = 0; s < 20; ++s) {
        for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, nullptr);
    }
    const GLuint fbo = graph.colorFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, kW, kH);
    scene.drawOpaque(view);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, kW, kH);
    const fx::ProgramBuildCounts before = fx::programBuildCounts();
    EXPECT_EQ(plugin->renderView(view, fx::HostDepth{}), fx::ErrorCode::None);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    EXPECT_GT(plugin->stats().particlesDrawn, 0);
    EXPECT_EQ(fx::programBuildCounts().inFrame, before.inFrame);
    EXPECT_EQ(fx::programBuildCounts().built, before.built);
}

}  // namespace program_cache_test
}  // namespace fxtest
