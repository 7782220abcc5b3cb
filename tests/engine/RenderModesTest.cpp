// The plugin's techniques and optimizations inside the real engine frame (issue: soft-particle
// renderer): prepass-EQUAL must not change a pixel; quarter-res must stay close to full res and
// its depth-aware upsample must beat plain bilinear next to depth edges; passes and targets
// exist only when needed.
#include <gtest/gtest.h>

#include "PassChecks.h"

#include <algorithm>
#include <cmath>

#include "GameTestUtil.h"
#include "gl/Gl.h"

using namespace cube;

namespace {

// The standard frame: 1.5 s into the burnout, chase camera, no HUD, no mirror.
Options standard(int w = 320, int h = 256) {
    Options o = cubetest::smallOptions(w, h);
    o.startTime = 4.5;
    o.mirror = false;
    return o;
}

// Renders the same simulated frame in several configurations of one game.
struct Frames {
    Game game;
    explicit Frames(const Options& o, int warm = 90) {
        std::string err;
        ok = game.Init(o, &err);
        EXPECT_TRUE(ok) << err;
        for (int i = 0; ok && i < warm; ++i) game.Update(1.0f / 60.0f);
    }
    ImageRGBA8 render(bool equal, fx::Technique t, bool quarter, bool bilinear = false) {
        game.options().prepassEqual = equal;
        fx::RenderOptions ro = game.specialFX().plugin()->renderOptions();
        ro.techniqueOverride = t;
        ro.quarterRes = quarter;
        ro.quarterResAlways = quarter;
        ro.bilinearUpsample = bilinear;
        game.specialFX().plugin()->setRenderOptions(ro);
        game.captureNextFrame();
        game.RenderFrame();
        return game.lastFrame();
    }
    bool ok = false;
};

double rmse(const ImageRGBA8& a, const ImageRGBA8& b, const std::vector<uint8_t>* mask = nullptr) {
    double se = 0.0;
    size_t n = 0;
    for (size_t p = 0; p < a.pixels.size() / 4; ++p) {
        if (mask && !(*mask)[p]) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels[p * 4 + c]) - double(b.pixels[p * 4 + c]);
            se += d * d;
            ++n;
        }
    }
    return n ? std::sqrt(se / double(n)) : 0.0;
}

}  // namespace

TEST(RenderModes, PrepassEqualIsPixelIdenticalToLess) {
    // Full size: silhouette and coplanar-seam pixels are where a depth-test mismatch shows
    // (an earlier LESS-vs-EQUAL tie rule differed on 1-5 pixels per frame at 1280x1024 only).
    Frames f(standard(1280, 1024));
    ASSERT_TRUE(f.ok);
    for (int frame = 0; frame < 3; ++frame) {
        for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical}) {
            const ImageRGBA8 less = f.render(false, t, false);
            const ImageRGBA8 equal = f.render(true, t, false);
            ASSERT_FALSE(less.pixels.empty());
            size_t differing = 0;
            for (size_t i = 0; i < less.pixels.size(); ++i) differing += less.pixels[i] != equal.pixels[i];
            EXPECT_EQ(differing, 0u) << "frame " << frame << ", technique " << int(t) << ": EQUAL differs from LESS";
            EXPECT_TRUE(passKept(f.game.graph(), "chase.depth_prepass"));
        }
        for (int i = 0; i < 20; ++i) f.game.Update(1.0f / 60.0f);
    }
    // With quarter-res too.
    EXPECT_TRUE(f.render(false, fx::Technique::Soft, true).pixels == f.render(true, fx::Technique::Soft, true).pixels);
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

TEST(RenderModes, PrepassEqualIsPixelIdenticalWithOverdrawPanels) {
    Options o = standard();
    Frames f(o);
    ASSERT_TRUE(f.ok);
    // Six costly panels on the camera, back to front (as fxbench's overdraw scenario).
    CameraQuads quads;
    quads.cost = 4;
    for (int i = 0; i < 6; ++i) {
        CameraQuad q;
        q.distance = 40.0f - 4.0f * float(i);
        q.centerY = 0.3f;
        q.halfWidth = 0.95f;
        q.halfHeight = 0.7f;
        quads.quads.push_back(q);
    }
    const ImageRGBA8 bare = f.render(false, fx::Technique::Soft, false);
    f.game.setCameraQuads(quads);
    EXPECT_FALSE(f.render(false, fx::Technique::Soft, false).pixels == bare.pixels);  // the panels are drawn
    EXPECT_TRUE(f.render(false, fx::Technique::Soft, false).pixels == f.render(true, fx::Technique::Soft, false).pixels);
}

