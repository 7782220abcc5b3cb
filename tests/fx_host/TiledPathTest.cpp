// The tiled path (TiledPath.h, RenderOptions::tiled): hard and soft billboards and spheres shaded
// per 16 px tile by a compute shader, then blended onto sceneColor once per covered pixel.
//  - It runs: the view's pass is "particles_tiled" and the rasterised "particles" never runs.
//  - The picture is the rasterised one up to rounding (kTolerance): under standard depth (the
//    linear target), reversed-Z and a reversed-Z z-buffer read in place, near 0.1 and 0.01 m, far
//    1e3 and 1e7 m, contrast powers 1, 2 and 1.3, alpha, premultiplied and additive blending, fog,
//    and particles that cross the ground, stand in front of a wall, reach past the view's edge,
//    around the near plane and behind the camera; coloured particles whose order shows in the
//    picture (the compute shader blends front to back what the raster path blends back to front).
//  - Lit smoke: the rasterised lit picture of the same shape (quads, trimmed polygons) up to rounding.
//  - Where it cannot draw (spheres under an orthographic projection), the view is drawn as
//    without it.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <glad/gl.h>
#include <glm/gtc/matrix_transform.hpp>

#include "FxTestHost.h"
#include "render/FullResPath.h"
#include "render/TileSort.h"
#include "render/TiledPath.h"
#include "render/TiledStageTimes.h"

namespace fxtest {
namespace tiled_path_test {  // named: the fx_host tests build as unity batches

constexpr int kW = 256, kH = 192;
// The raster path's blend rounds each layer to the 8-bit target; the compute shader keeps floats
// until the one blend of the pixel. Measured (llvmpipe): at most 2/255 with the 7 particles of the
// first test; 4/255 with 24 overlapping puffs (43-75 channel values of 147,456 at 3 or more, about
// 1,100 at 2), 3/255 additive.
constexpr int kTolerance = 4;
// Spheres: one channel value of 147,456 at 5/255 besides (the atlas level of detail is one per
// sphere, its centre's; the raster path's varies a little over the disc, and where it sits between
// two levels the other one is read).
constexpr int kSphericalTolerance = 5;

// 24 overlapping puffs on a ring 2 m round (0, y, -2), their heights from `y` up in steps of 0.1 m,
// every life, angle and atlas frame, each faded to `fade`.
std::vector<HandParticle> ringOfPuffs(float y, float fade) {
    std::vector<HandParticle> puffs;
    for (int i = 0; i < 24; ++i) {
        const float a = 0.7f * float(i);
        puffs.push_back(HandParticle{glm::vec3(2.0f * std::cos(a), y + 0.1f * float(i % 5), -2.0f + 2.0f * std::sin(a)),
                                     2.5f, float(i) / 24.0f, a, fade, i % 4});
    }
    return puffs;
}

// A ground 60 m across, grey 0.3, for a reversed-Z host.
TestScene reversedGround() {
    TestScene scene;
    scene.reversedZ = true;
    scene.quads = {TestScene::ground(60.0f, glm::vec3(0.3f))};
    return scene;
}

class TiledPathTest : public FxHostTest {
protected:
    Image draw(DirectParticles& particles, TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view,
               bool tiled) {
        particles.settings.options.tiling = tiled ? fx::Tiling::On : fx::Tiling::Off;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = particles.declare(view, f); });
        return graph.readColor();
    }
    TestHostAdapter host;
    DirectParticles direct{&host};
    int drawn = 0;
};

