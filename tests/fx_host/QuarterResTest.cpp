// Quarter-res particles against the full-res frame: image error of the whole frame, and of the
// pixels next to depth edges for the depth-aware and the plain bilinear upsample.
#include <cmath>
#include <cstdio>

#include "FxTestHost.h"

namespace fxtest {
// Named so that the test files of one unity translation unit keep their helpers apart.
namespace quarter_res_test {

constexpr int kW = 256, kH = 192;

class QuarterResTest : public FxHostTest {};

// The end-to-end burnout frame (the repo's reactions, 1.5 s of wheelspin) at full and at quarter
// res: PSNR over the whole frame >= 35 dB.
TEST_F(QuarterResTest, BurnoutFrameMatchesFullResAbove35dB) {
    TestHostAdapter host;
    fx::PluginImports imports;
    imports.host = &host;
    std::unique_ptr<fx::Plugin> plugin = fxCreatePlugin(imports);
    ASSERT_TRUE(plugin);
    ASSERT_TRUE(plugin->loadReactions(CUBE_SOURCE_DIR "/reactions", nullptr));
    host.setRearSlip(1.0f);
    for (int s = 0; s < 90; ++s) {
        for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, nullptr);
    }
    TestScene scene;
    scene.quads = {TestScene::ground(60.0f, glm::vec3(0.18f, 0.18f, 0.2f)),
                   TestScene::wallZ(-8.0f, -30.0f, 30.0f, 0.0f, 4.0f, glm::vec3(0.45f, 0.3f, 0.25f))};
    const fx::ViewInfo view = makeView(glm::vec3(5.0f, 2.2f, 7.5f), glm::vec3(0.0f, 0.9f, 1.0f), kW, kH);
    TestFrameGraph graph(kW, kH);
    auto frame = [&](bool quarter, bool bilinear) {
        fx::RenderOptions o;
        o.quarterRes = quarter;
        o.quarterResAlways = quarter;
        o.bilinearUpsample = bilinear;
        plugin->setRenderOptions(o);
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { plugin->declarePasses(view, f); });
        return graph.readColor();
    };
    const Image full = frame(false, false);
    const Image quarter = frame(true, false);
    const Image bilinear = frame(true, true);
    ASSERT_GT(plugin->stats().particlesDrawn, 50);
    writePng("/tmp/fx_host_burnout_full.png", full);
    writePng("/tmp/fx_host_burnout_quarter.png", quarter);
    const double db = psnr(full, quarter);
    std::printf("[ measured ] burnout frame PSNR quarter (depth-aware) %.1f dB, quarter (bilinear) %.1f dB\n",
                db, psnr(full, bilinear));
    EXPECT_GE(db, 35.0);
}

// Bright smoke behind a wall whose top edge crosses it, and a thin pole in front: on the pixels
// within 2 px of a depth edge the depth-aware upsample is closer to full res than bilinear.
TEST_F(QuarterResTest, DepthAwareUpsampleBeatsBilinearNextToDepthEdges) {
    TestHostAdapter host;
    DirectParticles direct(&host);
    EdgeScene edge = wallAndPoleScene(kW, kH, false);
    direct.desc.render.softness = edge.softness;
    direct.set(edge.puffs);
    TestScene& scene = edge.scene;
    const fx::ViewInfo& view = edge.view;
    TestFrameGraph graph(kW, kH);
    auto frame = [&](bool quarter, bool bilinear) {
        direct.settings.options.quarterRes = quarter;
        direct.settings.options.quarterResAlways = quarter;
        direct.settings.options.bilinearUpsample = bilinear;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { direct.declare(view, f); });
        return graph.readColor();
    };
    const Image full = frame(false, false);
    const std::vector<float> depth = graph.readLinearDepth();
    const Image aware = frame(true, false);
    const Image bilinear = frame(true, true);
    ASSERT_TRUE(graph.ran("particles_composite"));

    const std::vector<uint8_t> edges = depthEdgeMask(depth, kW, kH, 2);
    std::vector<uint8_t> rest(edges.size());
    for (size_t i = 0; i < edges.size(); ++i) rest[i] = !edges[i];
    const MaskError eAware = maskedError(aware, full, edges);
    const MaskError eBilinear = maskedError(bilinear, full, edges);
    const MaskError rAware = maskedError(aware, full, rest);
    const MaskError rBilinear = maskedError(bilinear, full, rest);
    std::printf("[ measured ] %d edge px: depth-aware mean %.2f max %d, bilinear mean %.2f max %d (1/255)\n",
                eAware.pixels, eAware.mean, eAware.max, eBilinear.mean, eBilinear.max);
    std::printf("[ measured ] %d other px: depth-aware mean %.2f max %d, bilinear mean %.2f max %d (1/255)\n",
                rAware.pixels, rAware.mean, rAware.max, rBilinear.mean, rBilinear.max);
    std::printf("[ measured ] wall frame PSNR: depth-aware %.1f dB, bilinear %.1f dB\n",
                psnr(full, aware), psnr(full, bilinear));
    writePng("/tmp/fx_host_edge_full.png", full);
    writePng("/tmp/fx_host_edge_quarter_depth_aware.png", aware);
    writePng("/tmp/fx_host_edge_quarter_bilinear.png", bilinear);
    writePng("/tmp/fx_host_edge_diff_depth_aware_x4.png", amplifiedDiff(aware, full, 4));
    writePng("/tmp/fx_host_edge_diff_bilinear_x4.png", amplifiedDiff(bilinear, full, 4));

    ASSERT_GT(eAware.pixels, 500) << "the scene should have long depth edges";
    EXPECT_LT(eAware.mean, 0.6 * eBilinear.mean);
    EXPECT_LT(eAware.max, eBilinear.max);
}

}  // namespace quarter_res_test
}  // namespace fxtest
