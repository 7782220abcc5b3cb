// Fade classification (FadePyramid.h, FadeClassification::On): soft billboards and spheres skip
// the scene-depth fetch in the blocks where the fade pyramid says no geometry lies within their
// softness, or (spheres) no nearer than their deepest point.
//  - The picture is the one drawn without it, bit for bit: under standard depth (the linear
//    target), reversed-Z and a reversed-Z z-buffer read in place, near and far clip planes of
//    0.01 m and 1e7 m, contrast powers folded and general, and particles that cross the ground,
//    stand well in front of a wall, just in front of it, fill more than the view, reach behind
//    the camera or lie wholly behind it.
//  - It skips: with copies of the soft and spherical shaders that discard a skipped fragment
//    instead of giving it a fade of 1 (an unclipped chord), a particle far in front of a wall
//    draws nothing at all, and one that crosses the ground loses a share of its pixels, each of
//    which the unclassified draw shows exactly as with the ground gone.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "FxTestHost.h"

namespace fxtest {
namespace fade_classification_test {  // named: the fx_host tests build as unity batches

constexpr int kW = 256, kH = 192;

// The shaders with the soft and spherical programs' skipped fragments discarded, in a folder of
// their own.
std::string shadersDiscardingSkips() {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(scratchDir()) / "shaders_discarding_skips";
    fs::remove_all(dir);
    fs::copy(fs::path(CUBE_SOURCE_DIR) / "shaders", dir);
    for (const auto& [file, at] : {std::pair<const char*, const char*>{"fs_particles_soft.glsl", "    float fade = 1.0;\n"},
                                   {"fs_particles_spherical.glsl", "    float sceneZ = 3.0e38;\n"}}) {
        const fs::path path = dir / file;
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        std::string s = text.str();
        const size_t pos = s.find(at);
        EXPECT_NE(pos, std::string::npos) << path << ": the line this test edits is not there";
        if (pos != std::string::npos) s.insert(pos, "    if (!nearScene) discard;\n");
        std::ofstream(path) << s;
    }
    return dir.string();
}

const char* techniqueName(fx::Technique t) { return t == fx::Technique::Soft ? "soft" : "spherical"; }

class FadeClassificationTest : public FxHostTest {
protected:
    Image draw(DirectParticles& particles, TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view,
               bool classify) {
        particles.settings.classification = classify ? fx::FadeClassification::On : fx::FadeClassification::Off;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = particles.declare(view, f); });
        return graph.readColor();
    }
    TestHostAdapter host;
    DirectParticles direct{&host};
    int drawn = 0;
};

// White smoke (softness 1 m) on a black world: ground, a far wall and particles of every kind of
// placement, soft billboards and spheres; every frame drawn with and without classification.
TEST_F(FadeClassificationTest, ClassifiedFramesAreBitIdenticalToUnclassifiedOnes) {
    direct.desc.render.softness = 1.0f;
    direct.desc.render.nearFade = 0.3f;
    direct.set({
        HandParticle{glm::vec3(0.0f, 1.0f, 0.0f), 4.0f, 0.5f, 0.3f},    // crosses the ground
        HandParticle{glm::vec3(-3.0f, 3.0f, -5.0f), 3.0f, 0.5f, 1.1f},  // 15 m in front of the wall
        HandParticle{glm::vec3(1.0f, 1.2f, -19.4f), 3.0f, 0.5f, 0.0f},  // 0.6 m in front of it
        HandParticle{glm::vec3(5.0f, 0.5f, 2.0f), 6.0f, 0.5f, 2.0f},    // past the view's right edge
        HandParticle{glm::vec3(0.0f, 2.0f, 7.0f), 3.0f, 0.5f, 0.7f},    // around the camera's near plane
        HandParticle{glm::vec3(0.0f, 2.0f, 11.0f), 2.0f},               // behind the camera
    });
    int compared = 0;
    for (const fx::Technique technique : {fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.desc.render.technique = technique;
        for (const int host : {0, 1, 2}) {
            const bool reversed = host > 0, zBuffer = host == 2;
            for (const float nearPlane : {0.1f, 0.01f}) {
                for (const float farPlane : {1000.0f, 1.0e7f}) {
                    TestFrameGraph graph(kW, kH, reversed, zBuffer);
                    TestScene scene;
                    scene.sky = glm::vec3(0.0f);
                    scene.reversedZ = reversed;
                    scene.quads = {TestScene::ground(60.0f, glm::vec3(0.0f)),
                                   TestScene::wallZ(-20.0f, -40.0f, 40.0f, 0.0f, 30.0f, glm::vec3(0.0f))};
                    fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.0f, 8.0f), glm::vec3(0.0f, 1.0f, 0.0f), kW, kH,
                                                 nearPlane, farPlane);
                    if (reversed) useReversedZ(&view);
                    for (const float contrast : {1.0f, 2.0f, 1.3f}) {  // 1.3: the general-power program
                        direct.desc.render.contrastPower = contrast;
                        SCOPED_TRACE(std::string(techniqueName(technique)) + ", " +
                                     (zBuffer ? "reversed-Z, z-buffer read" : reversed ? "reversed-Z" : "standard") +
                                     ", near " + std::to_string(nearPlane) + ", far " + std::to_string(farPlane) +
                                     ", contrast " + std::to_string(contrast));
                        const Image plain = draw(direct, graph, scene, view, false);
                        ASSERT_GE(drawn, 4);
                        const Image classified = draw(direct, graph, scene, view, true);
                        int smoke = 0;
                        for (int y = 0; y < kH; ++y) {
                            for (int x = 0; x < kW; ++x) smoke += plain.at(x, y)[0] > 8 ? 1 : 0;
                        }
                        ASSERT_GT(smoke, kW * kH / 10) << "too little smoke: the comparison would prove little";
                        EXPECT_EQ(maxAbsDiff(plain, classified), 0);
                        ++compared;
                    }
                }
            }
        }
    }
    EXPECT_EQ(compared, 2 * 3 * 2 * 2 * 3);
}

