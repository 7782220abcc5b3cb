// fxbench's pure figures: image error, the depth-edge mask and quantiles.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fxbench_image_error.h"
#include "fxbench_modes.h"
#include "fxbench_stats.h"
#include "fxbench_summary.h"
#include "game/TechniqueModes.h"

namespace {

cube::ImageRGBA8 flat(int w, int h, uint8_t v) {
    cube::ImageRGBA8 img;
    img.width = w;
    img.height = h;
    img.pixels.assign(size_t(w) * size_t(h) * 4, v);
    return img;
}

TEST(FxbenchError, IdenticalImagesGiveZeroErrorAndThePsnrCap) {
    const cube::ImageRGBA8 a = flat(8, 8, 100);
    fxbench::ErrorAccum e;
    e.add(a, a, {});
    EXPECT_EQ(e.rmse(), 0.0);
    EXPECT_EQ(e.maxAbs, 0);
    EXPECT_EQ(e.psnrDb(), fxbench::kPsnrCapDb);
    EXPECT_EQ(e.edgePct(), 0.0);
}

TEST(FxbenchError, OneChannelOffGivesTheExpectedRmsePsnrAndMax) {
    cube::ImageRGBA8 a = flat(10, 10, 0), b = flat(10, 10, 0);
    a.pixels[4 * 7 + 1] = 30;   // pixel 7, green
    a.pixels[4 * 9 + 3] = 255;  // alpha is not compared
    fxbench::ErrorAccum e;
    e.add(a, b, {});
    const double rmse = std::sqrt(30.0 * 30.0 / 300.0);
    EXPECT_NEAR(e.rmse(), rmse, 1e-12);
    EXPECT_NEAR(e.psnrDb(), 20.0 * std::log10(255.0 / rmse), 1e-9);
    EXPECT_EQ(e.maxAbs, 30);
}

TEST(FxbenchError, EdgeShareCountsOnlyMaskedPixelsOverTheThreshold) {
    cube::ImageRGBA8 a = flat(4, 1, 50), b = flat(4, 1, 50);
    a.pixels[0] = 50 + fxbench::kEdgeErrorThreshold + 1;  // pixel 0: over, on an edge
    a.pixels[4] = 50 + fxbench::kEdgeErrorThreshold;      // pixel 1: at the threshold, on an edge
    a.pixels[8] = 200;                                    // pixel 2: over, not on an edge
    fxbench::ErrorAccum e;
    e.add(a, b, {1, 1, 0, 0});
    EXPECT_EQ(e.edgePixels, 2u);
    EXPECT_EQ(e.edgeOver, 1u);
    EXPECT_DOUBLE_EQ(e.edgePct(), 50.0);
}

TEST(FxbenchError, TiltedPlaneHasNoDepthEdgesAndAStepHasThem) {
    const int w = 32, h = 16;
    // A plane at any angle: inverse depth affine in x and y.
    std::vector<float> plane(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) plane[size_t(y * w + x)] = 1.0f / (0.02f + 0.003f * float(x) + 0.01f * float(y));
    std::vector<uint8_t> m = fxbench::depthEdgeMask(plane, w, h);
    EXPECT_EQ(std::count(m.begin(), m.end(), 1), 0);

    // A wall at 5 m over a background at 50 m, meeting at column 16.
    std::vector<float> step(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) step[size_t(y * w + x)] = x < 16 ? 5.0f : 50.0f;
    m = fxbench::depthEdgeMask(step, w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // Columns 15 and 16 bend; dilated by one pixel: 14..17.
            const bool want = x >= 16 - 1 - fxbench::kDepthEdgeRadius && x <= 16 + fxbench::kDepthEdgeRadius;
            EXPECT_EQ(m[size_t(y * w + x)] != 0, want) << x << "," << y;
        }
    }
}

TEST(FxbenchError, CoverageIsEveryPixelWhoseColourChanged) {
    cube::ImageRGBA8 bare = flat(3, 2, 10), frame = flat(3, 2, 10);
    frame.pixels[4 * 2 + 2] = 11;
    frame.pixels[4 * 5 + 0] = 0;
    frame.pixels[4 * 4 + 3] = 0;  // alpha only: not coverage
    std::vector<uint8_t> mask;
    EXPECT_EQ(fxbench::coverageMask(frame, bare, &mask), 2u);
    EXPECT_EQ(mask, (std::vector<uint8_t>{0, 0, 1, 0, 0, 1}));
}

TEST(FxbenchStats, QuantilesInterpolateBetweenRanks) {
    const std::vector<double> v = {5, 1, 4, 2, 3};
    EXPECT_DOUBLE_EQ(fxbench::median(v), 3.0);
    EXPECT_DOUBLE_EQ(fxbench::quantile(v, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(fxbench::quantile(v, 1.0), 5.0);
    EXPECT_DOUBLE_EQ(fxbench::quantile(v, 0.95), 4.8);
    EXPECT_DOUBLE_EQ(fxbench::median({}), 0.0);
    EXPECT_DOUBLE_EQ(fxbench::mean(v), 3.0);
}

}  // namespace

// A mode named after a technique ("soft+quarter", "spherical-lit") draws that technique: the
// word before the first '+' or '-' is a --mode word of game/TechniqueModes.h whose override is
// the mode's technique. A renamed word or a mislabelled row fails here.
TEST(FxbenchModes, ATechniqueNamedModeDrawsThatTechnique) {
    int named = 0;
    for (const fxbench::Mode& m : fxbench::allModes()) {
        if (!m.effects) continue;  // nofx
        const std::string name = m.name;
        const cube::TechniqueMode* mode = cube::findTechniqueMode(name.substr(0, name.find_first_of("+-")));
        ASSERT_NE(mode, nullptr) << name << " does not start with a technique word";
        EXPECT_EQ(mode->technique, m.technique) << name;
        ++named;
    }
    EXPECT_GT(named, 10);
}

// A sweep point within 5 % below its count gets no note; one further below says why: pools too
// small, emission too slow, or particles that died after the pools filled.
TEST(FxbenchSweep, APointShortOfItsCountSaysWhy) {
    auto note = [](double alive, double capacity, double emitted, double dropped) {
        fxbench::Report r;
        r.particlesAlive = alive;
        r.particleCapacity = capacity;
        r.particlesEmitted = emitted;
        r.particlesDropped = dropped;
        fxbench::noteParticlesReached(&r, 1000.0);
        EXPECT_EQ(r.particlesRequested, 1000.0);
        return r.notes.empty() ? std::string() : r.notes.back();
    };
    EXPECT_EQ(note(950.0, 1000.0, 950.0, 0.0), "");
    EXPECT_NE(note(940.0, 1000.0, 940.0, 0.0).find("emission too slow"), std::string::npos);
    EXPECT_NE(note(500.0, 500.0, 2000.0, 1500.0).find("the pools hold 500"), std::string::npos);
    const std::string died = note(300.0, 1000.0, 1200.0, 200.0);
    EXPECT_NE(died.find("reached 300 of 1000"), std::string::npos) << died;
    EXPECT_NE(died.find("died"), std::string::npos) << died;
}