// Particles of every kind of placement, coloured by life (red young, blue old) so that the order
// of overlapping ones shows; each frame drawn rasterised and tiled.
TEST_F(TiledPathTest, TiledFramesMatchRasterisedOnes) {
    ASSERT_TRUE(fx::TiledPath::available()) << "llvmpipe's GL 4.5 has compute shaders";
    direct.desc.render.softness = 1.0f;
    direct.desc.render.nearFade = 0.3f;
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f, 0.1f, 0.1f, 0.9f)},
                                      fx::ColorStop{1.0f, glm::vec4(0.1f, 0.2f, 1.0f, 0.6f)}};
    direct.set({
        HandParticle{glm::vec3(0.0f, 1.0f, 0.0f), 4.0f, 0.1f, 0.3f},    // crosses the ground
        HandParticle{glm::vec3(0.5f, 1.2f, 0.5f), 3.0f, 0.9f, 1.0f},    // in front of it, another colour
        HandParticle{glm::vec3(-3.0f, 3.0f, -5.0f), 3.0f, 0.5f, 1.1f},  // 15 m in front of the wall
        HandParticle{glm::vec3(1.0f, 1.2f, -19.4f), 3.0f, 0.2f, 0.0f},  // 0.6 m in front of it
        HandParticle{glm::vec3(5.0f, 0.5f, 2.0f), 6.0f, 0.7f, 2.0f},    // past the view's right edge
        HandParticle{glm::vec3(0.0f, 2.0f, 7.0f), 3.0f, 0.5f, 0.7f},    // around the camera's near plane
        HandParticle{glm::vec3(0.0f, 2.0f, 11.0f), 2.0f},               // behind the camera
    });
    int compared = 0;
    for (const fx::Technique technique : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.desc.render.technique = technique;
        const char* name = technique == fx::Technique::Hard ? "hard" : technique == fx::Technique::Soft ? "soft" : "spherical";
        for (const int host : {0, 1, 2}) {
            const bool reversed = host > 0, zBuffer = host == 2;
            for (const float nearPlane : {0.1f, 0.01f}) {
                for (const float farPlane : {1000.0f, 1.0e7f}) {
                    TestFrameGraph graph(kW, kH, reversed, zBuffer);
                    TestScene scene;
                    scene.sky = glm::vec3(0.0f);
                    scene.reversedZ = reversed;
                    scene.quads = {TestScene::ground(60.0f, glm::vec3(0.2f)),
                                   TestScene::wallZ(-20.0f, -40.0f, 40.0f, 0.0f, 30.0f, glm::vec3(0.1f))};
                    fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.0f, 8.0f), glm::vec3(0.0f, 1.0f, 0.0f), kW, kH,
                                                 nearPlane, farPlane);
                    if (reversed) useReversedZ(&view);
                    for (const float contrast : {1.0f, 2.0f, 1.3f}) {
                        if (technique != fx::Technique::Soft && contrast != 1.0f) continue;  // no fade to shape
                        direct.desc.render.contrastPower = contrast;
                        SCOPED_TRACE(std::string(name) + ", " +
                                     (zBuffer ? "reversed-Z, z-buffer read" : reversed ? "reversed-Z" : "standard") +
                                     ", near " + std::to_string(nearPlane) + ", far " + std::to_string(farPlane) +
                                     ", contrast " + std::to_string(contrast));
                        const Image raster = draw(direct, graph, scene, view, false);
                        ASSERT_GE(drawn, 5);
                        EXPECT_TRUE(graph.ran(fx::ParticleRenderer::kFullResPass));
                        const Image tiled = draw(direct, graph, scene, view, true);
                        EXPECT_TRUE(graph.ran(fx::TiledPath::kPass));
                        EXPECT_FALSE(graph.ran(fx::ParticleRenderer::kFullResPass)) << "the rasterised pass ran too";
                        int smoke = 0;
                        for (int y = 0; y < kH; ++y) {
                            for (int x = 0; x < kW; ++x) smoke += raster.at(x, y)[0] > 60 ? 1 : 0;
                        }
                        ASSERT_GT(smoke, kW * kH / 10) << "too little smoke: the comparison would prove little";
                        EXPECT_LE(maxAbsDiff(raster, tiled), kTolerance);
                        ++compared;
                    }
                }
            }
        }
    }
    EXPECT_EQ(compared, 3 * 2 * 2 * (1 + 3 + 1));
}