TEST(RenderModes, QuarterResStaysCloseAndDepthAwareBeatsBilinearAtEdges) {
    Options o = standard(640, 512);
    Frames f(o);
    ASSERT_TRUE(f.ok);
    const ImageRGBA8 full = f.render(false, fx::Technique::Soft, false);
    const ImageRGBA8 aware = f.render(false, fx::Technique::Soft, true, false);
    const ImageRGBA8 bilinear = f.render(false, fx::Technique::Soft, true, true);
    const double psnrAware = cubetest::psnr(full, aware);
    EXPECT_GE(psnrAware, 35.0) << "quarter-res (depth-aware) vs full res";
    const int w = full.width, h = full.height;
    // Pixels next to depth edges where smoke is involved: where the scene depth of the frame
    // bends or jumps (silhouettes of the car, wheels, barrier top, ...: the second difference of
    // inverse depth, flat on any plane, above 10 % of it, as fxbench's depth-edge mask), one
    // pixel either side, where the full-res frame shows smoke (it differs from the bare frame).
    // Colour edges at one depth (glass on the cabin, a rim in its tyre) are not depth edges:
    // there both upsamplers see one surface.
    f.game.options().effects = false;
    f.game.captureNextFrame();
    f.game.captureNextSceneDepth();
    f.game.RenderFrame();
    const ImageRGBA8 bare = f.game.lastFrame();
    const std::vector<float> depth = f.game.lastSceneDepth();  // rows top-down, as the frame
    f.game.options().effects = true;
    ASSERT_EQ(depth.size(), size_t(w) * size_t(h));
    std::vector<float> inv(depth.size());
    for (size_t i = 0; i < inv.size(); ++i) inv[i] = depth[i] > 1e-6f ? 1.0f / depth[i] : 1e6f;
    auto bent = [&](size_t prev, size_t i, size_t next) {
        return std::abs(inv[prev] - 2.0f * inv[i] + inv[next]) > 0.10f * inv[i];
    };
    std::vector<uint8_t> depthEdge(depth.size(), 0), edge(depth.size(), 0);
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (bent(i - 1, i, i + 1) || bent(i - size_t(w), i, i + size_t(w))) depthEdge[i] = 1;
        }
    int edges = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            bool near = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) near = near || depthEdge[size_t(y + dy) * size_t(w) + size_t(x + dx)];
            const auto s = cubetest::pixel(full, x, y), b = cubetest::pixel(bare, x, y);
            const bool smoke = std::abs(s.r - b.r) + std::abs(s.g - b.g) + std::abs(s.b - b.b) > 12;
            if (near && smoke) {
                edge[size_t(y) * size_t(w) + size_t(x)] = 1;
                ++edges;
            }
        }
    ASSERT_GT(edges, 50) << "the standard frame has smoke passing geometry silhouettes";
    const double eAware = rmse(full, aware, &edge), eBilinear = rmse(full, bilinear, &edge);
    RecordProperty("psnr_quarter_depth_aware_db", std::to_string(psnrAware));
    RecordProperty("edge_rmse_depth_aware", std::to_string(eAware));
    RecordProperty("edge_rmse_bilinear", std::to_string(eBilinear));
    std::printf("quarter-res: PSNR %.2f dB (depth-aware) / %.2f dB (bilinear); edge RMSE %.2f vs %.2f over %d px\n",
                psnrAware, cubetest::psnr(full, bilinear), eAware, eBilinear, edges);
    EXPECT_LT(eAware, eBilinear);
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

TEST(RenderModes, PassesAndTargetsExistOnlyWhenNeeded) {
    Frames f(standard());
    ASSERT_TRUE(f.ok);
    // The frame declares the prepass and the quarter-res passes only when it needs them, so
    // "no prepass" is passNotRun; the passKept checks of the same names below make a rename fail.
    // Hard particles need no scene depth: no prepass.
    f.render(false, fx::Technique::Hard, false);
    EXPECT_TRUE(passNotRun(f.game.graph(), "chase.depth_prepass"));
    EXPECT_TRUE(passKept(f.game.graph(), "chase.particles"));
    // Soft: the scene depth comes from the opaque pass (a second render target), so no second
    // scene pass; a prepass only with prepass-EQUAL. Quarter-res targets only while it is on.
    f.render(false, fx::Technique::Soft, false);
    EXPECT_TRUE(passNotRun(f.game.graph(), "chase.depth_prepass"));
    EXPECT_TRUE(passKept(f.game.graph(), "chase.particles"));
    f.render(true, fx::Technique::Soft, false);
    EXPECT_TRUE(passKept(f.game.graph(), "chase.depth_prepass"));
    f.render(false, fx::Technique::Soft, false);
    EXPECT_TRUE(passNotRun(f.game.graph(), "chase.particles_quarter"));
    f.render(false, fx::Technique::Soft, true);
    EXPECT_TRUE(passKept(f.game.graph(), "chase.particles_quarter"));
    EXPECT_TRUE(passKept(f.game.graph(), "chase.particles_composite"));
    // No visible particle (camera looking at the empty sky): no particle pass, no prepass.
    cubetest::fixCamera(f.game.options(), {0.0f, 5.0f, -80.0f}, {0.0f, 60.0f, -200.0f});
    f.game.Update(0.0f);
    f.render(false, fx::Technique::Soft, true);
    EXPECT_TRUE(passNotRun(f.game.graph(), "chase.depth_prepass"));
    EXPECT_TRUE(passNotRun(f.game.graph(), "chase.particles_quarter"));
    for (const std::string& n : f.game.graph().report().executed) EXPECT_EQ(n.find("particles"), std::string::npos) << n;
}


