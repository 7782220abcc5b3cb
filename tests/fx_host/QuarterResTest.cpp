// Quarter-res particles against the full-res frame: image error of the whole frame, and of the
// pixels next to depth edges for the depth-aware and the plain bilinear upsample.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "FxTestHost.h"
#include "render/QuarterResPath.h"

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

// The composite against the rule it implements, worked out here from what it read: the half-res
// colour and depth as the quarter pass left them, the scene before it and the full-res depth.
// Per pixel: no smoke in the bilinear footprint leaves it as it was; all four taps within the
// threshold blend bilinearly; on an edge only the taps within it, renormalised, or else the
// nearest-depth one. The shader gets its weights from the sampler's bilinear filter (llvmpipe
// filters 8-bit texels in 8-bit steps), so a channel may differ by 2/255; the rule's branches
// (edge, nearest, no smoke) must each be met by this frame.
TEST_F(QuarterResTest, CompositeFollowsTheDepthAwareRulePixelByPixel) {
    TestHostAdapter host;
    DirectParticles direct(&host);
    EdgeScene edge = wallAndPoleScene(kW, kH, false);
    // A fence of thin bars behind the smoke, against the sky: in the gaps between bars about two
    // pixels apart every tap of a footprint holds a bar's depth (the half-res depth keeps the
    // nearest), none the sky's, the nearest-depth case.
    for (int i = 0; i < 16; ++i) {
        const float x = -3.0f + 0.12f * float(i) + 0.003f * float(i % 5);
        edge.scene.quads.push_back(TestScene::wallZ(-1.5f, x, x + 0.05f, 0.0f, 3.0f, glm::vec3(0.2f, 0.2f, 0.3f)));
    }
    direct.desc.render.softness = edge.softness;
    direct.set(edge.puffs);
    TestFrameGraph graph(kW, kH);
    direct.settings.options.quarterRes = true;
    direct.settings.options.quarterResAlways = true;
    Image before;
    std::vector<float> halfColor, halfDepth;
    int hw = 0, hh = 0, dw = 0, dh = 0;
    graph.afterPluginPass = [&](const std::string& pass) {
        if (pass != "particles_quarter") return;
        before = graph.readColor();
        halfColor = graph.readTarget(fx::QuarterResPath::kColorTarget, &hw, &hh);
        halfDepth = graph.readTarget(fx::QuarterResPath::kDepthTarget, &dw, &dh);
    };
    renderFrame(graph, edge.scene, edge.view, [&](fx::FrameBuilder& f) { direct.declare(edge.view, f); });
    graph.afterPluginPass = nullptr;
    ASSERT_TRUE(graph.ran("particles_composite"));
    ASSERT_FALSE(halfColor.empty());
    ASSERT_FALSE(halfDepth.empty());
    ASSERT_EQ(hw, dw);
    ASSERT_EQ(hh, dh);
    const Image after = graph.readColor();
    const std::vector<float> depth = graph.readLinearDepth();

    auto clampi = [](int v, int hi) { return std::min(std::max(v, 0), hi); };
    int worst = 0, edgePixels = 0, nearestPixels = 0, smokeFree = 0, smoky = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float lx = (float(x) + 0.5f) * float(hw) / float(kW) - 0.5f;
            const float ly = (float(y) + 0.5f) * float(hh) / float(kH) - 0.5f;
            const int bx = int(std::floor(lx)), by = int(std::floor(ly));
            const float fx = lx - float(bx), fy = ly - float(by);
            const std::array<int, 4> tx = {clampi(bx, hw - 1), clampi(bx + 1, hw - 1), clampi(bx, hw - 1),
                                           clampi(bx + 1, hw - 1)};
            const std::array<int, 4> ty = {clampi(by, hh - 1), clampi(by, hh - 1), clampi(by + 1, hh - 1),
                                           clampi(by + 1, hh - 1)};
            const std::array<float, 4> w = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
            std::array<std::array<float, 4>, 4> c{};
            std::array<float, 4> diff{};
            float sum = 0.0f;
            float full = depth[size_t(y) * kW + size_t(x)];
            if (!(full > 0.0f && full < 3.0e38f)) full = 3.0e38f;
            for (int i = 0; i < 4; ++i) {
                const size_t t = size_t(ty[size_t(i)]) * size_t(hw) + size_t(tx[size_t(i)]);
                for (int k = 0; k < 4; ++k) {
                    c[size_t(i)][size_t(k)] = halfColor[t * 4 + size_t(k)];
                    sum += c[size_t(i)][size_t(k)];
                }
                diff[size_t(i)] = std::fabs(halfDepth[t * 4] - full);
            }
            std::array<float, 4> out{};
            bool blended = sum > 0.0f;
            if (blended) {
                ++smoky;
                std::array<float, 4> kept{};
                float keptSum = 0.0f;
                for (int i = 0; i < 4; ++i) {
                    const bool inside = diff[size_t(i)] <= fx::QuarterResPath::kDepthThreshold * full;
                    kept[size_t(i)] = inside ? w[size_t(i)] : 0.0f;
                    keptSum += kept[size_t(i)];
                }
                if (keptSum < 0.999f) ++edgePixels;
                if (keptSum <= 1e-3f) {
                    ++nearestPixels;
                    const size_t first = size_t(std::min_element(diff.begin(), diff.end()) - diff.begin());
                    kept = {0.0f, 0.0f, 0.0f, 0.0f};
                    kept[first] = 1.0f;
                    keptSum = 1.0f;
                }
                for (int i = 0; i < 4; ++i) {
                    for (int k = 0; k < 4; ++k) out[size_t(k)] += kept[size_t(i)] * c[size_t(i)][size_t(k)] / keptSum;
                }
            } else {
                ++smokeFree;
            }
            for (int k = 0; k < 4; ++k) {
                const float dst = before.value(x, y, k);
                const float expected = blended ? out[size_t(k)] + dst * (1.0f - out[3]) : dst;
                const int e = int(std::lround(std::min(std::max(expected, 0.0f), 1.0f) * 255.0f));
                worst = std::max(worst, std::abs(e - int(after.at(x, y)[k])));
            }
        }
    }
    std::printf("[ measured ] composite vs its rule: %d smoky px (%d on an edge, %d nearest), %d smoke-free; "
                "worst channel %d/255\n",
                smoky, edgePixels, nearestPixels, smokeFree, worst);
    EXPECT_GT(edgePixels, 200);
    EXPECT_GT(nearestPixels, 0);
    EXPECT_GT(smokeFree, 1000);
    EXPECT_LE(worst, 2);
}

