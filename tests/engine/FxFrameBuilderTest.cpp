// engine_stub's fx::FrameBuilder adapter over the frame graph.
#include <gtest/gtest.h>

#include "GlTestContext.h"
#include "game/FxFrameBuilder.h"
#include "rtt/RenderTargetPool.h"

using namespace cube;

class FxFrameBuilderTest : public test::GlTest {};

TEST_F(FxFrameBuilderTest, RelativePluginTargetsFollowTheViewNotThePoolsMainView) {
    rtt::RenderTargetPool pool;
    pool.setViewSize(320, 256);  // the main view
    rtt::FrameGraph graph(pool, true, rtt::TimingMode::Off);
    pool.beginFrame();
    graph.reset();
    rtt::RenderTargetDesc colorDesc;
    colorDesc.width = 96;  // a mirror inset
    colorDesc.height = 33;
    const rtt::FrameGraphResource color = graph.create("mirror.color", colorDesc);
    const rtt::FrameGraphResource depth = graph.create("mirror.scene_depth", colorDesc);

    FxFrameBuilder fx(graph, "mirror.", 50, 96, 33);
    fx::TargetDesc half;
    half.scale = 0.5f;
    const fx::Target t = fx.createTarget("particles_half", half);
    int seenW = 0, seenH = 0;
    fx.addPass("particles_quarter", {fx.sceneDepth()}, {t}, [&](fx::PassContext& ctx) {
        seenW = ctx.width(t);
        seenH = ctx.height(t);
    });
    fx.addPass("particles_composite", {t}, {fx.sceneColor()}, [](fx::PassContext&) {});
    EXPECT_TRUE(fx.readsSceneDepth());
    fx.replay(color, depth);
    graph.addPass("depth", 10, {}, {depth}, [](rtt::PassContext&) {});
    graph.addPass("present", 100, {color}, {}, [](rtt::PassContext&) {}, true);
    ASSERT_TRUE(graph.compile()) << graph.report().error;
    ASSERT_TRUE(graph.execute()) << graph.report().error;
    pool.endFrame();
    EXPECT_EQ(seenW, 48);
    EXPECT_EQ(seenH, 17);  // ceil(33 / 2)
    EXPECT_TRUE(graph.isKept("mirror.particles_quarter"));
}