// The plugin samples the z-buffer the opaque pass drew (the default) instead of a linear R32F
// target the opaque pass writes as a second render target (--fx-depth linear, API 2.0's
// contract): one target fewer a frame, no second colour output, and the same picture: both
// depth forms give the same linear distances to within the z-buffer's precision (reversed-Z
// float: 6e-8 t, render/DepthMapping.h). A standard 24-bit z-buffer (3e-8 t^2 / near) is not
// offered: the plugin reads the linear target there, the same frame bit for bit.
TEST(RenderModes, ZBufferSampledInPlaceMatchesTheLinearDepthWithOneTargetLess) {
    for (bool reversed : {true, false}) {
        SCOPED_TRACE(reversed ? "reversed-Z, 32-bit float" : "standard, 24-bit");
        Options o = standard();
        o.reversedZ = reversed;
        Frames f(o);
        ASSERT_TRUE(f.ok);
        struct Case {
            fx::Technique technique;
            bool quarter;
        };
        for (const Case& c : {Case{fx::Technique::Soft, false}, Case{fx::Technique::Spherical, false},
                              Case{fx::Technique::Soft, true}, Case{fx::Technique::Mega, false}}) {
            SCOPED_TRACE(std::to_string(int(c.technique)) + (c.quarter ? " quarter" : ""));
            f.game.options().pluginLinearDepth = true;
            const ImageRGBA8 linear = f.render(false, c.technique, c.quarter);
            const int linearTargets = f.game.graph().report().targetsAcquired;
            f.game.options().pluginLinearDepth = false;
            const ImageRGBA8 zbuffer = f.render(false, c.technique, c.quarter);
            const int zbufferTargets = f.game.graph().report().targetsAcquired;
            ASSERT_EQ(linear.pixels.size(), zbuffer.pixels.size());
            int worst = 0;
            size_t differing = 0;
            for (size_t i = 0; i < linear.pixels.size(); ++i) {
                const int d = std::abs(int(linear.pixels[i]) - int(zbuffer.pixels[i]));
                worst = std::max(worst, d);
                differing += d != 0;
            }
            EXPECT_LE(worst, reversed ? 1 : 0) << differing << " channel values differ";
            EXPECT_EQ(zbufferTargets, linearTargets - (reversed ? 1 : 0)) << "no linear scene depth target";
            EXPECT_GT(f.game.specialFX().plugin()->stats().particlesDrawn, 0);
        }
        // Under prepass-EQUAL the prepass runs either way (a z-buffer read or a linear one).
        f.render(true, fx::Technique::Soft, false);
        EXPECT_TRUE(passKept(f.game.graph(), "chase.depth_prepass"));
    }
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}

// Every view of a frame, chase and rear-view mirror, with lit self-shadowed smoke: the default
// frame-graph path and the immediate path (--fx-depth zbuffer) draw the same picture. The engine
// declares each view's smoke shadow map into its frame graph as it declares the view, but runs
// renderView only when the frame executes; the immediate path must not take a map declared for
// another view (or any map of the host's graph, whose targets its own frame cannot read).
TEST(RenderModes, BothDepthPathsDrawTheSameChaseAndMirror) {
    // run.sh's moment (t = 7 s, the burnout), at half its size: smoke in both views, and view
    // sizes whose opacity maps differ (SmokeOpacityMap::sizeFor).
    Options o = standard(640, 512);
    o.mirror = true;
    Frames f(o, 150);
    ASSERT_TRUE(f.ok);
    f.game.options().pluginZBuffer = false;
    const ImageRGBA8 graph = f.render(false, fx::Technique::Soft, false);
    f.game.options().pluginZBuffer = true;
    const ImageRGBA8 immediate = f.render(false, fx::Technique::Soft, false);
    f.game.options().pluginZBuffer = false;
    ASSERT_EQ(graph.pixels.size(), immediate.pixels.size());
    ASSERT_GT(f.game.specialFX().plugin()->stats().particlesDrawn, 0);
    int worst = 0;
    size_t differing = 0;
    for (size_t i = 0; i < graph.pixels.size(); ++i) {
        const int d = std::abs(int(graph.pixels[i]) - int(immediate.pixels[i]));
        worst = std::max(worst, d);
        differing += d > 1;
    }
    EXPECT_LE(worst, 1) << differing << " channel values differ by more than 1/255";
    EXPECT_EQ(gl::errorCount(), 0) << gl::lastError();
}