// A view's lists, written on the CPU (a software rasterizer's default up to
// kSoftwareCpuListEntries: these tests run on one) or sorted on the GPU (TileSort: a GPU's default,
// kCpuListEntries 0), are the same lists, and so are those of a list whose particles the GPU sorted
// back to front (TileSort::orderLimit 0; a GPU's default from kOrderParticles): the frames are
// equal bit for bit, for each technique, coloured by life so that the order shows, and the
// counters say which way each frame went.
TEST_F(TiledPathTest, ListsWrittenOnTheCpuOrSortedOnTheGpuGiveTheSameFrame) {
    struct LimitBack {
        ~LimitBack() {
            fx::TiledPath::resetCpuListLimit();
            fx::TileSort::resetOrderLimit();
            fx::TiledPath::resetDeferBins();
            fx::TiledPath::resetGpuBins();
            fx::TiledPath::resetGatherInPass();
        }
    } limitBack;
    fx::TiledPath::resetDeferBins();
    fx::TiledPath::resetGpuBins();
    fx::TiledPath::resetGatherInPass();
    ASSERT_TRUE(fx::TiledPath::gatherInPass()) << "on by default (CUBEFX_TILED_GATHER_IN_PASS unset)";
    ASSERT_TRUE(fx::TiledPath::deferBins()) << "on by default (CUBEFX_TILED_DEFER_BINS unset)";
    ASSERT_TRUE(fx::TiledPath::gpuBins()) << "on by default (CUBEFX_TILED_GPU_BINS unset)";
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f, 0.1f, 0.1f, 0.9f)},
                                      fx::ColorStop{1.0f, glm::vec4(0.1f, 0.2f, 1.0f, 0.6f)}};
    ASSERT_TRUE(fx::TiledPath::softwareRasterizer(reinterpret_cast<const char*>(glGetString(GL_RENDERER))));
    ASSERT_EQ(fx::TiledPath::cpuListLimit(true), fx::TiledPath::kSoftwareCpuListEntries);
    ASSERT_EQ(fx::TiledPath::cpuListLimit(false), fx::TiledPath::kCpuListEntries);
    EXPECT_EQ(fx::TiledPath::kCpuListEntries, 0u) << "on a GPU the GPU writes every view's lists";
    std::vector<HandParticle> puffs;
    for (int i = 0; i < 40; ++i) {
        const float a = 0.5f * float(i);
        puffs.push_back(HandParticle{glm::vec3(2.5f * std::cos(a), 0.5f + 0.1f * float(i % 7), -2.0f + 2.5f * std::sin(a)),
                                     2.0f + 0.05f * float(i), float(i) / 40.0f, a, 0.9f, i % 4});
    }
    direct.set(puffs);
    for (const fx::Technique technique : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.desc.render.technique = technique;
        SCOPED_TRACE(int(technique));
        TestFrameGraph graph(kW, kH, true, true);
        TestScene scene = reversedGround();
        fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.5f, 6.0f), glm::vec3(0.0f, 0.5f, -1.0f), kW, kH);
        useReversedZ(&view);
        uint64_t cpu = fx::TiledPath::cpuListViews(), gpu = fx::TiledPath::gpuSortedViews();
        const Image byDefault = draw(direct, graph, scene, view, true);  // a few thousand entries
        ASSERT_GE(drawn, 40);
        EXPECT_TRUE(graph.ran(fx::TiledPath::kPass));
        EXPECT_EQ(fx::TiledPath::cpuListViews(), cpu + 1) << "a small view's lists are the CPU's on llvmpipe";
        EXPECT_EQ(fx::TiledPath::gpuSortedViews(), gpu);
        const uint64_t ordered = fx::TileSort::gpuOrderedViews();
        fx::TiledPath::setCpuListLimit(0);
        const Image sorted = draw(direct, graph, scene, view, true);
        EXPECT_EQ(fx::TiledPath::cpuListViews(), cpu + 1);
        EXPECT_EQ(fx::TiledPath::gpuSortedViews(), gpu + 1) << "with the limit at 0 the GPU sorts";
        EXPECT_EQ(fx::TileSort::gpuOrderedViews(), ordered) << "llvmpipe: the CPU sorts the particles";
        fx::TileSort::setOrderLimit(0);
        const uint64_t deferred = fx::TiledPath::deferredBinViews(), gpuBinned = fx::TiledPath::gpuBinnedViews();
        const uint64_t gathered = fx::TiledPath::gatheredViews();
        const Image gpuOrdered = draw(direct, graph, scene, view, true);
        EXPECT_EQ(fx::TiledPath::gpuBinnedViews(), gpuBinned + 1) << "the GPU bins a view binned in its pass";
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + 1)
            << "its particles are written from the pool into the pass's buffer, not while declared";
        EXPECT_EQ(fx::TiledPath::gpuSortedViews(), gpu + 2);
        EXPECT_EQ(fx::TileSort::gpuOrderedViews(), ordered + 1) << "with the order limit at 0 the GPU sorts them";
        EXPECT_EQ(fx::TiledPath::deferredBinViews(), deferred + 1) << "a view the GPU orders is binned in its pass";
        // In two passes, the setup first (the instances, the order, the records), then the bins.
        const std::vector<std::string>& ran = graph.executed();
        const auto setupAt = std::find(ran.begin(), ran.end(), fx::TiledPath::kSetupPass);
        ASSERT_NE(setupAt, ran.end());
        EXPECT_EQ(std::find(ran.begin(), ran.end(), fx::TiledPath::kPass), setupAt + 1);
        // A host graph that leaves the setup pass out (culled it, or ran another view's between):
        // the second pass does its work itself, the same frame.
        graph.skipPluginPass = [](const std::string& name) { return name == fx::TiledPath::kSetupPass; };
        const Image setUpInTheSecond = draw(direct, graph, scene, view, true);
        graph.skipPluginPass = nullptr;
        EXPECT_FALSE(graph.ran(fx::TiledPath::kSetupPass));
        EXPECT_TRUE(graph.ran(fx::TiledPath::kPass));
        EXPECT_EQ(fx::TiledPath::deferredBinViews(), deferred + 2);
        EXPECT_EQ(fx::TiledPath::gpuBinnedViews(), gpuBinned + 2);
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + 2) << "by the second pass";
        EXPECT_EQ(maxAbsDiff(gpuOrdered, setUpInTheSecond), 0);
        // The pool changed after the view was declared, before its passes ran, the renderer told
        // first (the plugin does so before a step, a fire or a reload): the view as declared.
        const std::vector<HandParticle> elsewhere = ringOfPuffs(1.5f, 0.4f);
        const uint64_t settled = direct.renderer.listsSettled();
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            drawn = direct.declare(view, f);
            direct.renderer.settleLists();
            direct.set(elsewhere);
        });
        EXPECT_EQ(direct.renderer.listsSettled(), settled + 1);
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + 2) << "written when the renderer was told";
        EXPECT_EQ(maxAbsDiff(gpuOrdered, graph.readColor()), 0);
        const Image changed = draw(direct, graph, scene, view, true);
        EXPECT_GT(maxAbsDiff(gpuOrdered, changed), 20) << "the change shows in the next frame";
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + 3);
        // The graph holds that frame's passes until its next frame; they ran: nothing to write.
        direct.renderer.settleLists();
        EXPECT_EQ(direct.renderer.listsSettled(), settled + 1);
        direct.set(puffs);
        // CUBEFX_TILED_GATHER_IN_PASS=0: the list is written while declared; the same frame.
        fx::TiledPath::setGatherInPass(false);
        const Image listCopied = draw(direct, graph, scene, view, true);
        fx::TiledPath::resetGatherInPass();
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + 3);
        EXPECT_EQ(maxAbsDiff(gpuOrdered, listCopied), 0);
        // Binned in its pass on the host's threads instead (CUBEFX_TILED_GPU_BINS=0): the same frame.
        fx::TiledPath::setGpuBins(false);
        const Image binnedOnCpu = draw(direct, graph, scene, view, true);
        fx::TiledPath::resetGpuBins();
        EXPECT_TRUE(graph.ran(fx::TiledPath::kSetupPass));
        EXPECT_EQ(fx::TiledPath::deferredBinViews(), deferred + 6);
        EXPECT_EQ(fx::TiledPath::gpuBinnedViews(), gpuBinned + 5) << "the host's threads binned it";
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + 3) << "and the list was written while declared";
        EXPECT_EQ(maxAbsDiff(gpuOrdered, binnedOnCpu), 0);
        // The same view binned while it is declared: the same frame.
        fx::TiledPath::setDeferBins(false);
        const Image binnedEarly = draw(direct, graph, scene, view, true);
        fx::TiledPath::resetDeferBins();
        EXPECT_EQ(fx::TiledPath::deferredBinViews(), deferred + 6);
        EXPECT_EQ(fx::TiledPath::gpuBinnedViews(), gpuBinned + 5);
        EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + 3);
        EXPECT_FALSE(graph.ran(fx::TiledPath::kSetupPass)) << "one pass for a view binned while declared";
        EXPECT_EQ(fx::TileSort::gpuOrderedViews(), ordered + 7);
        fx::TiledPath::resetCpuListLimit();
        fx::TileSort::resetOrderLimit();
        EXPECT_EQ(maxAbsDiff(byDefault, sorted), 0);
        EXPECT_EQ(maxAbsDiff(byDefault, gpuOrdered), 0);
        EXPECT_EQ(maxAbsDiff(byDefault, binnedEarly), 0);
        // The same particles in pool order look different: the order is in the picture.
        direct.desc.render.sortBackToFront = false;
        const Image unsorted = draw(direct, graph, scene, view, true);
        direct.desc.render.sortBackToFront = true;
        EXPECT_GT(maxAbsDiff(byDefault, unsorted), 20);
        int smoke = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) smoke += byDefault.at(x, y)[0] > 60 ? 1 : 0;
        }
        EXPECT_GT(smoke, kW * kH / 10) << "too little smoke: the comparison would prove little";
    }
}

