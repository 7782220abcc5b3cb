// engine_stub's fx::FrameBuilder adapter over the frame graph.
#include <gtest/gtest.h>

#include "PassChecks.h"

#include "GlTestContext.h"
#include "rtt/RenderTargetPool.h"
#include "view/FxFrameBuilder.h"

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

    graph.addPass("depth", 10, {}, {depth}, [](rtt::PassContext&) {});
    FxFrameBuilder fx(graph, color, depth, "mirror.", 50, 96, 33);
    fx::TargetDesc half;
    half.scale = 0.5f;
    const fx::Target t = fx.createTarget("particles_half", half);
    int seenW = 0, seenH = 0;
    fx::TextureRef ref;
    fx.addPass("particles_quarter", {fx.sceneDepth()}, {t}, [&](fx::PassContext& ctx) {
        seenW = ctx.width(t);
        seenH = ctx.height(t);
        ref = ctx.texture(t, 0);
    });
    fx.addPass("particles_composite", {t}, {fx.sceneColor()}, [](fx::PassContext&) {});
    EXPECT_TRUE(fx.readsSceneDepth());
    graph.addPass("present", 100, {color}, {}, [](rtt::PassContext&) {}, true);
    ASSERT_TRUE(graph.compile()) << graph.report().error;
    ASSERT_TRUE(graph.execute()) << graph.report().error;
    pool.endFrame();
    EXPECT_EQ(seenW, 48);
    EXPECT_EQ(seenH, 17);  // ceil(33 / 2)
    EXPECT_TRUE(passKept(graph, "mirror.particles_quarter"));
    EXPECT_TRUE(passKept(graph, "depth"));  // kept because the plugin's pass reads scene depth
    // Textures cross the boundary typed: name, format and size.
    EXPECT_NE(ref.name, 0u);
    EXPECT_EQ(ref.format, fx::TargetFormat::RGBA8);
    EXPECT_EQ(ref.width, 48);
    EXPECT_EQ(ref.height, 17);
}
