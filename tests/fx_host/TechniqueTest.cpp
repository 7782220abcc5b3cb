// The three techniques against geometry, with one hand-placed particle drawn by the plugin's
// renderer in the fx_host frame graph: the ground-contact line (soft and spherical have no
// step, hard does), a particle entirely behind a wall (contributes nothing), a camera flying
// through a spherical particle (no frame-to-frame jump), the near fade's line, extreme clip planes
// (the soft fade matches the CPU value at 1 m and at 10 km), and back-to-front order.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "FxTestHost.h"

namespace fxtest {
namespace {

const char* name(fx::Technique t) {
    switch (t) {
    case fx::Technique::Hard: return "hard";
    case fx::Technique::Soft: return "soft";
    case fx::Technique::Spherical: return "spherical";
    case fx::Technique::Mega: return "mega";
    case fx::Technique::FromReaction: break;
    }
    return "from_reaction";
}

class TechniqueTest : public FxHostTest {
protected:
    Image draw(TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view, bool particles) {
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            if (particles) drawn = direct.declare(view, f);
        });
        return graph.readColor();
    }

    TestHostAdapter host;
    DirectParticles direct{&host};
    int drawn = 0;
};

// --- intersection with the ground -------------------------------------------------------------

// Largest step of the green channel between vertically adjacent pixels in a window, in [0, 1].
float maxVerticalStep(const Image& img, int x0, int x1, int y0, int y1) {
    float worst = 0.0f;
    for (int x = x0; x <= x1; ++x) {
        for (int y = y0; y < y1; ++y) {
            worst = std::max(worst, std::fabs(img.value(x, y + 1, 1) - img.value(x, y, 1)));
        }
    }
    return worst;
}

// A 4 m particle centred 0.5 m above a black ground, seen from 4 m up and 6 m back: its
// billboard plane meets the ground along a horizontal line (z = 0.29). On black the pixel value
// is the premultiplied smoke (about 0.9 x alpha). Bound: 0.1 per pixel for soft (softness 1 m)
// and spherical; hard steps by the full smoke value there (> 0.3).
TEST_F(TechniqueTest, GroundContactLineIsSmoothForSoftAndSphericalButNotHard) {
    constexpr int kW = 256, kH = 192;
    constexpr float kBound = 0.1f;
    TestFrameGraph graph(kW, kH);
    TestScene scene;
    scene.sky = glm::vec3(0.0f);
    scene.quads = {TestScene::ground(50.0f, glm::vec3(0.0f))};
    const fx::ViewInfo view = makeView(glm::vec3(0, 4, 6), glm::vec3(0, 0.5f, 0), kW, kH);
    direct.desc.render.softness = 1.0f;
    direct.desc.render.contrastPower = 1.0f;
    direct.set({HandParticle{glm::vec3(0.0f, 0.5f, 0.0f), 4.0f}});

    // Where the billboard plane (through the centre, facing the camera) meets the ground.
    const glm::vec3 forward = glm::normalize(glm::vec3(0, 0.5f, 0) - view.eye);
    const float z = -forward.y * 0.5f / forward.z;  // dot(p - c, forward) = 0 at y = 0, x = 0
    const glm::vec3 line = projectToPixel(view, glm::vec3(0.0f, 0.0f, z));
    const int x0 = int(line.x) - 20, x1 = int(line.x) + 20;
    const int y0 = int(line.y) - 8, y1 = int(line.y) + 8;

    float steps[4] = {};
    for (fx::Technique t : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.settings.options.techniqueOverride = t;
        const Image img = draw(graph, scene, view, true);
        ASSERT_EQ(drawn, 1);
        writePng(std::string("/tmp/fx_host_ground_") + name(t) + ".png", img);
        steps[int(t)] = maxVerticalStep(img, x0, x1, y0, y1);
        // The particle is really there just above the line (not a vacuous pass).
        EXPECT_GT(img.value(int(line.x), int(line.y) + 10, 1), 0.2f) << name(t);
        std::printf("[ measured ] ground contact max step %-9s %.3f\n", name(t), steps[int(t)]);
    }
    EXPECT_GT(steps[int(fx::Technique::Hard)], 0.3f);
    EXPECT_LT(steps[int(fx::Technique::Soft)], kBound);
    EXPECT_LT(steps[int(fx::Technique::Spherical)], kBound);
}

// --- a particle entirely behind geometry ------------------------------------------------------

