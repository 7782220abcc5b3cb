// Lit smoke is stable (seed 000 section 3.3.8 reports its lit smoke flickering and
// popping): the shipped reactions through the plugin's entry point, lit by a scene light.
//   - still camera, paused simulation: two frames are byte-identical;
//   - simulation running at 60 Hz: the frame-to-frame change of smoke pixels with light is at
//     most 1.5 times the change without it (light adds no flicker of its own; the change that
//     remains is the smoke moving);
//   - the camera flying through the cloud: no step changes the picture by more than 4 times the
//     median step (no pop when particles pass the near plane or the light's box changes).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "FxTestHost.h"

namespace fxtest {
// Named so that the test files of one unity translation unit keep their helpers apart.
namespace light_stability_test {

constexpr int kWidth = 200, kHeight = 150;

class LightStabilityTest : public LoadedPluginTest {
protected:
    LightStabilityTest() : LoadedPluginTest(kWidth, kHeight, {CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml"}) {
        light.toSun = glm::vec3(-0.6f, 0.5f, -0.6f);  // low, behind and left of the smoke
    }
    void step(int steps) { simulate(1.0f, steps); }
    // Mean |a - b| (0..255, RGB) over the pixels where either differs from `bare`.
    static double smokeChange(const Image& a, const Image& b, const Image& bare) {
        double sum = 0.0;
        long n = 0;
        for (size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
            bool smoke = false;
            for (int c = 0; c < 3; ++c) smoke |= a.rgba[i + c] != bare.rgba[i + c] || b.rgba[i + c] != bare.rgba[i + c];
            if (!smoke) continue;
            for (int c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
            n += 3;
        }
        return n ? sum / double(n) : 0.0;
    }

    // Mean |a - b| over every pixel (0..255, RGB).
    static double meanChange(const Image& a, const Image& b) {
        double sum = 0.0;
        for (size_t i = 0; i < a.rgba.size(); ++i) {
            if (i % 4 != 3) sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
        }
        return sum / (double(a.rgba.size()) * 0.75);
    }

    fx::SceneLight light;
};

TEST_F(LightStabilityTest, AStillPausedFrameRepeatsExactly) {
    step(60);
    ASSERT_EQ(plugin->setSceneLight(light), fx::ErrorCode::None);
    const Image a = render();
    const Image b = render();
    EXPECT_TRUE(graph.ran("smoke_opacity"));
    EXPECT_EQ(maxAbsDiff(a, b), 0);
}

TEST_F(LightStabilityTest, LightAddsNoFlickerWhileTheSmokeMoves) {
    step(60);
    renderFrame(graph, scene, view, [](fx::FrameBuilder&) {});
    const Image bare = graph.readColor();
    // The same 20 simulated frames, each rendered unlit and lit.
    std::vector<double> unlit, lit;
    Image prevUnlit, prevLit;
    for (int f = 0; f < 20; ++f) {
        step(1);
        plugin->clearSceneLight();
        const Image u = render();
        ASSERT_EQ(plugin->setSceneLight(light), fx::ErrorCode::None);
        const Image l = render();
        if (f > 0) {
            unlit.push_back(smokeChange(u, prevUnlit, bare));
            lit.push_back(smokeChange(l, prevLit, bare));
        }
        prevUnlit = u;
        prevLit = l;
    }
    std::sort(unlit.begin(), unlit.end());
    std::sort(lit.begin(), lit.end());
    const double unlitMedian = unlit[unlit.size() / 2], litMedian = lit[lit.size() / 2];
    std::printf("[ measured ] frame-to-frame change of smoke pixels (0..255): unlit median %.2f max %.2f, "
                "lit median %.2f max %.2f\n", unlitMedian, unlit.back(), litMedian, lit.back());
    ASSERT_GT(unlitMedian, 0.0) << "the smoke must move, or the test proves nothing";
    EXPECT_LE(litMedian, 1.5 * unlitMedian + 0.5);
    EXPECT_LE(lit.back(), 1.5 * unlit.back() + 0.5);
}

TEST_F(LightStabilityTest, FlyingThroughTheCloudHasNoJump) {
    step(90);
    // From 7.5 m in front of the wheels to 0 m, 0.15 m per frame, paused: each position lit
    // and unlit. Passing dense smoke close by changes the picture a lot from step to step
    // anyway; what light must not add is a pop: a step much larger than both its neighbours,
    // or a largest step beyond the unlit one's.
    std::vector<double> lit, unlit;
    Image prevLit, prevUnlit;
    for (int f = 0; f <= 50; ++f) {
        const float z = 7.5f - 0.15f * float(f);
        view = makeView(glm::vec3(0.5f, 1.2f, z), glm::vec3(0.5f, 1.0f, z - 5.0f), kWidth, kHeight);
        plugin->clearSceneLight();
        const Image u = render();
        ASSERT_EQ(plugin->setSceneLight(light), fx::ErrorCode::None);
        const Image l = render();
        if (f > 0) {
            lit.push_back(meanChange(l, prevLit));
            unlit.push_back(meanChange(u, prevUnlit));
        }
        prevLit = l;
        prevUnlit = u;
    }
    const double litMax = *std::max_element(lit.begin(), lit.end());
    const double unlitMax = *std::max_element(unlit.begin(), unlit.end());
    std::printf("[ measured ] fly-through, largest picture change per 0.15 m step (0..255): lit %.2f, unlit %.2f\n",
                litMax, unlitMax);
    ASSERT_GT(unlitMax, 0.0);
    EXPECT_LE(litMax, 1.25 * unlitMax);
    for (size_t i = 1; i + 1 < lit.size(); ++i) {
        EXPECT_LE(lit[i], 2.5 * std::max(lit[i - 1], lit[i + 1]) + 1.0) << "a pop at step " << i;
    }
}

}  // namespace light_stability_test
}  // namespace fxtest
