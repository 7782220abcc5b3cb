// Fade classification (issue 14 item 4, FadeClassifier.h): the tile pass, the three classes of
// hand-placed particles (in front of a far wall, hidden behind a near wall, touching the ground),
// their counts, the image equal bit for bit to the unclassified one under both depth conventions
// and at extreme clip planes, and the switch through the plugin's API on the wheel-smoke frame.
#include <cstdio>
#include <string>

#include "FxTestHost.h"

namespace fxtest {
namespace {

class FadeClassifyTest : public FxHostTest {
protected:
    Image draw(TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view, bool classify) {
        direct.settings.classify = classify;
        direct.settings.countClasses = true;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
        return graph.readColor();
    }

    TestHostAdapter host;
    DirectParticles direct{&host};
    int drawn = 0;
};

std::string countsText(const fx::FadeClassCounts& c) {
    return "fade " + std::to_string(c.fadeNeeded) + ", in front " + std::to_string(c.inFront) + ", hidden " +
           std::to_string(c.hidden) + (c.counted ? "" : " (not counted)");
}

// Camera at (0, 1.5, 5) looking down -z over a ground, a far wall at z = -20 and a near wall
// (x 0..4, z = -2). Three particles 0.5 m wide:
//   at (-1, 2.8, 0):   above the horizon, over the far wall 25 m away: in front;
//   at (2, 1.5, -4):   9 m away straight behind the near wall (7 m): hidden;
//   at (-2, 0.3, 0):   on the ground: its tiles hold ground nearer than it: fade needed.
// Soft (softness 0.3 m) and spherical, standard and reversed-Z depth. With the classes the image
// is the unclassified one, bit for bit; the tile pass runs only when classification is on.
TEST_F(FadeClassifyTest, ClassesOfHandPlacedParticlesAndTheImageIsUnchanged) {
    constexpr int kW = 320, kH = 240;
    direct.desc.render.softness = 0.3f;
    direct.set({HandParticle{glm::vec3(-1.0f, 2.8f, 0.0f), 0.5f}, HandParticle{glm::vec3(2.0f, 1.5f, -4.0f), 0.5f},
                HandParticle{glm::vec3(-2.0f, 0.3f, 0.0f), 0.5f}});
    for (const bool reversed : {false, true}) {
        TestFrameGraph graph(kW, kH, reversed);
        TestScene scene;
        scene.reversedZ = reversed;
        scene.quads = {TestScene::ground(60.0f, glm::vec3(0.2f, 0.2f, 0.2f)),
                       TestScene::wallZ(-20.0f, -40.0f, 40.0f, 0.0f, 30.0f, glm::vec3(0.3f, 0.25f, 0.2f)),
                       TestScene::wallZ(-2.0f, 0.0f, 4.0f, 0.0f, 4.0f, glm::vec3(0.1f, 0.3f, 0.1f))};
        fx::ViewInfo view = makeView(glm::vec3(0.0f, 1.5f, 5.0f), glm::vec3(0.0f, 1.5f, 0.0f), kW, kH);
        if (reversed) useReversedZ(&view);
        for (const fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical}) {
            direct.settings.options.techniqueOverride = t;
            const std::string label = std::string(t == fx::Technique::Soft ? "soft" : "spherical") +
                                      (reversed ? ", reversed-Z" : ", standard depth");
            const Image plain = draw(graph, scene, view, false);
            EXPECT_FALSE(graph.ran(fx::FadeClassifier::kPass)) << label;
            EXPECT_FALSE(direct.renderer.fadeClassCounts().counted) << label;
            const Image classified = draw(graph, scene, view, true);
            ASSERT_EQ(drawn, 3) << label;
            EXPECT_TRUE(graph.ran(fx::FadeClassifier::kPass)) << label;
            const fx::FadeClassCounts c = direct.renderer.fadeClassCounts();
            std::printf("[ measured ] %s: %s\n", label.c_str(), countsText(c).c_str());
            EXPECT_TRUE(c.counted) << label;
            EXPECT_EQ(c.inFront, 1) << label << ": " << countsText(c);
            EXPECT_EQ(c.hidden, 1) << label << ": " << countsText(c);
            EXPECT_EQ(c.fadeNeeded, 1) << label << ": " << countsText(c);
            EXPECT_EQ(maxAbsDiff(plain, classified), 0) << label;
            if (!reversed && t == fx::Technique::Soft) writePng("/tmp/fx_host_classified_soft.png", classified);
        }
    }
}

// The classes' margins hold at extreme clip planes (near 0.01, far 1e7): a particle 10 km away
// (2 km wide, softness 1 m) with a wall 0.1 m, 0.7 m and 5 m behind it. With the wall within the
// softness the fade is needed; 5 m behind, the particle is in front (the margin there is
// 1e-5 x 10 km = 0.1 m plus 1 mm). Either way the classified image equals the unclassified one,
// whose fade TechniqueTest.SoftFadeIsExactWithExtremeClipPlanes checks against the CPU value.
TEST_F(FadeClassifyTest, ExtremeClipPlanesKeepTheImageAndTheClasses) {
    constexpr int kW = 128, kH = 96;
    constexpr float kDistance = 10000.0f;
    direct.desc.render.softness = 1.0f;
    direct.desc.render.contrastPower = 1.5f;
    direct.settings.options.techniqueOverride = fx::Technique::Soft;
    direct.set({HandParticle{glm::vec3(0.0f, 0.0f, -kDistance), 2000.0f}});
    for (const bool reversed : {false, true}) {
        TestFrameGraph graph(kW, kH, reversed);
        fx::ViewInfo view = makeView(glm::vec3(0.0f), glm::vec3(0, 0, -1), kW, kH, 0.01f, 1.0e7f);
        if (reversed) useReversedZ(&view);
        for (const float gap : {0.1f, 0.7f, 5.0f}) {
            TestScene scene;
            scene.sky = glm::vec3(0.0f);
            scene.reversedZ = reversed;
            const float half = kDistance * 4.0f;
            scene.quads = {TestScene::wallZ(-(kDistance + gap), -half, half, -half, half, glm::vec3(0.0f))};
            const Image plain = draw(graph, scene, view, false);
            const Image classified = draw(graph, scene, view, true);
            ASSERT_EQ(drawn, 1);
            const fx::FadeClassCounts c = direct.renderer.fadeClassCounts();
            std::printf("[ measured ] %s, wall %.1f m behind at 10 km: %s\n", reversed ? "reversed-Z" : "standard",
                        double(gap), countsText(c).c_str());
            EXPECT_EQ(maxAbsDiff(plain, classified), 0) << "gap " << gap;
            EXPECT_EQ(c.inFront, gap > 1.0f ? 1 : 0) << "gap " << gap << ": " << countsText(c);
            EXPECT_EQ(c.fadeNeeded, gap > 1.0f ? 0 : 1) << "gap " << gap << ": " << countsText(c);
            EXPECT_EQ(c.hidden, 0) << "gap " << gap;
        }
    }
}

// Through the plugin (API 1.3): Off by default, a bad value refused with nothing changed; on the
// wheel-smoke frame of the wall scene the classified image equals the unclassified one, the
// counts add up to the particles drawn, and every plugin pass restores a scrambled host state.
class FadeClassifyPluginTest : public PluginHostTest {
protected:
    FadeClassifyPluginTest() : PluginHostTest(160, 120) {}
    void SetUp() override {
        PluginHostTest::SetUp();
        createPlugin(CUBE_SOURCE_DIR "/reactions");
    }
};

TEST_F(FadeClassifyPluginTest, SwitchCountsAndHostState) {
    EXPECT_EQ(plugin->fadeClassification(), fx::FadeClassification::Off);
    EXPECT_EQ(plugin->setFadeClassification(static_cast<fx::FadeClassification>(2)), fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->fadeClassification(), fx::FadeClassification::Off);
    EXPECT_EQ(plugin->stats().apiErrors, 1);
    EXPECT_TRUE(host.logged("setFadeClassification"));
    EXPECT_FALSE(plugin->fadeClassCounts().counted);

    simulate(1.0f, 60);
    useWallScene();
    for (const fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical}) {
        fx::RenderOptions o;
        o.techniqueOverride = t;
        plugin->setRenderOptions(o);
        const std::string label = t == fx::Technique::Soft ? "soft" : "spherical";
        EXPECT_EQ(plugin->setFadeClassification(fx::FadeClassification::Off), fx::ErrorCode::None);
        std::string ignored;
        const Image plain = renderChecked(view, false, &ignored);
        EXPECT_FALSE(graph.ran(fx::FadeClassifier::kPass)) << label;

        EXPECT_EQ(plugin->setFadeClassification(fx::FadeClassification::On), fx::ErrorCode::None);
        EXPECT_EQ(plugin->setFadeClassCounting(true), fx::ErrorCode::None);
        std::string mismatches;
        const Image dirty = renderChecked(view, true, &mismatches);
        EXPECT_TRUE(mismatches.empty()) << label << ":\n" << mismatches;
        EXPECT_TRUE(graph.ran(fx::FadeClassifier::kPass)) << label;
        const fx::FadeClassCounts c = plugin->fadeClassCounts();
        std::printf("[ measured ] wall scene, %s, %d drawn: %s\n", label.c_str(), plugin->stats().particlesDrawn,
                    countsText(c).c_str());
        EXPECT_TRUE(c.counted) << label;
        EXPECT_GT(plugin->stats().particlesDrawn, 0) << label;
        EXPECT_EQ(c.fadeNeeded + c.inFront + c.hidden, plugin->stats().particlesDrawn) << label;
        const Image clean = renderChecked(view, false, &ignored);
        EXPECT_EQ(maxAbsDiff(dirty, clean), 0) << label << ": the picture must not depend on the host state";
        EXPECT_EQ(maxAbsDiff(plain, clean), 0) << label << ": classification must not change the picture";
        EXPECT_EQ(plugin->setFadeClassCounting(false), fx::ErrorCode::None);
    }
    // Off again: no tile pass, nothing counted.
    EXPECT_EQ(plugin->setFadeClassification(fx::FadeClassification::Off), fx::ErrorCode::None);
    std::string ignored;
    renderChecked(view, false, &ignored);
    EXPECT_FALSE(graph.ran(fx::FadeClassifier::kPass));
    EXPECT_FALSE(plugin->fadeClassCounts().counted);
}

}  // namespace
}  // namespace fxtest