TEST_F(TechniqueTest, ParticleBehindAWallContributesNothing) {
    constexpr int kW = 160, kH = 120;
    TestFrameGraph graph(kW, kH);
    TestScene scene;
    scene.quads = {TestScene::ground(50.0f, glm::vec3(0.2f, 0.22f, 0.2f)),
                   TestScene::wallZ(-2.0f, -20.0f, 20.0f, 0.0f, 10.0f, glm::vec3(0.3f, 0.5f, 0.3f))};
    const fx::ViewInfo view = makeView(glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), kW, kH);
    // Sphere of radius 1.5 around z = -5: all of it 1.5 m or more behind the wall.
    direct.set({HandParticle{glm::vec3(0.0f, 1.5f, -5.0f), 3.0f}});
    const Image reference = draw(graph, scene, view, false);
    for (fx::Technique t : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.settings.options.techniqueOverride = t;
        for (bool quarter : {false, true}) {
            direct.settings.options.quarterRes = quarter;
            direct.settings.options.quarterResAlways = quarter;
            const Image img = draw(graph, scene, view, true);
            ASSERT_EQ(drawn, 1) << name(t) << " not even drawn: the test would prove nothing";
            EXPECT_LE(maxAbsDiff(img, reference), 1) << name(t) << (quarter ? " quarter" : "");
        }
    }
}

// --- camera flying through a spherical particle -----------------------------------------------

struct FlyThrough {
    float maxMeanChange = 0.0f;   ///< largest frame-to-frame mean |change| over the image
    int maxPixelChange = 0;       ///< largest frame-to-frame single-channel change, 1/255
    float insideCoverage = 0.0f;  ///< mean value with the camera at the particle's centre
};

// The camera moves from 6 m in front of a 4 m particle (on black) to 6 m behind it, 5 cm a frame.
FlyThrough flyThrough(TestFrameGraph& graph, TestScene& scene, DirectParticles& direct,
                      const std::string& pngPrefix) {
    FlyThrough r;
    Image previous;
    const int frames = 240;
    for (int f = 0; f <= frames; ++f) {
        const float z = 6.0f - 12.0f * float(f) / float(frames);
        const fx::ViewInfo view = makeView(glm::vec3(0.0f, 1.5f, z), glm::vec3(0.0f, 1.5f, z - 1.0f),
                                           graph.width(), graph.height(), 0.1f, 100.0f);
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& fb) { direct.declare(view, fb); });
        const Image img = graph.readColor();
        if (f == frames / 2) {
            double sum = 0.0;
            for (size_t i = 0; i < img.rgba.size(); i += 4) sum += img.rgba[i + 1] / 255.0;
            r.insideCoverage = float(sum / double(img.rgba.size() / 4));
        }
        if (!pngPrefix.empty() && (f == 100 || f == 116 || f == 120)) {
            writePng(pngPrefix + std::to_string(f) + ".png", img);
        }
        if (f > 0) {
            double sum = 0.0;
            for (size_t i = 0; i < img.rgba.size(); ++i) {
                if ((i & 3) == 3) continue;
                const int d = std::abs(int(img.rgba[i]) - int(previous.rgba[i]));
                sum += d;
                r.maxPixelChange = std::max(r.maxPixelChange, d);
            }
            r.maxMeanChange = std::max(r.maxMeanChange, float(sum / (img.rgba.size() * 0.75) / 255.0));
        }
        previous = img;
    }
    return r;
}

// Bound: no frame changes by more than 0.02 on average or by more than 40/255 in any pixel.
// The soft billboard with near_fade 0 pops (its quad is clipped whole at the near plane), which
// shows the bound catches a jump.
TEST_F(TechniqueTest, CameraMovingThroughASphericalParticleHasNoJump) {
    constexpr float kMeanBound = 0.02f;
    constexpr int kPixelBound = 40;
    TestFrameGraph graph(128, 96);
    TestScene scene;
    scene.sky = glm::vec3(0.0f);
    direct.set({HandParticle{glm::vec3(0.0f, 1.5f, 0.0f), 4.0f}});

    for (float nearFade : {0.0f, 0.5f}) {
        direct.desc.render.nearFade = nearFade;
        direct.settings.options.techniqueOverride = fx::Technique::Spherical;
        const FlyThrough s = flyThrough(graph, scene, direct,
                                        nearFade == 0.0f ? "/tmp/fx_host_flythrough_spherical_" : "");
        std::printf("[ measured ] spherical near_fade %.1f: max mean change %.4f, max pixel change %d/255, "
                    "inside coverage %.3f\n", nearFade, s.maxMeanChange, s.maxPixelChange, s.insideCoverage);
        EXPECT_LT(s.maxMeanChange, kMeanBound);
        EXPECT_LE(s.maxPixelChange, kPixelBound);
        EXPECT_GT(s.insideCoverage, 0.1f) << "inside the particle the quad must still cover the screen";
    }

    direct.desc.render.nearFade = 0.0f;
    direct.settings.options.techniqueOverride = fx::Technique::Soft;
    const FlyThrough soft = flyThrough(graph, scene, direct, "");
    std::printf("[ measured ] soft near_fade 0.0: max mean change %.4f, max pixel change %d/255\n",
                soft.maxMeanChange, soft.maxPixelChange);
    EXPECT_GT(soft.maxMeanChange, kMeanBound) << "the billboard should pop: the bound is too loose";

    // With its near fade the billboard fades out before the near plane clips it.
    direct.desc.render.nearFade = 0.5f;
    const FlyThrough faded = flyThrough(graph, scene, direct, "");
    std::printf("[ measured ] soft near_fade 0.5: max mean change %.4f, max pixel change %d/255\n",
                faded.maxMeanChange, faded.maxPixelChange);
    EXPECT_LT(faded.maxMeanChange, 0.1f);
}

