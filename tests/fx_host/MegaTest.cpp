// Mega-particles (technique mega, fx_plugin/render/MegaRenderer.h) in the fx_host frame graph:
// hand-placed spheres drawn by MegaRenderer (occlusion by a wall, determinism, one continuous
// volume, lighting from the sun's side), and the whole plugin with the run-time override (passes
// declared only when a Mega batch is visible, the billboard path leaving those batches alone, the
// host's GL state restored after every pass).
#include <glad/gl.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "FxTestHost.h"
#include "../../fx_plugin/render/MegaRenderer.h"

namespace fxtest {
namespace {

bool hasMegaPass(const std::vector<std::string>& passes) {
    for (const std::string& p : passes) {
        if (p.rfind("mega_", 0) == 0) return true;
    }
    return false;
}

bool has(const std::vector<std::string>& passes, const std::string& name) {
    for (const std::string& p : passes) {
        if (p == name) return true;
    }
    return false;
}

class MegaTest : public FxHostTest {
protected:
    MegaTest() {
        direct.desc.render.technique = fx::Technique::Mega;
        direct.desc.render.softness = 0.3f;
    }

    /// One frame of the scene with the hand-placed spheres drawn by MegaRenderer (or none).
    Image draw(TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view, bool particles) {
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            if (!particles) return;
            fx::ParticleBatch batch;
            batch.pool = &direct.pool;
            batch.desc = &direct.desc;
            batch.sortBackToFront = true;
            batch.time = time;
            fx::FrameSettings settings;
            settings.light = light;
            drawn = mega.declarePasses(view, f, &batch, 1, settings);
        });
        return graph.readColor();
    }

    /// A ground and a wall at z = 0 covering x < 0 (the left half of a view from (0, 1.5, 6)).
    static TestScene wallOnTheLeft() {
        TestScene scene;
        scene.quads = {TestScene::ground(50.0f, glm::vec3(0.2f, 0.22f, 0.2f)),
                       TestScene::wallZ(0.0f, -20.0f, 0.0f, 0.0f, 10.0f, glm::vec3(0.3f, 0.5f, 0.3f))};
        return scene;
    }
    /// Three spheres 2-3 m behind the wall's plane, across its edge.
    void setClusterBehindTheWall() {
        direct.set({HandParticle{glm::vec3(-0.6f, 1.5f, -2.5f), 2.0f}, HandParticle{glm::vec3(0.6f, 1.7f, -2.0f), 2.0f},
                    HandParticle{glm::vec3(0.0f, 1.2f, -3.0f), 2.4f}});
    }

    TestHostAdapter host;
    DirectParticles direct{&host};
    fx::MegaRenderer mega{fx::RendererConfig{&host, "", "", nullptr, fx::Jobs()}, direct.programs};  // one cache, as the plugin
    fx::LightState light;
    float time = 1.25f;
    int drawn = 0;
};

// A cluster of spheres 2-3 m behind a wall that hides the left half of the view. Every pixel of
// the wall equals the frame without smoke within 1/255 (the blur's fuzzy edge spreads over the
// wall in the reduced-resolution targets; the composite's depth test removes it), while right of
// the wall the cloud is really drawn (a vacuous pass is ruled out).
TEST_F(MegaTest, NoSmokeOverNearerGeometry) {
    constexpr int kW = 192, kH = 144;
    TestFrameGraph graph(kW, kH);
    TestScene scene = wallOnTheLeft();
    const fx::ViewInfo view = makeView(glm::vec3(0.0f, 1.5f, 6.0f), glm::vec3(0.0f, 1.5f, 0.0f), kW, kH);
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f, 1.0f, 1.0f, 1.0f)}};
    setClusterBehindTheWall();
    const Image reference = draw(graph, scene, view, false);
    const Image img = draw(graph, scene, view, true);
    ASSERT_EQ(drawn, 3);
    writePng("/tmp/fx_host_mega_wall.png", img);
    // The wall's right edge (x = 0, z = 0) lands in the middle column.
    const int edge = int(std::floor(projectToPixel(view, glm::vec3(0.0f, 1.5f, 0.0f)).x));
    int worstBehindWall = 0, bestVisible = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(img.at(x, y)[c]) - int(reference.at(x, y)[c])));
            if (x < edge - 1) worstBehindWall = std::max(worstBehindWall, d);
            if (x > edge + 1) bestVisible = std::max(bestVisible, d);
        }
    }
    std::printf("[ measured ] mega behind a wall: max |diff| on the wall %d/255, beside it %d/255\n",
                worstBehindWall, bestVisible);
    EXPECT_LE(worstBehindWall, 1);
    EXPECT_GT(bestVisible, 60);
}