// CUBEFX_TILED_STAGE_TIMES=1 (TiledStageTimes::set): a view binned in its pass is timed stage by
// stage with GL_TIMESTAMP queries, read a few views later without a stall and reported as medians
// in the renderer's log, each of the eight stages named with a time of 0 or more (llvmpipe's
// timestamps say nothing more); off, nothing is reported; a view binned while declared is not
// timed.
TEST_F(TiledPathTest, StageTimesAreLoggedForViewsBinnedInTheirPass) {
    struct Back {
        ~Back() {
            fx::TiledPath::resetCpuListLimit();
            fx::TileSort::resetOrderLimit();
            fx::TiledStageTimes::reset();
            fx::TiledStageTimes::setReportEvery(64);
        }
    } back;
    direct.set(ringOfPuffs(0.5f, 0.9f));
    TestFrameGraph graph(kW, kH, true, true);
    TestScene scene = reversedGround();
    fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.5f, 6.0f), glm::vec3(0.0f, 0.5f, -1.0f), kW, kH);
    useReversedZ(&view);
    auto reports = [&] {
        std::vector<std::string> lines;
        for (const std::string& m : host.messages()) {
            if (m.find("fx: tiled stages, GPU ms") != std::string::npos) lines.push_back(m);
        }
        return lines;
    };
    fx::TiledPath::setCpuListLimit(0);
    fx::TileSort::setOrderLimit(0);
    fx::TiledStageTimes::setReportEvery(3);
    fx::TiledStageTimes::set(false);
    for (int frame = 0; frame < 8; ++frame) draw(direct, graph, scene, view, true);
    EXPECT_TRUE(graph.ran(fx::TiledPath::kSetupPass));
    EXPECT_TRUE(reports().empty()) << "off by default";
    fx::TiledStageTimes::set(true);
    for (int frame = 0; frame < 12; ++frame) draw(direct, graph, scene, view, true);
    const std::vector<std::string> lines = reports();
    ASSERT_GE(lines.size(), 2u) << "12 views, a report every 3 (read a few views late)";
    for (const std::string& line : lines) {
        EXPECT_NE(line.find("median of 3 views, 24 particles"), std::string::npos) << line;
        for (const char* stage : fx::TiledStageTimes::kStageNames) {
            const size_t at = line.find(std::string(" ") + stage + " ");
            ASSERT_NE(at, std::string::npos) << stage << " in " << line;
            EXPECT_GE(std::atof(line.c_str() + at + std::strlen(stage) + 2), 0.0) << line;
        }
    }
    // Binned while declared (one pass): not timed.
    fx::TiledPath::setDeferBins(false);
    for (int frame = 0; frame < 8; ++frame) draw(direct, graph, scene, view, true);
    fx::TiledPath::resetDeferBins();
    EXPECT_EQ(reports().size(), lines.size());
}

