// The particle renderer's contracts beyond the techniques: lazy loading, the grow-only instance
// stream, views declared before any of them runs, additive blending, and ramp rebuilds.
#include <cmath>

#include "FxTestHost.h"

namespace fxtest {
namespace {

class RendererTest : public FxHostTest {
protected:
    TestHostAdapter host;
    DirectParticles direct{&host};
    TestScene scene;
};

TEST_F(RendererTest, NothingVisibleLoadsNothingAndDeclaresNothing) {
    TestFrameGraph graph(64, 48);
    const fx::ViewInfo view = makeView(glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), 64, 48);
    int drawn = -1;
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
    EXPECT_EQ(drawn, 0);
    EXPECT_EQ(direct.renderer.state(), fx::ParticleRenderer::State::Unloaded);
    // A particle behind the camera is culled: still nothing loaded, nothing declared.
    direct.set({HandParticle{glm::vec3(0, 1, 12), 1.0f}});
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
    EXPECT_EQ(drawn, 0);
    EXPECT_EQ(graph.executed(), std::vector<std::string>{"opaque"});
    EXPECT_EQ(direct.renderer.state(), fx::ParticleRenderer::State::Unloaded);
    direct.set({HandParticle{glm::vec3(0, 1, 0), 1.0f}});
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
    EXPECT_EQ(drawn, 1);
    EXPECT_EQ(direct.renderer.state(), fx::ParticleRenderer::State::Ready);
}

TEST_F(RendererTest, InstanceBufferGrowsOnlyAndStopsGrowingWhenWarm) {
    TestFrameGraph graph(64, 48);
    const fx::ViewInfo view = makeView(glm::vec3(0, 1, 30), glm::vec3(0, 1, 0), 64, 48);
    auto frameWith = [&](int count) {
        std::vector<HandParticle> ps;
        for (int i = 0; i < count; ++i) {
            ps.push_back(HandParticle{glm::vec3(float(i % 40) - 20.0f, 1.0f + float(i / 40) * 0.1f, 0.0f), 0.5f});
        }
        direct.set(ps);
        int drawn = 0;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
        EXPECT_EQ(drawn, count);
    };
    frameWith(3000);
    const size_t big = direct.renderer.instanceStream().capacityBytes();
    const int grows = direct.renderer.instanceStream().growCount();
    EXPECT_GE(big, 3000 * sizeof(fx::ParticleInstance));
    frameWith(10);
    EXPECT_EQ(direct.renderer.instanceStream().capacityBytes(), big) << "shrank";
    frameWith(3000);
    EXPECT_EQ(direct.renderer.instanceStream().growCount(), grows) << "grew again once warm";
}

// A mirror view declared after the main view and before either executes draws its own particles.
TEST_F(RendererTest, ViewsDeclaredBeforeAnyRunKeepTheirOwnDraws) {
    scene.quads = {TestScene::ground(30.0f, glm::vec3(0.15f))};
    direct.set({HandParticle{glm::vec3(-1, 1, 0), 2.0f}, HandParticle{glm::vec3(2, 1.5f, -1), 2.5f, 0.2f, 1.0f}});
    const fx::ViewInfo a = makeView(glm::vec3(0, 1.5f, 6), glm::vec3(0, 1, 0), 96, 72);
    const fx::ViewInfo b = makeView(glm::vec3(4, 3, -5), glm::vec3(0, 1, 0), 96, 72);
    TestFrameGraph ga(96, 72), gb(96, 72);
    renderFrame(ga, scene, a, [&](fx::FrameBuilder& f) { direct.declare(a, f); });
    const Image aloneA = ga.readColor();
    renderFrame(gb, scene, b, [&](fx::FrameBuilder& f) { direct.declare(b, f); });
    const Image aloneB = gb.readColor();

    ga.beginFrame();
    gb.beginFrame();
    scene.declareHostPasses(ga, a);
    scene.declareHostPasses(gb, b);
    EXPECT_EQ(direct.declare(a, ga), 2);
    EXPECT_EQ(direct.declare(b, gb), 2);
    ga.execute();
    gb.execute();
    EXPECT_EQ(maxAbsDiff(ga.readColor(), aloneA), 0);
    EXPECT_EQ(maxAbsDiff(gb.readColor(), aloneB), 0);
    EXPECT_GT(maxAbsDiff(aloneA, aloneB), 10) << "the two views should differ";
}

// Additive particles only add light (never darken what is behind) and leave coverage alone;
// alpha-blended ones of the same colour replace part of the background.
TEST_F(RendererTest, AdditiveBlendAddsAndAlphaBlendCovers) {
    TestFrameGraph graph(64, 48);
    scene.sky = glm::vec3(0.6f, 0.3f, 0.3f);
    const fx::ViewInfo view = makeView(glm::vec3(0, 0, 4), glm::vec3(0, 0, 0), 64, 48);
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.2f, 0.2f, 0.9f, 0.9f)}};
    direct.set({HandParticle{glm::vec3(0, 0, 0), 3.0f}});
    renderFrame(graph, scene, view, nullptr);
    const Image background = graph.readColor();
    Image result[2];
    for (fx::BlendMode mode : {fx::BlendMode::Alpha, fx::BlendMode::Additive}) {
        direct.desc.render.blend = mode;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { direct.declare(view, f); });
        result[mode == fx::BlendMode::Additive] = graph.readColor();
    }
    const uint8_t* bg = background.at(32, 24);
    const uint8_t* alpha = result[0].at(32, 24);
    const uint8_t* add = result[1].at(32, 24);
    EXPECT_LT(alpha[0], bg[0] - 40) << "alpha blending covers the red background";
    EXPECT_GE(add[0], bg[0]) << "additive never darkens";
    EXPECT_GT(add[2], bg[2] + 40) << "additive adds the blue";
    for (size_t i = 0; i < background.rgba.size(); ++i) {
        if ((i & 3) != 3) {
            ASSERT_GE(result[1].rgba[i], background.rgba[i]);
        }
    }
}

// A hot reload that changes a reaction's colour stops changes the colour on screen.
TEST_F(RendererTest, ColourRampFollowsChangedStops) {
    TestFrameGraph graph(64, 48);
    scene.sky = glm::vec3(0.0f);
    const fx::ViewInfo view = makeView(glm::vec3(0, 0, 4), glm::vec3(0, 0, 0), 64, 48);
    direct.set({HandParticle{glm::vec3(0, 0, 0), 3.0f, 0.25f}});
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1, 0, 0, 1)}};
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { direct.declare(view, f); });
    const uint8_t red = graph.readColor().at(32, 24)[0];
    // Life 0.25 is halfway along a 0 -> 0.5 ramp from black to green: half the brightness.
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0, 0, 0, 1)},
                                      fx::ColorStop{0.5f, glm::vec4(0, 1, 0, 1)}};
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { direct.declare(view, f); });
    const Image img = graph.readColor();
    EXPECT_GT(red, 60);
    EXPECT_EQ(img.at(32, 24)[0], 0);
    EXPECT_NEAR(float(img.at(32, 24)[1]), 0.5f * float(red), 0.1f * float(red));
}

}  // namespace
}  // namespace fxtest