// The host's scene depth is read through the renderer's own nearest sampler: a host that left
// GL's default sampling on it (a mipmapped minification filter, levels up to 1000, one level
// there: an incomplete texture that reads 0) or linear filtering gets the same cloud.
TEST_F(MegaTest, TheHostsDepthSamplingStateDoesNotChangeTheCloud) {
    constexpr int kW = 157, kH = 113;
    TestFrameGraph graph(kW, kH);
    TestScene scene = wallOnTheLeft();
    const fx::ViewInfo view = makeView(glm::vec3(0.0f, 1.5f, 6.0f), glm::vec3(0.0f, 1.5f, 0.0f), kW, kH);
    setClusterBehindTheWall();
    const Image nearest = draw(graph, scene, view, true);
    ASSERT_EQ(drawn, 3);
    graph.setSceneDepthSampling(GL_LINEAR, GL_LINEAR, 0);
    EXPECT_EQ(maxAbsDiff(nearest, draw(graph, scene, view, true)), 0) << "linear";
    graph.setSceneDepthSampling(GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, 1000);
    EXPECT_EQ(maxAbsDiff(nearest, draw(graph, scene, view, true)), 0) << "GL defaults";
    graph.setSceneDepthSampling(GL_NEAREST, GL_NEAREST, 0);
}

// Two renders of the same particles, clock and camera are byte-identical (the noise is a
// function of world position and simulation time only).
TEST_F(MegaTest, DeterministicForAPausedSimulation) {
    constexpr int kW = 160, kH = 120;
    TestFrameGraph graph(kW, kH);
    TestScene scene;
    scene.quads = {TestScene::ground(50.0f, glm::vec3(0.3f))};
    const fx::ViewInfo view = makeView(glm::vec3(1.0f, 2.0f, 6.0f), glm::vec3(0.0f, 1.0f, 0.0f), kW, kH);
    direct.set({HandParticle{glm::vec3(-0.5f, 1.0f, 0.0f), 2.0f, 0.3f}, HandParticle{glm::vec3(0.7f, 1.3f, 0.2f), 1.6f, 0.6f}});
    light.on = true;
    light.toSun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
    light.ambient = glm::vec3(0.3f);
    const Image a = draw(graph, scene, view, true);
    const Image b = draw(graph, scene, view, true);
    ASSERT_EQ(drawn, 2);
    EXPECT_TRUE(a.rgba == b.rgba) << "max |diff| " << maxAbsDiff(a, b);
    // The clock does animate the noise (the figure above is not trivially equal).
    time += 5.0f;
    const Image later = draw(graph, scene, view, true);
    EXPECT_GT(maxAbsDiff(a, later), 0);
}

// Opacity (white on black: the green channel) along the screen line joining two sphere centres:
// the lowest value, the value at the less opaque centre, and the largest step between
// neighbouring pixels.
struct LineProfile {
    float lowest = 1.0f, atCentres = 1.0f, steepest = 0.0f;
};
LineProfile profile(const Image& img, const fx::ViewInfo& view, glm::vec3 from, glm::vec3 to) {
    LineProfile out;
    const glm::vec3 a = projectToPixel(view, from), b = projectToPixel(view, to);
    out.atCentres = std::min(img.value(int(a.x), int(a.y), 1), img.value(int(b.x), int(b.y), 1));
    float previous = -1.0f;
    const int steps = int(std::ceil(glm::length(glm::vec2(b - a))));
    for (int s = 0; s <= steps; ++s) {
        const glm::vec2 p = glm::mix(glm::vec2(a), glm::vec2(b), float(s) / float(std::max(steps, 1)));
        const float v = img.value(int(p.x), int(p.y), 1);
        out.lowest = std::min(out.lowest, v);
        if (previous >= 0.0f) out.steepest = std::max(out.steepest, std::fabs(v - previous));
        previous = v;
    }
    return out;
}

