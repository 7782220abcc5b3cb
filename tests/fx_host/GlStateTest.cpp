// The plugin restores every GL state it touches: the host puts the context into an unusual
// state before each plugin pass (and before declarePasses, where the renderer loads its GL
// objects lazily), and ~24 state values are compared after it: for every technique, at full
// res and at quarter res with both upsamples. The picture must not depend on that host state.
#include <glad/gl.h>

#include "FxTestHost.h"

namespace fxtest {
// Named so that the test files of one unity translation unit keep their helpers apart.
namespace gl_state_test {

constexpr int kW = 160, kH = 120;

class GlStateTest : public LoadedPluginTest {
protected:
    GlStateTest() : LoadedPluginTest(kW, kH, {CUBE_SOURCE_DIR "/reactions", 60, true}) {}
    Image frame(bool dirty, std::string* mismatches) { return renderChecked(view, dirty, mismatches); }
};

TEST_F(GlStateTest, EveryPassRestoresTheHostState) {
    struct Mode {
        fx::Technique technique;
        bool quarter, bilinear;
    };
    const Mode modes[] = {{fx::Technique::Hard, false, false},      {fx::Technique::Soft, false, false},
                          {fx::Technique::Spherical, false, false}, {fx::Technique::Hard, true, false},
                          {fx::Technique::Soft, true, false},       {fx::Technique::Spherical, true, false},
                          {fx::Technique::Soft, true, true}};
    for (const Mode& m : modes) {
        fx::RenderOptions o;
        o.techniqueOverride = m.technique;
        o.quarterRes = m.quarter;
        o.quarterResAlways = m.quarter;
        o.bilinearUpsample = m.bilinear;
        plugin->setRenderOptions(o);
        const std::string label = std::to_string(int(m.technique)) + (m.quarter ? " quarter" : " full") +
                                  (m.bilinear ? " bilinear" : "");
        std::string mismatches;
        const Image dirtyImage = frame(true, &mismatches);
        EXPECT_TRUE(mismatches.empty()) << label << ":\n" << mismatches;
        size_t pluginPasses = 0;
        for (const std::string& pass : graph.executed()) pluginPasses += pass.rfind("particles", 0) == 0;
        EXPECT_EQ(pluginPasses, m.quarter ? 3u : 1u) << label;
        const Image cleanImage = frame(false, &mismatches);
        EXPECT_EQ(maxAbsDiff(dirtyImage, cleanImage), 0) << label << ": the picture depends on host state";
    }
    EXPECT_GT(plugin->stats().particlesDrawn, 0);
}

// Lit smoke (API 1.2): the opacity map's pass, the lit programs, and declareShadowPasses called
// by the host itself, under a scrambled host state.
TEST_F(GlStateTest, LitSmokeRestoresTheHostStateToo) {
    ASSERT_EQ(plugin->setSceneLight(fx::SceneLight{}), fx::ErrorCode::None);
    for (fx::Technique t : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        for (bool quarter : {false, true}) {
            fx::RenderOptions o;
            o.techniqueOverride = t;
            o.quarterRes = quarter;
            o.quarterResAlways = quarter;
            plugin->setRenderOptions(o);
            const std::string label = std::to_string(int(t)) + (quarter ? " quarter" : " full");
            std::string mismatches;
            const Image dirtyImage = frame(true, &mismatches);
            EXPECT_TRUE(mismatches.empty()) << label << ":\n" << mismatches;
            EXPECT_TRUE(graph.ran("smoke_opacity")) << label;
            const Image cleanImage = frame(false, &mismatches);
            EXPECT_EQ(maxAbsDiff(dirtyImage, cleanImage), 0) << label << ": the picture depends on host state";
        }
    }
    // The host's own call, before its ground pass.
    std::string mismatches;
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
        applyDirtyHostState();
        const GlStateSnapshot before = captureGlState();
        const fx::SmokeShadow shadow = plugin->declareShadowPasses(view, f);
        EXPECT_TRUE(shadow.valid());
        plugin->declarePasses(view, f);
        mismatches += before.diff(captureGlState());
    });
    EXPECT_TRUE(mismatches.empty()) << mismatches;
    plugin->clearSceneLight();
}

// The snapshot catches a change (so the test above can fail).
TEST_F(GlStateTest, SnapshotSeesAChangedValue) {
    applyDirtyHostState();
    const GlStateSnapshot before = captureGlState();
    glBlendFunc(GL_ONE, GL_ONE);
    EXPECT_NE(before.diff(captureGlState()).find("blendSrcRgb"), std::string::npos);
}

// The KHR_debug callback counts (so "no GL error anywhere" can fail); cleared afterwards.
TEST_F(GlStateTest, DebugCallbackCountsErrors) {
    if (!hasKhrDebug()) GTEST_SKIP() << "no KHR_debug";
    glEnable(GLenum(0xDEAD));
    drainGlErrors("deliberate error");
    EXPECT_GE(glErrorCount(), 1);
    resetGlErrors();
}

}  // namespace gl_state_test
}  // namespace fxtest