// Each blend mode, with linear fog, billboards and spheres: the tint, the fog's colour and the
// premultiplied or additive output are the particle's own, as the raster path's vertex shader
// makes them (a sphere's near fade, per pixel, too: the camera is 2 m from the nearest puffs).
TEST_F(TiledPathTest, BlendModesAndFogMatchRasterisedOnes) {
    direct.desc.render.softness = 0.5f;
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.9f, 0.6f, 0.2f, 0.8f)},
                                      fx::ColorStop{1.0f, glm::vec4(0.2f, 0.5f, 0.9f, 0.5f)}};
    direct.set(ringOfPuffs(0.6f, 0.8f));
    for (const fx::Technique technique : {fx::Technique::Soft, fx::Technique::Spherical})
    for (const fx::BlendMode blend : {fx::BlendMode::Alpha, fx::BlendMode::Premultiplied, fx::BlendMode::Additive}) {
        direct.desc.render.technique = technique;
        direct.desc.render.blend = blend;
        for (const bool fog : {false, true}) {
            SCOPED_TRACE(std::string(technique == fx::Technique::Soft ? "soft" : "spherical") + ", blend " +
                         std::to_string(int(blend)) + (fog ? ", fog" : ""));
            TestFrameGraph graph(kW, kH, true, true);
            TestScene scene = reversedGround();
            fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.5f, 6.0f), glm::vec3(0.0f, 0.5f, -1.0f), kW, kH);
            useReversedZ(&view);
            if (fog) {
                view.fog.mode = fx::Fog::Mode::Linear;
                view.fog.color = glm::vec3(0.5f, 0.6f, 0.7f);
                view.fog.start = 2.0f;
                view.fog.end = 14.0f;
            }
            const Image raster = draw(direct, graph, scene, view, false);
            ASSERT_GE(drawn, 20);
            const Image tiled = draw(direct, graph, scene, view, true);
            EXPECT_TRUE(graph.ran(fx::TiledPath::kPass));
            EXPECT_LE(maxAbsDiff(raster, tiled), technique == fx::Technique::Spherical ? kSphericalTolerance : kTolerance);
        }
    }
}