// A black sky seen from 8 m down the z axis, looking at the origin (192 x 144).
struct BlackSkyShot {
    static constexpr int kW = 192, kH = 144;
    BlackSkyShot() { scene.sky = glm::vec3(0.0f); }
    TestFrameGraph graph{kW, kH};
    TestScene scene;
    const fx::ViewInfo view = makeView(glm::vec3(0.0f, 0.0f, 8.0f), glm::vec3(0.0f), kW, kH);
};

// Unlit white spheres on a black sky, 8 m away. Two overlapping spheres of different depths (the
// front one's outline crosses the back one): along the line joining their centres the opacity
// stays within 15 % of the centres' (no gap) and changes by at most 0.05 between neighbouring
// pixels (no outline). Two spheres 10 cm apart (about 1.5 pixels here): the blur closes the gap
// to at least half the centres' opacity, where the exact spheres leave nothing.
TEST_F(MegaTest, SpheresMeltIntoOneContinuousVolume) {
    BlackSkyShot shot;
    direct.desc.mega.noiseStrength = 0.0f;  // the geometry's continuity alone

    const glm::vec3 left(-1.0f, 0.0f, -0.8f), right(1.0f, 0.2f, 0.4f);
    direct.set({HandParticle{left, 3.0f}, HandParticle{right, 3.0f}});
    const Image overlapping = draw(shot.graph, shot.scene, shot.view, true);
    ASSERT_EQ(drawn, 2);
    writePng("/tmp/fx_host_mega_two_spheres.png", overlapping);
    const LineProfile o = profile(overlapping, shot.view, left, right);

    const glm::vec3 a(-1.05f, 0.0f, 0.0f), b(1.05f, 0.0f, 0.0f);  // radius 1: a 10 cm gap
    direct.set({HandParticle{a, 2.0f}, HandParticle{b, 2.0f}});
    const Image apart = draw(shot.graph, shot.scene, shot.view, true);
    writePng("/tmp/fx_host_mega_gap.png", apart);
    const LineProfile g = profile(apart, shot.view, a, b);
    std::printf("[ measured ] mega overlapping spheres: centres %.3f, lowest between %.3f, steepest step %.3f; "
                "10 cm apart: centres %.3f, lowest between %.3f\n",
                o.atCentres, o.lowest, o.steepest, g.atCentres, g.lowest);
    EXPECT_GT(o.atCentres, 0.5f);
    EXPECT_GE(o.lowest, 0.85f * o.atCentres);
    EXPECT_LE(o.steepest, 0.05f);
    EXPECT_GT(g.atCentres, 0.5f);
    EXPECT_GE(g.lowest, 0.5f * g.atCentres);
}

// Lit by a sun from the right, the right half of a round cloud is brighter than the left half by
// at least 25 % (mean green over cloud pixels); with the sun moved to the left it is the other way.
TEST_F(MegaTest, TheHalfTowardTheSunIsBrighter) {
    BlackSkyShot shot;
    direct.set({HandParticle{glm::vec3(-0.4f, 0.0f, 0.0f), 2.6f}, HandParticle{glm::vec3(0.4f, 0.1f, 0.1f), 2.6f},
                HandParticle{glm::vec3(0.0f, -0.3f, -0.2f), 2.6f}});
    direct.desc.mega.noiseStrength = 0.0f;  // the halves' difference is the light's alone
    light.on = true;
    light.sunColor = glm::vec3(1.0f);
    light.ambient = glm::vec3(0.25f);
    auto halves = [&](glm::vec3 toSun, float* leftMean, float* rightMean) {
        light.toSun = glm::normalize(toSun);
        const Image img = draw(shot.graph, shot.scene, shot.view, true);
        writePng(std::string("/tmp/fx_host_mega_lit_") + (toSun.x > 0.0f ? "right" : "left") + ".png", img);
        double sum[2] = {0.0, 0.0};
        int count[2] = {0, 0};
        const int centre = int(projectToPixel(shot.view, glm::vec3(0.0f)).x);
        for (int y = 0; y < BlackSkyShot::kH; ++y) {
            for (int x = 0; x < BlackSkyShot::kW; ++x) {
                if (x == centre || img.value(x, y, 1) < 0.02f) continue;  // the cloud only
                sum[x > centre] += img.value(x, y, 1);
                ++count[x > centre];
            }
        }
        ASSERT_GT(count[0], 100);
        ASSERT_GT(count[1], 100);
        *leftMean = float(sum[0] / count[0]);
        *rightMean = float(sum[1] / count[1]);
    };
    float l = 0.0f, r = 0.0f, l2 = 0.0f, r2 = 0.0f;
    halves(glm::vec3(1.0f, 0.2f, 0.3f), &l, &r);
    halves(glm::vec3(-1.0f, 0.2f, 0.3f), &l2, &r2);
    std::printf("[ measured ] mega lit, sun right: left %.3f right %.3f; sun left: left %.3f right %.3f\n", l, r,
                l2, r2);
    EXPECT_GT(r, 1.25f * l);
    EXPECT_GT(l2, 1.25f * r2);
    // Mirror images of each other within a few per cent (the cloud is nearly symmetric).
    EXPECT_NEAR(r / l, l2 / r2, 0.35f);
}

