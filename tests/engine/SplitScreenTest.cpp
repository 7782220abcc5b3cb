// cube_game --split: two chase cameras side by side in one framebuffer, each with its own smoke,
// through the plugin's frame-graph path (the z-buffer sampled in place, and the linear depth) and
// its immediate path (renderView on the bound framebuffer's depth). Each half equals the same
// camera drawn alone over a window of the half's size (--split-alone), the same simulated frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "GameTestUtil.h"

using namespace cube;

namespace {

constexpr int kW = 320, kH = 200;  // halves of 160 x 200
/// Largest |difference| (1/255 per channel) between a half and the view drawn alone. Measured
/// (llvmpipe, 320 x 200): the left half bit for bit on all three paths; the right half, drawn
/// 160 px further right, 1/255 on 1-3 of 32000 pixels, where llvmpipe's rasteriser rounds
/// interpolated values differently (tests/fx_host/ViewportTest.cpp measures the same with no
/// scene depth at all).
constexpr int kTolerance = 1;

Options options(int w, bool split, int alone) {
    Options o = cubetest::smallOptions(w, kH);
    o.startTime = 4.5;
    o.mirror = false;
    o.split = split;
    o.splitAlone = alone;
    return o;
}

struct Frames {
    Game game;
    bool ok = false;
    explicit Frames(const Options& o) {
        std::string err;
        ok = game.Init(o, &err);
        EXPECT_TRUE(ok) << err;
        for (int i = 0; ok && i < 90; ++i) game.Update(1.0f / 60.0f);
    }
    ImageRGBA8 render(int alone, fx::Technique t, bool quarter, bool zbuffer, bool linear, bool tiled = false) {
        game.options().splitAlone = alone;
        game.options().pluginZBuffer = zbuffer;
        game.options().pluginLinearDepth = linear;
        fx::RenderOptions ro = game.specialFX().plugin()->renderOptions();
        ro.techniqueOverride = t;
        ro.quarterRes = quarter;
        ro.quarterResAlways = quarter;
        ro.tiling = tiled ? fx::Tiling::On : fx::Tiling::Auto;
        game.specialFX().plugin()->setRenderOptions(ro);
        game.specialFX().plugin()->prepareGl(nullptr);
        game.captureNextFrame();
        game.RenderFrame();
        return game.lastFrame();
    }
};

// Max |difference| over RGB between columns [x0, x0 + w) of `split` and all of `alone`.
int halfDiff(const ImageRGBA8& split, int x0, const ImageRGBA8& alone, int* differing) {
    int worst = 0;
    *differing = 0;
    for (int y = 0; y < alone.height; ++y) {
        for (int x = 0; x < alone.width; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) {
                const size_t a = (size_t(y) * size_t(split.width) + size_t(x0 + x)) * 4 + size_t(c);
                const size_t b = (size_t(y) * size_t(alone.width) + size_t(x)) * 4 + size_t(c);
                d = std::max(d, std::abs(int(split.pixels[a]) - int(alone.pixels[b])));
            }
            worst = std::max(worst, d);
            *differing += d > 0;
        }
    }
    return worst;
}

TEST(SplitScreen, EachHalfEqualsItsCameraDrawnAloneThroughEveryDepthPath) {
    Frames split(options(kW, true, 0));
    Frames alone(options(kW / 2, false, 1));
    ASSERT_TRUE(split.ok && alone.ok);
    struct Mode {
        const char* name;
        fx::Technique technique;
        bool quarter;
        bool tiled;
    };
    // Tiled: on llvmpipe the CPU lists and orders a view; the ctest SplitScreen.TiledOnTheGpusWay
    // runs this again with the GPU's lists and order, each view then binned in its own pass
    // (TiledPath::deferBins) on the graph's paths.
    const Mode modes[] = {{"soft", fx::Technique::Soft, false, false},
                          {"spherical", fx::Technique::Spherical, false, false},
                          {"soft quarter", fx::Technique::Soft, true, false},
                          {"mega", fx::Technique::Mega, false, false},
                          {"soft tiled", fx::Technique::Soft, false, true}};
    struct Path {
        const char* name;
        bool zbuffer, linear;
    };
    const Path paths[] = {{"graph (z-buffer in place)", false, false},
                          {"graph (linear depth)", false, true},
                          {"zbuffer (renderView)", true, false}};
    for (const Mode& m : modes) {
        for (const Path& p : paths) {
            SCOPED_TRACE(std::string(m.name) + ", " + p.name);
            const ImageRGBA8 both = split.render(0, m.technique, m.quarter, p.zbuffer, p.linear, m.tiled);
            ASSERT_EQ(both.width, kW);
            for (int half = 0; half < 2; ++half) {
                const ImageRGBA8 ref = alone.render(half + 1, m.technique, m.quarter, p.zbuffer, p.linear, m.tiled);
                ASSERT_EQ(ref.width, kW / 2);
                int differing = 0;
                const int diff = halfDiff(both, half * (kW / 2), ref, &differing);
                EXPECT_LE(diff, kTolerance) << (half ? "right" : "left") << " half";
                EXPECT_LT(differing, ref.width * ref.height / 1000) << "a rounding step on a few pixels, not a region";
                if (half == 0) {
                    EXPECT_EQ(diff, 0) << "the left half is at (0, 0): bit for bit";
                }
                std::printf("[ measured ] %-13s %-26s %s half: max |diff| %d/255, %d of %d pixels differ\n", m.name,
                            p.name, half ? "right" : "left ", diff, differing, ref.width * ref.height);
            }
        }
    }
    // Each half shows smoke of its own: the frame with the plugin's passes differs from the bare one.
    split.game.options().effects = false;
    const ImageRGBA8 bare = split.render(0, fx::Technique::Soft, false, false, false);
    split.game.options().effects = true;
    const ImageRGBA8 smoky = split.render(0, fx::Technique::Soft, false, false, false);
    for (int half = 0; half < 2; ++half) {
        int changed = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = half * (kW / 2); x < (half + 1) * (kW / 2); ++x) {
                const size_t i = (size_t(y) * kW + size_t(x)) * 4;
                changed += bare.pixels[i] != smoky.pixels[i] || bare.pixels[i + 1] != smoky.pixels[i + 1];
            }
        }
        EXPECT_GT(changed, 200) << (half ? "right" : "left") << " half: its smoke";
        std::printf("[ measured ] smoke in the %s half: %d pixels\n", half ? "right" : "left", changed);
    }
}

TEST(SplitScreen, OptionsRefuseWhatCannotShareOneFramebuffer) {
    Options o = options(kW, true, 0);
    o.prepassEqual = true;
    std::string error;
    EXPECT_FALSE(checkOptions(o, &error));
    EXPECT_NE(error.find("--prepass-equal"), std::string::npos) << error;
    o.prepassEqual = false;
    o.splitAlone = 1;
    EXPECT_FALSE(checkOptions(o, &error));
    o.splitAlone = 0;
    EXPECT_TRUE(checkOptions(o, &error)) << error;
}

}  // namespace