// Lit smoke (a scene light, the reaction taking it): each technique, with the opacity map's
// self-shadowing and without, with linear fog, and reactions that do not take the light (additive,
// lighting off) in a lit view. The raster path interpolates the light its vertex shader works out (the sun through
// the opacity map, the phase) over its triangles: a quad's two, or a trimmed polygon's fan, whose
// vertices lie elsewhere (measured on llvmpipe with absorption 3: quads against trimmed 21-25/255).
// The tiled path interpolates over the same triangles as the raster path of the same shape, so each
// shape's tiled frame is that shape's raster frame up to rounding: kTolerance, and spheres (lit at
// their centre whatever the shape) kSphericalTolerance; trimmed billboards one more (measured: one
// or two channel values of 147,456 at 5/255, the rest within 3/255, PSNR 58.6-59.0 dB).
TEST_F(TiledPathTest, LitSmokeMatchesRasterisedLitSmoke) {
    direct.set(ringOfPuffs(0.8f, 0.9f));
    direct.desc.render.softness = 0.5f;
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.95f, 0.9f, 0.85f, 0.9f)},
                                      fx::ColorStop{1.0f, glm::vec4(0.8f, 0.8f, 0.85f, 0.6f)}};
    fx::LightState light;
    light.on = true;
    light.toSun = glm::normalize(glm::vec3(0.6f, 0.7f, -0.4f));
    light.sunColor = glm::vec3(1.0f, 0.92f, 0.8f);
    light.ambient = glm::vec3(0.25f, 0.3f, 0.38f);
    direct.settings.light = light;
    struct Case {
        fx::Technique technique;
        float absorption;
        fx::BlendMode blend;
        bool takesLight;
        bool fog = false;
    };
    int spread = 0;
    for (const Case& c : {Case{fx::Technique::Soft, 0.0f, fx::BlendMode::Alpha, true},
                          Case{fx::Technique::Soft, 3.0f, fx::BlendMode::Alpha, true},
                          Case{fx::Technique::Soft, 3.0f, fx::BlendMode::Alpha, true, true},
                          Case{fx::Technique::Hard, 3.0f, fx::BlendMode::Premultiplied, true},
                          Case{fx::Technique::Spherical, 3.0f, fx::BlendMode::Alpha, true},
                          Case{fx::Technique::Spherical, 0.0f, fx::BlendMode::Alpha, true, true},
                          Case{fx::Technique::Soft, 3.0f, fx::BlendMode::Additive, true},
                          Case{fx::Technique::Soft, 3.0f, fx::BlendMode::Alpha, false}}) {
        direct.desc.render.technique = c.technique;
        direct.desc.render.blend = c.blend;
        direct.desc.lighting.absorption = c.absorption;
        direct.desc.lighting.enabled = c.takesLight;
        SCOPED_TRACE(testing::Message() << "technique " << int(c.technique) << ", absorption " << c.absorption
                                        << ", blend " << int(c.blend) << (c.takesLight ? "" : ", lighting off")
                                        << (c.fog ? ", fog" : ""));
        TestFrameGraph graph(kW, kH, true, true);
        TestScene scene = reversedGround();
        fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.5f, 6.0f), glm::vec3(0.0f, 0.8f, -1.0f), kW, kH);
        useReversedZ(&view);
        if (c.fog) {
            view.fog.mode = fx::Fog::Mode::Linear;
            view.fog.color = glm::vec3(0.5f, 0.6f, 0.7f);
            view.fog.start = 2.0f;
            view.fog.end = 14.0f;
        }
        direct.settings.shape = fx::ParticleShape::Quad;
        const Image rasterQuads = draw(direct, graph, scene, view, false);
        ASSERT_GE(drawn, 20);
        const Image tiled = draw(direct, graph, scene, view, true);
        EXPECT_TRUE(graph.ran(fx::TiledPath::kPass));
        EXPECT_FALSE(graph.ran(fx::ParticleRenderer::kFullResPass));
        direct.settings.shape = fx::ParticleShape::Trimmed;
        const Image rasterTrimmed = draw(direct, graph, scene, view, false);
        const Image tiledTrimmed = draw(direct, graph, scene, view, true);
        // Lit at all: the same frame unlit differs from it.
        direct.settings.light.on = false;
        const Image unlit = draw(direct, graph, scene, view, true);
        direct.settings.light.on = true;
        const int quads = maxAbsDiff(rasterQuads, tiled), trimmed = maxAbsDiff(rasterTrimmed, tiledTrimmed),
                  shapes = maxAbsDiff(rasterQuads, rasterTrimmed);
        std::printf("[ measured ] technique %d absorption %.0f blend %d%s%s: tiled against raster, quads %d/255, "
                    "trimmed %d/255 (raster quads against trimmed %d/255); lit against unlit %d/255\n",
                    int(c.technique), double(c.absorption), int(c.blend), c.takesLight ? "" : " (lighting off)",
                    c.fog ? " fog" : "", quads, trimmed, shapes, maxAbsDiff(tiled, unlit));
        if (c.takesLight && c.blend != fx::BlendMode::Additive) {
            EXPECT_GT(maxAbsDiff(tiled, unlit), 40) << "the light changed nothing";
        } else {
            EXPECT_EQ(maxAbsDiff(tiled, unlit), 0) << "a reaction that takes no light is drawn unlit";
        }
        const int tolerance = c.technique == fx::Technique::Spherical ? kSphericalTolerance : kTolerance;
        EXPECT_LE(quads, tolerance);
        EXPECT_LE(trimmed, c.technique == fx::Technique::Spherical ? tolerance : tolerance + 1);
        spread = std::max(spread, shapes);
    }
    EXPECT_GT(spread, 10) << "the shadowed cases should tell the shapes apart (else the trimmed check shows nothing)";
    direct.settings.light = fx::LightState{};
}