// The downsample keeps each 2x2 block's nearest (red) and farthest (green) depth, the block of an
// odd view's last row and column clamped to it: equal to the host's linear depth read back, for
// its linear R32F depth (t = d exactly), and within 1e-5 of it for its reversed-Z float z-buffer
// sampled in place (decoded in the shader).
TEST_F(QuarterResTest, DownsampleKeepsEachBlocksNearestAndFarthestDepth) {
    constexpr int kOddW = 255, kOddH = 191;
    for (const bool roundUp : {false, true}) {
    std::vector<float> linearHalf;  // the linear host's downsample, what the z-buffer's is held to
    for (const bool zBuffer : {false, true}) {
        TestHostAdapter host;
        DirectParticles direct(&host);
        EdgeScene edge = wallAndPoleScene(kOddW, kOddH, zBuffer);
        // A puff through the near plane: the tiles are the whole view, every block is written.
        edge.puffs.push_back(HandParticle{glm::vec3(0.0f, 1.4f, 7.7f), 1.0f, 0.5f, 0.0f, 0.05f, 0});
        direct.desc.render.softness = edge.softness;
        direct.set(edge.puffs);
        direct.settings.options.quarterRes = true;
        direct.settings.options.quarterResAlways = true;
        TestFrameGraph graph(kOddW, kOddH, zBuffer, zBuffer);
        graph.roundSizesUp = roundUp;
        std::vector<float> half;
        int hw = 0, hh = 0;
        graph.afterPluginPass = [&](const std::string& pass) {
            if (pass == "particles_depth_downsample") half = graph.readTarget(fx::QuarterResPath::kDepthTarget, &hw, &hh);
        };
        renderFrame(graph, edge.scene, edge.view, [&](fx::FrameBuilder& f) { direct.declare(edge.view, f); });
        graph.afterPluginPass = nullptr;
        ASSERT_FALSE(half.empty());
        EXPECT_EQ(graph.zBufferUsed(), zBuffer);
        // Rounded down, the last column and row are left to the composite's clamped footprint;
        // rounded up, their blocks are one pixel wide.
        ASSERT_EQ(hw, roundUp ? kOddW / 2 + 1 : kOddW / 2);
        ASSERT_EQ(hh, roundUp ? kOddH / 2 + 1 : kOddH / 2);
        // The host's own linear depth of the same scene (its prepass, run by hand when the
        // plugin read the z-buffer instead).
        const std::vector<float> depth = zBuffer ? std::vector<float>() : graph.readLinearDepth();
        if (!zBuffer) linearHalf = half;
        double worst = 0.0;
        int blocks = 0, mixed = 0;
        for (int y = 0; y < hh; ++y) {
            for (int x = 0; x < hw; ++x) {
                const size_t t = (size_t(y) * size_t(hw) + size_t(x)) * 4;
                if (zBuffer) {
                    for (int k = 0; k < 2; ++k) {
                        const float a = half[t + size_t(k)], b = linearHalf[t + size_t(k)];
                        if (b >= 3.0e38f) {
                            EXPECT_GE(a, 3.0e38f) << x << "," << y;
                            continue;
                        }
                        worst = std::max(worst, std::fabs(double(a) - double(b)) / double(b));
                    }
                    ++blocks;
                    continue;
                }
                float lo = 3.0e38f, hi = 0.0f;
                for (int dy = 0; dy < 2; ++dy) {
                    for (int dx = 0; dx < 2; ++dx) {
                        const int px = std::min(2 * x + dx, kOddW - 1), py = std::min(2 * y + dy, kOddH - 1);
                        float d = depth[size_t(py) * kOddW + size_t(px)];
                        if (!(d > 0.0f && d < 3.0e38f)) d = 3.0e38f;
                        lo = std::min(lo, d);
                        hi = std::max(hi, d);
                    }
                }
                ++blocks;
                if (hi > lo * 1.1f) ++mixed;
                ASSERT_EQ(half[t], lo) << "block " << x << "," << y;
                ASSERT_EQ(half[t + 1], hi) << "block " << x << "," << y;
            }
        }
        std::printf("[ measured ] downsample %s, half size rounded %s: %d blocks, %d across a depth edge, "
                    "worst relative error %.2e\n",
                    zBuffer ? "reversed-Z z-buffer vs linear" : "linear R32F", roundUp ? "up" : "down", blocks,
                    mixed, worst);
        if (!zBuffer) {
            EXPECT_GT(mixed, 100);
        }
        EXPECT_LT(worst, 1e-5);
    }
    }
}

}  // namespace quarter_res_test
}  // namespace fxtest