// How far a faded frame is from `expected` times the unfaded one: the largest |faded / full -
// expected| of the green channel over the pixels where the unfaded smoke is above 100/255 (8-bit
// read-back is too coarse below), their count in *used.
float worstRatioError(const Image& full, const Image& faded, float expected, int* used) {
    float worst = 0.0f;
    *used = 0;
    for (int y = 0; y < full.height; ++y) {
        for (int x = 0; x < full.width; ++x) {
            if (full.at(x, y)[1] < 100) continue;
            ++*used;
            worst = std::max(worst, std::fabs(faded.value(x, y, 1) / full.value(x, y, 1) - expected));
        }
    }
    return worst;
}

// The near fade is the line from 0 at the near plane to 1 at near_fade metres past it: a
// billboard at near + k/4 of near_fade draws k/4 of the same billboard without the fade (near_fade
// 0), and one past it all of it. Hard and soft (on black, a sky far behind: soft's own fade is 1).
// Tolerance 0.03 (8-bit read-back, compared where the unfaded smoke is above 100/255).
TEST_F(TechniqueTest, NearFadeRisesLinearlyFromTheNearPlane) {
    constexpr int kW = 96, kH = 72;
    constexpr float kNear = 0.1f, kFade = 0.5f;
    TestFrameGraph graph(kW, kH);
    TestScene scene;
    scene.sky = glm::vec3(0.0f);
    const fx::ViewInfo view = makeView(glm::vec3(0.0f), glm::vec3(0, 0, -1), kW, kH, kNear, 1000.0f);
    for (const fx::Technique technique : {fx::Technique::Hard, fx::Technique::Soft}) {
        direct.desc.render.technique = technique;
        for (const float part : {0.25f, 0.5f, 0.75f, 1.5f}) {
            const float depth = kNear + part * kFade;
            direct.set({HandParticle{glm::vec3(0.0f, 0.0f, -depth), depth * 0.6f}});
            direct.desc.render.nearFade = 0.0f;
            const Image full = draw(graph, scene, view, true);
            direct.desc.render.nearFade = kFade;
            const Image faded = draw(graph, scene, view, true);
            const float expected = std::min(part, 1.0f);
            int used = 0;
            const float worst = worstRatioError(full, faded, expected, &used);
            ASSERT_GT(used, 50) << name(technique) << " at " << depth << " m barely visible";
            std::printf("[ measured ] %s near fade at %.3f m (%.2f of near_fade): expected %.2f, worst error "
                        "%.4f over %d px\n", name(technique), depth, part, expected, worst, used);
            EXPECT_LT(worst, 0.03f) << name(technique) << " at " << depth << " m";
        }
    }
}

// --- extreme clip planes ----------------------------------------------------------------------

float cpuSoftFade(float sceneDepth, float particleDepth, float softness, float contrast) {
    const float x = glm::clamp((sceneDepth - particleDepth) / softness, 0.0f, 1.0f);
    const float flip = x > 0.5f ? 1.0f - x : x;
    const float y = 0.5f * std::pow(glm::clamp(2.0f * flip, 0.0f, 1.0f), contrast);
    return x > 0.5f ? 1.0f - y : y;
}

