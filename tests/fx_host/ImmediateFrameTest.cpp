// The immediate path's frame (fx_plugin/render/ImmediateFrame.h) on its own: culling, allocation
// only for running passes, the depth hook before its first reader; and the timing of the two
// depth sources, run only on request.
#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "FxTestHost.h"
#include "../../fx_plugin/src/PluginImpl.h"
#include "../../fx_plugin/render/ImmediateFrame.h"
#include "../../fx_plugin/render/ImmediateRenderer.h"
#include "../../fx_plugin/render/SceneDepthSource.h"

namespace fxtest {
namespace immediate_frame {  // named: the fx_host tests build as unity batches

using Source = fx::ImmediateView::DepthSource;

// The frame graph's rules on their own: culling, allocation only for running passes, the depth
// hook before the first reader only.
TEST_F(FxHostTest, ImmediateFrameCullsUnreadPassesAndProducesDepthBeforeItsFirstReader) {
    fx::ImmediateTargetPool pool;
    pool.beginFrame();
    int produced = 0;
    std::vector<std::string> order;
    fx::ImmediateFrameSetup setup;
    setup.width = 64;
    setup.height = 32;
    setup.produceDepth = [&](uint32_t, const fx::DepthRegion&) {
        ++produced;
        order.push_back("depth");
    };
    fx::ImmediateFrame frame(pool, setup);
    fx::TargetDesc half;
    half.scale = 0.5f;
    const fx::Target unread = frame.createTarget("unread", half);
    const fx::Target used = frame.createTarget("used", half);
    auto record = [&](const char* n) { return [&order, n](fx::PassContext&) { order.push_back(n); }; };
    frame.addPass("culled", {frame.sceneDepth()}, {unread}, record("culled"));
    frame.addPass("first", {}, {used}, record("first"));
    frame.addPass("reader", {frame.sceneDepth(), used}, {frame.sceneColor()}, record("reader"));
    frame.addPass("second_reader", {frame.sceneDepth()}, {frame.sceneColor()}, record("second_reader"));
    frame.execute();
    EXPECT_EQ(order, (std::vector<std::string>{"first", "depth", "reader", "second_reader"}));
    EXPECT_EQ(produced, 1);
    EXPECT_EQ(pool.allocatedNow(), 2) << "the linear depth and `used` (32 x 16); `unread` never";
    const fx::PooledTarget& usedSlot = pool.at(pool.at(0).desc.format == fx::TargetFormat::R32F ? 1 : 0);
    EXPECT_EQ(usedSlot.width, 32);
    EXPECT_EQ(usedSlot.height, 16);
    EXPECT_EQ(usedSlot.desc.format, fx::TargetFormat::RGBA8);
    pool.endFrame();
    pool.release();
}

// Timing (not a test: run with --gtest_also_run_disabled_tests). One interleaved run on the fx_host
// wall scene at 640 x 480: the host's frame (its opaque pass; with LinearR32F also its linear-depth
// prepass, as fx_host's graph draws it) plus the plugin's passes, CPU clock around glFinish.
TEST_F(FxHostTest, DISABLED_ImmediateDepthSourceTiming) {
    constexpr int W = 640, H = 480, kRounds = 61;
    TestHostAdapter host;
    fx::PluginImports imports;
    imports.host = &host;
    auto plugin = fxCreatePlugin(imports);
    ASSERT_TRUE(plugin && plugin->loadReactions(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml", nullptr));
    host.setRearSlip(1.0f);
    for (int s = 0; s < 60; ++s) {
        for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, nullptr);
    }
    fx::RenderOptions o;
    o.techniqueOverride = fx::Technique::Soft;
    plugin->setRenderOptions(o);
    TestScene scene;
    scene.quads = {TestScene::ground(40.0f, glm::vec3(0.2f)),
                   TestScene::wallZ(-5.0f, -20.0f, 20.0f, 0.0f, 3.0f, glm::vec3(0.4f, 0.3f, 0.3f))};
    const fx::ViewInfo view = makeView(glm::vec3(4.0f, 2.0f, 7.0f), glm::vec3(0.0f, 0.8f, 1.0f), W, H);
    TestFrameGraph graph(W, H);  // its prepass makes the host's linear depth for the R32F case
    fx::ProgramCache programs(fx::snapshotShaderReader(fx::shaderReader("")));
    fx::ImmediateRenderer immediate(&host, programs);
    HostTarget hostFb(W, H, GL_DEPTH_COMPONENT24);
    auto seconds = [] { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); };
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    std::vector<double> frameLinear, frameTexture, pluginLinear, pluginTexture;
    for (int round = 0; round < kRounds + 1; ++round) {
        for (int variant = 0; variant < 2; ++variant) {
            glFinish();
            const double t0 = seconds();
            fx::ImmediateView iv;
            iv.view = view;
            if (variant == 0) {
                // The host's linear depth: fx_host's prepass (linear depth + z), then its opaque pass.
                renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
                    f.addPass("reads_depth", {f.sceneDepth()}, {f.sceneColor()}, [](fx::PassContext&) {});
                });
                GLint name = 0;
                glBindFramebuffer(GL_READ_FRAMEBUFFER, graph.depthFramebuffer());
                glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                                      GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
                iv.depthSource = Source::LinearR32F;
                iv.depthTexture = GLuint(name);
                glBindFramebuffer(GL_FRAMEBUFFER, graph.colorFramebuffer());
                glViewport(0, 0, W, H);
            } else {
                glBindFramebuffer(GL_FRAMEBUFFER, hostFb.fbo);
                scene.drawOpaque(view);
                iv.depthSource = Source::DepthTexture;
                iv.depthTexture = hostFb.depth;
            }
            glFinish();
            const double t1 = seconds();
            ASSERT_EQ(fx::implOf(*plugin).renderImmediate(iv, &immediate), fx::ErrorCode::None);
            glFinish();
            const double t2 = seconds();
            if (round == 0) continue;  // warm-up (programs, targets)
            (variant == 0 ? frameLinear : frameTexture).push_back(t2 - t0);
            (variant == 0 ? pluginLinear : pluginTexture).push_back(t2 - t1);
        }
    }
    // The linearise pass alone (DepthLinearizer, full view, into an R32F target), for the breakdown.
    std::vector<double> passAlone;
    {
        HostTarget linear(W, H, 0);
        GLuint r32f = 0;
        glGenTextures(1, &r32f);
        glBindTexture(GL_TEXTURE_2D, r32f);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, W, H, 0, GL_RED, GL_FLOAT, nullptr);
        glBindFramebuffer(GL_FRAMEBUFFER, linear.fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, r32f, 0);
        fx::ProgramCache programs(fx::snapshotShaderReader(fx::shaderReader("")));
        buildLinearizeProgram(&programs);
        fx::DepthLinearizer depth;
        ASSERT_TRUE(depth.bind(programs));
        for (int round = 0; round < kRounds; ++round) {
            glFinish();
            const double t0 = seconds();
            depth.linearize(hostFb.depth, view.proj, fx::DepthMapping{}, view.farPlane, linear.fbo, W, H);
            glFinish();
            passAlone.push_back(seconds() - t0);
        }
        depth.releaseGl();
        glDeleteTextures(1, &r32f);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::printf("  linearise pass alone %.2f ms\n", 1e3 * median(passAlone));
    // The median of each round's ratio too: the two variants of a round ran back to back, so a
    // load change on the shared machine between rounds cancels out of it.
    std::vector<double> frameRatio, pluginRatio;
    for (size_t i = 0; i < frameLinear.size(); ++i) {
        frameRatio.push_back(frameTexture[i] / frameLinear[i]);
        pluginRatio.push_back(pluginTexture[i] / pluginLinear[i]);
    }
    std::printf("  %d x %d, %d rounds, medians: frame linear R32F %.2f ms, depth texture %.2f ms (%.3fx, per-round "
                "ratio %.3fx); plugin alone %.2f ms vs %.2f ms (%.3fx, per-round %.3fx)\n",
                W, H, kRounds, 1e3 * median(frameLinear), 1e3 * median(frameTexture),
                median(frameTexture) / median(frameLinear), median(frameRatio), 1e3 * median(pluginLinear),
                1e3 * median(pluginTexture), median(pluginTexture) / median(pluginLinear), median(pluginRatio));
}

}  // namespace immediate_frame
}  // namespace fxtest