// ---- the whole plugin ----------------------------------------------------------------------

class MegaPluginTest : public LoadedPluginTest {
protected:
    static constexpr int kW = 320, kH = 240;
    MegaPluginTest() : LoadedPluginTest(kW, kH, kSmokeOnWall) {}
    void frame(const fx::ViewInfo& v, bool dirty, std::string* mismatches) { renderChecked(v, dirty, mismatches); }
};

TEST_F(MegaPluginTest, OverrideMegaIsAcceptedAndRoutesEveryBatchToMega) {
    fx::RenderOptions o;
    o.techniqueOverride = fx::Technique::Mega;
    ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
    EXPECT_EQ(plugin->renderOptions().techniqueOverride, fx::Technique::Mega);
    std::string ignored;
    frame(view, false, &ignored);
    EXPECT_GT(plugin->stats().particlesDrawn, 0);
    for (const char* p : {fx::MegaRenderer::kDepthPass, fx::MegaRenderer::kSpheresPass, fx::MegaRenderer::kBlurHPass,
                          fx::MegaRenderer::kBlurVPass, fx::MegaRenderer::kCompositePass}) {
        EXPECT_TRUE(graph.ran(p)) << p;
    }
    EXPECT_FALSE(has(graph.declared(), fx::ParticleRenderer::kFullResPass)) << "drawn twice";
    // Back to the reaction's own technique (soft): no Mega pass, the billboards draw.
    o.techniqueOverride = fx::Technique::FromReaction;
    ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
    frame(view, false, &ignored);
    EXPECT_FALSE(hasMegaPass(graph.declared()));
    EXPECT_TRUE(graph.ran(fx::ParticleRenderer::kFullResPass));
}

TEST_F(MegaPluginTest, PassesOnlyWhenAMegaBatchIsVisible) {
    fx::RenderOptions o;
    o.techniqueOverride = fx::Technique::Mega;
    ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
    // Looking away from the smoke: nothing declared, no target created.
    const fx::ViewInfo away = makeView(glm::vec3(0.0f, 2.0f, 20.0f), glm::vec3(0.0f, 2.0f, 40.0f), kW, kH);
    std::string ignored;
    frame(away, false, &ignored);
    EXPECT_TRUE(graph.declared().size() > 0);
    EXPECT_FALSE(hasMegaPass(graph.declared()));
    EXPECT_EQ(graph.targetsCreated(), 0);
    EXPECT_EQ(plugin->stats().particlesDrawn, 0);
    // Facing it: the five passes.
    frame(view, false, &ignored);
    EXPECT_TRUE(hasMegaPass(graph.declared()));
    EXPECT_EQ(graph.targetsCreated(), 7);
}

TEST_F(MegaPluginTest, EveryMegaPassRestoresTheHostState) {
    fx::RenderOptions o;
    o.techniqueOverride = fx::Technique::Mega;
    ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
    for (bool lit : {false, true}) {
        if (lit) {
            ASSERT_EQ(plugin->setSceneLight(fx::SceneLight{}), fx::ErrorCode::None);
        } else {
            plugin->clearSceneLight();
        }
        std::string mismatches;
        frame(view, true, &mismatches);
        writePng(std::string("/tmp/fx_host_mega_burnout_") + (lit ? "lit" : "unlit") + ".png", graph.readColor());
        EXPECT_TRUE(graph.ran(fx::MegaRenderer::kCompositePass));
        EXPECT_TRUE(mismatches.empty()) << (lit ? "lit: " : "unlit: ") << mismatches;
        drainGlErrors("mega frame");
        EXPECT_EQ(glErrorCount(), 0) << glErrorLog();
    }
}

}  // namespace
}  // namespace fxtest