TEST_F(FadeClassificationTest, SkipsTheFetchOnlyWhereTheFadeIsOne) {
    DirectParticles discarding(&host, shadersDiscardingSkips());
    for (const fx::Technique technique : {fx::Technique::Soft, fx::Technique::Spherical}) {
        for (DirectParticles* p : {&direct, &discarding}) {
            p->desc.render.softness = 1.0f;
            p->desc.render.technique = technique;
        }
        for (const int host : {0, 1, 2}) {
            const bool reversed = host > 0, zBuffer = host == 2;
            const std::string label = std::string(techniqueName(technique)) + ", " +
                                      (zBuffer ? "reversed-Z, z-buffer read" : reversed ? "reversed-Z" : "standard");
            SCOPED_TRACE(label);
            TestFrameGraph graph(kW, kH, reversed, zBuffer);
            fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.0f, 8.0f), glm::vec3(0.0f, 1.0f, 0.0f), kW, kH);
            if (reversed) useReversedZ(&view);
            auto sceneWithGroundAt = [&](float groundY) {
                TestScene scene;
                scene.sky = glm::vec3(0.0f);
                scene.reversedZ = reversed;
                scene.quads = {TestScene::ground(60.0f, glm::vec3(0.0f), groundY),
                               TestScene::wallZ(-20.0f, -40.0f, 40.0f, groundY, 30.0f, glm::vec3(0.0f))};
                return scene;
            };
            auto smokePixels = [](const Image& img) {
                int n = 0;
                for (int y = 0; y < kH; ++y) {
                    for (int x = 0; x < kW; ++x) n += img.at(x, y)[0] > 0 ? 1 : 0;
                }
                return n;
            };
            TestScene scene = sceneWithGroundAt(0.0f);

            // 10 m from the camera, its lower edge 1 m above the ground: the ground behind it lies
            // 10 m further on and the wall 18 m, so no block of it comes within 1 m (nor within the
            // sphere's deepest point, 2.5 m behind its centre). (Large enough on the screen to be
            // classified: 80 px across, over vs_particles.glsl's kClassifyPixels.)
            const std::vector<HandParticle> inFront = {HandParticle{glm::vec3(-1.0f, 3.5f, -2.0f), 5.0f}};
            direct.set(inFront);
            discarding.set(inFront);
            const int shown = smokePixels(draw(direct, graph, scene, view, true));
            ASSERT_GT(shown, 400);
            EXPECT_EQ(smokePixels(draw(discarding, graph, scene, view, true)), 0) << "of " << shown << " smoke pixels";
            EXPECT_EQ(smokePixels(draw(discarding, graph, scene, view, false)), shown) << "unclassified: nothing skipped";

            // Crossing the ground: the blocks near the contact line fetch, the upper ones skip.
            const std::vector<HandParticle> crossing = {HandParticle{glm::vec3(0.0f, 1.0f, 0.0f), 4.0f}};
            direct.set(crossing);
            discarding.set(crossing);
            const Image all = draw(direct, graph, scene, view, true);
            const Image fetched = draw(discarding, graph, scene, view, true);
            TestScene groundGone = sceneWithGroundAt(-100.0f);
            const Image fadeOne = draw(direct, graph, groundGone, view, false);
            int skipped = 0, kept = 0, wrong = 0;
            for (int y = 0; y < kH; ++y) {
                for (int x = 0; x < kW; ++x) {
                    if (all.at(x, y)[0] == 0) continue;
                    if (fetched.at(x, y)[0] != 0) {
                        ++kept;
                        continue;
                    }
                    ++skipped;
                    for (int c = 0; c < 3; ++c) wrong += all.at(x, y)[c] != fadeOne.at(x, y)[c] ? 1 : 0;
                }
            }
            std::printf("[ measured ] %s: a particle across the ground, %d smoke pixels skip the depth fetch, %d fetch\n",
                        label.c_str(), skipped, kept);
            EXPECT_GT(skipped, (skipped + kept) / 4) << "classification skips little";
            EXPECT_GT(kept, 0) << "the contact line needs its fade";
            EXPECT_EQ(wrong, 0) << "a skipped pixel whose fade is not 1 (whose chord the ground clips)";
        }
    }
}