// Near 0.01, far 100000 and 1e7. A particle at 1 m (0.5 m wide) and one at 10 km (2 km wide),
// each with a wall `gap` metres behind it: the smoke's brightness over black, divided by the same
// pixel with the wall 500 m back (fade 1), is the shader's fade. Tolerance 0.03 (8-bit read-back,
// compared where the unfaded smoke is above 100/255). Twice: a standard 24-bit host (soft
// particles untested, the fade alone) and a reversed-Z host with a float z-buffer, where the
// plugin depth-tests soft particles: the test must not eat fragments 0.1 m in front of a wall
// 10 km away. The reversed-Z host twice more, offering its z-buffer (sceneZBuffer, API 2.1): the
// plugin then reads distances decoded from the float z-buffer in the shader, not the linear
// target, and must hit the same CPU fade.
TEST_F(TechniqueTest, SoftFadeIsExactWithExtremeClipPlanes) {
    constexpr int kW = 128, kH = 96;
    for (const int host : {0, 1, 2}) {
    const bool reversed = host > 0, zBuffer = host == 2;
    for (const float farPlane : {100000.0f, 1.0e7f}) {
    TestFrameGraph graph(kW, kH, reversed, zBuffer);
    direct.desc.render.softness = 1.0f;
    direct.desc.render.nearFade = 0.5f;
    for (float distance : {1.0f, 10000.0f}) {
        const float size = distance * 0.5f / (distance < 10.0f ? 1.0f : 2.5f);
        fx::ViewInfo view = makeView(glm::vec3(0.0f), glm::vec3(0, 0, -1), kW, kH, 0.01f, farPlane);
        if (reversed) useReversedZ(&view);
        direct.set({HandParticle{glm::vec3(0.0f, 0.0f, -distance), size}});
        for (float contrast : {1.0f, 1.5f, 2.0f, 1.3f}) {  // 1.3: the general-power program
            direct.desc.render.contrastPower = contrast;
            auto frameWithWallAt = [&](float gap) {
                TestScene scene;
                scene.sky = glm::vec3(0.0f);
                scene.reversedZ = reversed;
                const float half = distance * 4.0f;
                scene.quads = {TestScene::wallZ(-(distance + gap), -half, half, -half, half, glm::vec3(0.0f))};
                renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
                return graph.readColor();
            };
            const Image full = frameWithWallAt(500.0f);
            ASSERT_EQ(drawn, 1);
            EXPECT_EQ(graph.zBufferUsed(), zBuffer);
            EXPECT_EQ(graph.sceneDepthUsed(), !zBuffer);
            for (float gap : {0.1f, 0.3f, 0.7f}) {
                const Image faded = frameWithWallAt(gap);
                const float expected = cpuSoftFade(distance + gap, distance, 1.0f, contrast);
                int used = 0;
                const float worst = worstRatioError(full, faded, expected, &used);
                ASSERT_GT(used, 20) << "particle at " << distance << " m barely visible";
                std::printf("[ measured ] %s far %.0e: soft fade at %.0f m, gap %.1f m, contrast %.1f: "
                            "expected %.3f, worst error %.4f over %d px\n",
                            zBuffer ? "reversed-Z, z-buffer read" : reversed ? "reversed-Z" : "standard",
                            double(farPlane), distance, gap, contrast, expected, worst, used);
                EXPECT_LT(worst, 0.03f) << (zBuffer ? "z-buffer " : reversed ? "reversed " : "standard ") << "far " << farPlane
                                        << " distance " << distance << " gap " << gap;
            }
        }
    }
    }
    }
}

// --- draw order -------------------------------------------------------------------------------

// Two overlapping opaque-ish particles of one reaction, coloured by life through the ramp:
// red (life 0) in front, blue (life 1) behind, pool order front first. Sorted back to front the
// front particle is drawn last and dominates; unsorted (pool order) the back one does.
TEST_F(TechniqueTest, AlphaBlendedParticlesAreDrawnBackToFront) {
    TestFrameGraph graph(96, 72);
    TestScene scene;
    scene.sky = glm::vec3(0.0f);
    const fx::ViewInfo view = makeView(glm::vec3(0, 0, 5), glm::vec3(0, 0, 0), 96, 72);
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1, 0, 0, 1)},
                                      fx::ColorStop{1.0f, glm::vec4(0, 0, 1, 1)}};
    direct.desc.render.technique = fx::Technique::Hard;
    direct.set({HandParticle{glm::vec3(0, 0, 1), 2.0f, 0.0f}, HandParticle{glm::vec3(0, 0, -1), 3.0f, 1.0f}});
    for (bool sorted : {true, false}) {
        direct.desc.render.sortBackToFront = sorted;
        const Image img = draw(graph, scene, view, true);
        const uint8_t* c = img.at(48, 36);
        if (sorted) {
            EXPECT_GT(c[0], c[2]) << "front (red) particle should dominate";
        } else {
            EXPECT_GT(c[2], c[0]) << "unsorted pool order draws the back (blue) one last";
        }
    }
}

}  // namespace
}  // namespace fxtest