// Spheres under a projection that is not a perspective one are not the tiled path's: their views
// are drawn exactly as without it.
TEST_F(TiledPathTest, ViewsItCannotDrawAreDrawnAsWithoutIt) {
    direct.set({HandParticle{glm::vec3(0.0f, 1.0f, 0.0f), 4.0f}, HandParticle{glm::vec3(1.0f, 1.5f, -1.0f), 3.0f}});
    TestFrameGraph graph(kW, kH, true, true);
    TestScene scene = reversedGround();
    fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.0f, 8.0f), glm::vec3(0.0f, 1.0f, 0.0f), kW, kH);
    useReversedZ(&view);

    // Spheres seen through an orthographic projection (reversed-Z: far and near swapped).
    direct.desc.render.technique = fx::Technique::Spherical;
    fx::ViewInfo ortho = view;
    ortho.proj = glm::ortho(-6.0f, 6.0f, -4.5f, 4.5f, 1000.0f, 0.1f);
    const Image plain = draw(direct, graph, scene, ortho, false);
    const Image tiled = draw(direct, graph, scene, ortho, true);
    EXPECT_FALSE(graph.ran(fx::TiledPath::kPass));
    EXPECT_EQ(maxAbsDiff(plain, tiled), 0);
    // Where the GPU would sort the particles (limits at 0) the list comes unsorted, and the
    // raster path it goes to sorts it on the CPU first: the same frame. The nearer puff is first in
    // the pool and of another colour: drawn unsorted, the frame would differ.
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f, 0.1f, 0.1f, 0.9f)},
                                      fx::ColorStop{1.0f, glm::vec4(0.1f, 0.2f, 1.0f, 0.9f)}};
    direct.set({HandParticle{glm::vec3(0.0f, 1.5f, 3.0f), 3.0f, 0.1f}, HandParticle{glm::vec3(0.5f, 1.5f, -1.0f), 4.0f, 0.9f}});
    const Image sortedPlain = draw(direct, graph, scene, ortho, false);
    direct.desc.render.sortBackToFront = false;
    const Image unsortedPlain = draw(direct, graph, scene, ortho, false);
    direct.desc.render.sortBackToFront = true;
    EXPECT_GT(maxAbsDiff(sortedPlain, unsortedPlain), 20) << "the order shows in the picture";
    fx::TiledPath::setCpuListLimit(0);
    fx::TileSort::setOrderLimit(0);
    draw(direct, graph, scene, view, true);  // a perspective view: the tiled programs are built
    EXPECT_TRUE(graph.ran(fx::TiledPath::kPass));
    const uint64_t ordered = fx::TileSort::gpuOrderedViews();
    const Image deferred = draw(direct, graph, scene, ortho, true);
    fx::TiledPath::resetCpuListLimit();
    fx::TileSort::resetOrderLimit();
    EXPECT_FALSE(graph.ran(fx::TiledPath::kPass));
    EXPECT_EQ(fx::TileSort::gpuOrderedViews(), ordered);
    EXPECT_EQ(maxAbsDiff(sortedPlain, deferred), 0);
}