// A view away from (0, 0) of a larger framebuffer (a split screen's second player), drawn through
// renderView: the blocks are the view's own pixels, wherever it lies, so the classified frame is
// the unclassified one bit for bit, reading the bound framebuffer's depth (the plugin's copy) or
// the host's whole-framebuffer depth texture in place, soft billboards and spheres. The camera
// stands 3 m from the smoke; a second plugin with the shaders that discard what they skip shows
// that classification does skip there (fewer smoke pixels classified than not).
class FadeClassificationSplitTest : public LoadedPluginTest {
protected:
    FadeClassificationSplitTest() : LoadedPluginTest(kW, kH, kSmokeOnWall) {}

    static constexpr int kX = 37, kY = 11, kFw = kX + kW + 5, kFh = kY + kH + 3;

    // The view's frame into `split` at (kX, kY), classified or not, by `p`.
    Image frame(fx::Plugin& p, const fx::ViewInfo& v, bool classify, bool texture, const HostTarget& scratch,
                const HostTarget& split) {
        EXPECT_EQ(p.setFadeClassification(classify ? fx::FadeClassification::On : fx::FadeClassification::Off),
                  fx::ErrorCode::None);
        EXPECT_TRUE(p.prepareGl(nullptr));
        glBindFramebuffer(GL_FRAMEBUFFER, scratch.fbo);
        scene.drawOpaque(v);
        glBindFramebuffer(GL_FRAMEBUFFER, split.fbo);
        glViewport(0, 0, kFw, kFh);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, scratch.fbo);
        glBlitFramebuffer(0, 0, kW, kH, kX, kY, kX + kW, kY + kH, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
                          GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, split.fbo);
        glViewport(kX, kY, kW, kH);
        fx::HostDepth depth;
        if (texture) {
            depth.source = fx::HostDepth::Source::DepthTexture;
            depth.texture = split.depth;
        }
        EXPECT_EQ(p.renderView(v, depth), fx::ErrorCode::None);
        EXPECT_GT(p.stats().particlesDrawn, 0);
        return readFramebuffer(split.fbo, kFw, kFh);
    }
    // Pixels of the view's rectangle of `f` that differ from the opaque scene alone.
    int smokePixels(const Image& f, const Image& opaque) const {
        int n = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) n += f.at(kX + x, kY + y)[1] != opaque.at(x, y)[1] ? 1 : 0;
        }
        return n;
    }
};

TEST_F(FadeClassificationSplitTest, AViewAwayFromTheOriginIsTheUnclassifiedOne) {
    const fx::ViewInfo near = makeView(glm::vec3(-2.0f, 1.0f, 3.0f), glm::vec3(0.3f, 0.6f, 0.5f), kW, kH);
    HostTarget scratch(kW, kH, GL_DEPTH_COMPONENT24), split(kFw, kFh, GL_DEPTH_COMPONENT24);

    // The same smoke in a plugin that reads the discarding copy: simulated alike.
    fx::PluginImports imports;
    imports.host = &host;
    imports.shaderDir = shadersDiscardingSkips();
    std::unique_ptr<fx::Plugin> discarding = fxCreatePlugin(imports);
    ASSERT_TRUE(discarding);
    ASSERT_TRUE(discarding->loadReactions(kSmokeOnWall.reactions, nullptr));
    plugin.swap(discarding);
    simulate(1.0f, kSmokeOnWall.slippingSteps);
    plugin.swap(discarding);

    glBindFramebuffer(GL_FRAMEBUFFER, scratch.fbo);
    scene.drawOpaque(near);
    const Image opaque = readFramebuffer(scratch.fbo, kW, kH);
    for (const fx::Technique technique : {fx::Technique::Soft, fx::Technique::Spherical}) {
        fx::RenderOptions o;
        o.techniqueOverride = technique;
        ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
        ASSERT_EQ(discarding->setRenderOptions(o), fx::ErrorCode::None);
        for (const bool texture : {false, true}) {
            const std::string label = std::string(techniqueName(technique)) + ", " +
                                      (texture ? "the host's depth texture" : "the bound framebuffer's depth");
            SCOPED_TRACE(label);
            const Image plain = frame(*plugin, near, false, texture, scratch, split);
            const Image classified = frame(*plugin, near, true, texture, scratch, split);
            const int smoke = smokePixels(plain, opaque);
            EXPECT_GT(smoke, kW * kH / 20) << "little smoke in the view: the comparison would prove little";
            EXPECT_EQ(maxAbsDiff(plain, classified), 0);

            EXPECT_EQ(maxAbsDiff(frame(*discarding, near, false, texture, scratch, split), plain), 0)
                << "the discarding copy draws the same smoke unclassified";
            const int kept = smokePixels(frame(*discarding, near, true, texture, scratch, split), opaque);
            std::printf("[ measured ] split screen, %s: %d of %d smoke pixels fetch the depth classified\n",
                        label.c_str(), kept, smoke);
            EXPECT_LT(kept, smoke) << "nothing was classified: the comparison above proves nothing";
        }
    }
    discarding.reset();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace fade_classification_test
}  // namespace fxtest