// Bins worked out in the pass (TiledPath::deferBins) that the pass cannot take (here: lists past
// a storage block capped at 256 bytes, TileSort::setBlockLimit): the pass draws the view as the raster
// path would, its order put in place first, the frame the same as without the tiled path. Binned
// while declared (deferBins off), the same view goes to the raster pass from the start.
TEST_F(TiledPathTest, DeferredBinsThePassCannotTakeDrawTheRasterisedFrame) {
    struct LimitBack {
        ~LimitBack() {
            fx::TiledPath::resetCpuListLimit();
            fx::TileSort::resetOrderLimit();
            fx::TiledPath::resetDeferBins();
            fx::TileSort::setBlockLimit(0);
        }
    } limitBack;
    fx::TiledPath::resetDeferBins();
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f, 0.1f, 0.1f, 0.9f)},
                                      fx::ColorStop{1.0f, glm::vec4(0.1f, 0.2f, 1.0f, 0.6f)}};
    direct.set(ringOfPuffs(0.5f, 0.9f));
    TestFrameGraph graph(kW, kH, true, true);
    TestScene scene = reversedGround();
    fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.5f, 6.0f), glm::vec3(0.0f, 0.5f, -1.0f), kW, kH);
    useReversedZ(&view);
    const Image raster = draw(direct, graph, scene, view, false);
    fx::TiledPath::setCpuListLimit(0);
    fx::TileSort::setOrderLimit(0);
    const Image tiled = draw(direct, graph, scene, view, true);
    EXPECT_TRUE(graph.ran(fx::TiledPath::kPass));
    EXPECT_GT(maxAbsDiff(raster, tiled), 0) << "the tiled frame rounds differently: the fallback below shows";
    EXPECT_LE(maxAbsDiff(raster, tiled), kTolerance);

    fx::TileSort::setBlockLimit(256);  // 64 pairs: the ring's puffs take hundreds
    const uint64_t deferred = fx::TiledPath::deferredBinViews(), fallbacks = fx::TiledPath::deferredFallbacks();
    const uint64_t ordered = fx::TileSort::gpuOrderedViews();
    const Image fellBack = draw(direct, graph, scene, view, true);
    EXPECT_TRUE(graph.ran(fx::TiledPath::kPass)) << "declared tiled: the bins were not known yet";
    EXPECT_FALSE(graph.ran(fx::FullResPath::kPass));
    EXPECT_EQ(fx::TiledPath::deferredBinViews(), deferred);
    EXPECT_EQ(fx::TiledPath::deferredFallbacks(), fallbacks + 1);
    EXPECT_EQ(fx::TileSort::gpuOrderedViews(), ordered) << "the order begun on the GPU was dropped";
    EXPECT_EQ(maxAbsDiff(raster, fellBack), 0);

    fx::TiledPath::setDeferBins(false);
    const Image early = draw(direct, graph, scene, view, true);
    EXPECT_FALSE(graph.ran(fx::TiledPath::kPass));
    EXPECT_TRUE(graph.ran(fx::FullResPath::kPass));
    EXPECT_EQ(fx::TiledPath::deferredFallbacks(), fallbacks + 1);
    EXPECT_EQ(maxAbsDiff(raster, early), 0);

    // Back under the context's limit the next view is tiled again, its order its own.
    fx::TileSort::setBlockLimit(0);
    fx::TiledPath::resetDeferBins();
    const Image again = draw(direct, graph, scene, view, true);
    EXPECT_EQ(fx::TiledPath::deferredBinViews(), deferred + 1);
    EXPECT_EQ(maxAbsDiff(tiled, again), 0);
}

// Tiling::Auto, the default: rasterised on a software rasterizer (this context: llvmpipe), as
// Off; On and the 2.3 switch `tiled` draw it tiled. The renderer strings Auto tiles on and not.
TEST_F(TiledPathTest, AutoRasterisesOnASoftwareRasterizerAndOnOrTiledDrawTiled) {
    EXPECT_EQ(fx::RenderOptions{}.tiling, fx::Tiling::Auto);
    EXPECT_FALSE(fx::RenderOptions{}.tiled);
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    ASSERT_TRUE(fx::TiledPath::softwareRasterizer(renderer)) << renderer;
    for (const char* software : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Mesa X11 Software Rasterizer",
                                 "SwiftShader Device (Subzero)", "D3D12 (Microsoft Basic Render Driver)"}) {
        EXPECT_TRUE(fx::TiledPath::softwareRasterizer(software)) << software;
    }
    for (const char* gpu : {"NVIDIA H200/PCIe/SSE2", "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)",
                            "Mesa Intel(R) UHD Graphics 620 (KBL GT2)", "Apple M2"}) {
        EXPECT_FALSE(fx::TiledPath::softwareRasterizer(gpu)) << gpu;
    }
    EXPECT_FALSE(fx::TiledPath::softwareRasterizer(nullptr));

    direct.set({HandParticle{glm::vec3(0.0f, 1.0f, 0.0f), 4.0f}, HandParticle{glm::vec3(1.0f, 1.5f, -1.0f), 3.0f}});
    direct.desc.render.technique = fx::Technique::Soft;
    TestFrameGraph graph(kW, kH);
    TestScene scene;
    scene.quads = {TestScene::ground(60.0f, glm::vec3(0.3f))};
    const fx::ViewInfo view = makeView(glm::vec3(0.0f, 2.0f, 8.0f), glm::vec3(0.0f, 1.0f, 0.0f), kW, kH);
    struct Case {
        bool tiled;
        fx::Tiling tiling;
        bool expectTiled;
    };
    for (const Case& c : {Case{false, fx::Tiling::Auto, false}, Case{false, fx::Tiling::Off, false},
                          Case{false, fx::Tiling::On, true}, Case{true, fx::Tiling::Auto, true},
                          Case{true, fx::Tiling::Off, true}}) {
        SCOPED_TRACE(testing::Message() << "tiled " << c.tiled << ", tiling " << int(c.tiling));
        direct.settings.options.tiled = c.tiled;
        direct.settings.options.tiling = c.tiling;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
        EXPECT_GE(drawn, 2);
        EXPECT_EQ(graph.ran(fx::TiledPath::kPass), c.expectTiled);
        EXPECT_EQ(graph.ran(fx::ParticleRenderer::kFullResPass), !c.expectTiled);
    }
}

}  // namespace tiled_path_test
}  // namespace fxtest
