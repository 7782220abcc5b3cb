// FrameGraph on OSMesa: culling, order keys, target lifetimes, shared depth (prepass-EQUAL),
// timing method and the report.
#include <gtest/gtest.h>

#include "PassChecks.h"

#include <memory>
#include <string>
#include <vector>

#include "GlTestContext.h"
#include "RttTestUtil.h"
#include "rtt/Blit.h"
#include "rtt/FrameGraph.h"
#include "rtt/Readback.h"
#include "rtt/RenderTargetPool.h"

namespace cube::rtt {
namespace {

using testutil::fixed;

using testutil::TestProgram;

class FrameGraphTest : public test::GlTest {
protected:
    void SetUp() override {
        test::GlTest::SetUp();
        if (HasFatalFailure()) return;
        poolStorage_ = std::make_unique<RenderTargetPool>();
        graphStorage_ = std::make_unique<FrameGraph>(*poolStorage_, true);
    }
    void TearDown() override {
        graphStorage_.reset();
        poolStorage_.reset();
        test::GlTest::TearDown();
    }
    RenderTargetPool& pool() { return *poolStorage_; }
    FrameGraph& graph() { return *graphStorage_; }

private:
    std::unique_ptr<RenderTargetPool> poolStorage_;
    std::unique_ptr<FrameGraph> graphStorage_;
};

ClearValues clearTo(float r, float g, float b, float a) {
    ClearValues cv;
    cv.color[0] = {r, g, b, a};
    return cv;
}

TEST_F(FrameGraphTest, PassNobodyReadsIsCulledAndItsTargetNeverCreated) {
    bool executed = false, presented = false;
    auto unused = graph().create("unused", fixed(8, 8));
    auto color = graph().create("color", fixed(8, 8));
    graph().addPass("orphan", 10, [&](PassBuilder& b) { b.write(unused); },
                  [&](PassContext&) { executed = true; });
    graph().addPass("draw", 20, [&](PassBuilder& b) { b.write(color); },
                  [&](PassContext& ctx) { ctx.clear(color, clearTo(1, 0, 0, 1)); });
    graph().addPass("present", 30, [&](PassBuilder& b) { b.read(color); b.sideEffect(); },
                  [&](PassContext&) { presented = true; });
    ASSERT_TRUE(graph().compile()) << graph().report().error;
    EXPECT_TRUE(passCulled(graph(), "orphan"));
    // A name never declared is neither kept nor culled: the checks by name fail on it.
    EXPECT_FALSE(graph().declared("orphan_renamed"));
    EXPECT_FALSE(passCulled(graph(), "orphan_renamed"));
    EXPECT_FALSE(passKept(graph(), "orphan_renamed"));
    ASSERT_TRUE(graph().execute()) << graph().report().error;
    EXPECT_FALSE(executed);
    EXPECT_TRUE(presented);
    EXPECT_EQ(pool().stats().totalAllocations, 1u);  // "color" only
    EXPECT_EQ(graph().report().culled, std::vector<std::string>{"orphan"});
    EXPECT_EQ(graph().report().executed, (std::vector<std::string>{"draw", "present"}));
}

TEST_F(FrameGraphTest, CullingIsTransitive) {
    std::vector<std::string> ran;
    auto a = graph().create("a", fixed(4, 4));
    auto b = graph().create("b", fixed(4, 4));
    graph().addPass("writeA", 0, {}, {a}, [&](PassContext&) { ran.push_back("writeA"); });
    graph().addPass("aToB", 1, {a}, {b}, [&](PassContext&) { ran.push_back("aToB"); });  // b: no reader
    graph().addPass("marker", 2, {}, {}, [&](PassContext&) { ran.push_back("marker"); }, true);
    ASSERT_TRUE(graph().compile());
    ASSERT_TRUE(graph().execute());
    EXPECT_EQ(ran, std::vector<std::string>{"marker"});  // a side-effect pass with no targets stays
    EXPECT_EQ(pool().stats().totalAllocations, 0u);
}

TEST_F(FrameGraphTest, ChainAToBToPresentRunsAndCarriesPixels) {
    std::vector<std::string> ran;
    auto a = graph().create("a", fixed(8, 8));
    auto b = graph().create("b", fixed(4, 4));
    std::vector<uint8_t> result;
    graph().addPass("A", 0, {}, {a}, [&](PassContext& ctx) {
        ran.push_back("A");
        ctx.clear(a, clearTo(0, 1, 0, 1));
    });
    graph().addPass("B", 1, {a}, {b}, [&](PassContext& ctx) {
        ran.push_back("B");
        EXPECT_EQ(blitColor(ctx.pool(), ctx.handle(a), 0, ctx.handle(b), 0), RttError::None);
    });
    graph().addPass("present", 2, [&](PassBuilder& pb) { pb.read(b); pb.sideEffect(); }, [&](PassContext& ctx) {
        ran.push_back("present");
        EXPECT_EQ(ctx.width(b), 4);
        readRGBA8(ctx.pool(), ctx.handle(b), 0, &result);
    });
    ASSERT_TRUE(graph().compile());
    ASSERT_TRUE(graph().execute());
    EXPECT_EQ(ran, (std::vector<std::string>{"A", "B", "present"}));
    ASSERT_EQ(result.size(), 64u);
    EXPECT_EQ(result[1], 255);
    EXPECT_EQ(result[0], 0);
}

TEST_F(FrameGraphTest, PassesRunByOrderKeyThenDeclarationIndex) {
    std::vector<std::string> ran;
    auto log = [&](const char* name) { return [&ran, name](PassContext&) { ran.push_back(name); }; };
    graph().addPass("sky", 300, {}, {}, log("sky"), true);
    graph().addPass("opaque", 200, {}, {}, log("opaque"), true);
    graph().addPass("particles_a", 400, {}, {}, log("particles_a"), true);
    graph().addPass("prepass", 100, {}, {}, log("prepass"), true);
    graph().addPass("particles_b", 400, {}, {}, log("particles_b"), true);
    graph().addPass("hud", 900, {}, {}, log("hud"), true);
    ASSERT_TRUE(graph().compile());
    ASSERT_TRUE(graph().execute());
    EXPECT_EQ(ran, (std::vector<std::string>{"prepass", "opaque", "sky", "particles_a", "particles_b", "hud"}));
    EXPECT_EQ(graph().report().executed, ran);
}

TEST_F(FrameGraphTest, TargetsLiveFromFirstWriterToLastReaderAndAliasLaterTargets) {
    std::vector<int> inUse;
    auto t1 = graph().create("t1", fixed(8, 8));
    auto t2 = graph().create("t2", fixed(8, 8, ColorFormat::R32F));
    auto t3 = graph().create("t3", fixed(8, 8));  // same shape as t1, first used after t1 died
    auto probe = [&](PassContext&) { inUse.push_back(pool().stats().targetsInUse); };
    graph().addPass("nothingYet", 0, {}, {}, probe, true);
    graph().addPass("w1", 1, {}, {t1}, probe);
    graph().addPass("r1w2", 2, {t1}, {t2}, probe);
    graph().addPass("r2w3", 3, {t2}, {t3}, probe);
    graph().addPass("r3", 4, [&](PassBuilder& b) { b.read(t3); b.sideEffect(); }, probe);
    ASSERT_TRUE(graph().compile());
    ASSERT_TRUE(graph().execute());
    EXPECT_EQ(inUse, (std::vector<int>{0, 1, 2, 2, 1}));
    EXPECT_EQ(pool().stats().targetsInUse, 0);       // all released after the frame
    EXPECT_EQ(pool().stats().totalAllocations, 2u);  // t3 reused t1's GL objects
    EXPECT_EQ(graph().report().targetsAcquired, 3);
}

TEST_F(FrameGraphTest, PersistentImportKeepsItsWritersAndIsNeverReleased) {
    RenderTargetHandle scene = pool().acquire(fixed(8, 8));
    bool drew = false, drewTemp = false;
    auto sceneRes = graph().import("scene_color", scene, true);
    auto tempRes = graph().import("temp", scene);  // non-persistent: writers need readers
    graph().addPass("draw", 0, {}, {sceneRes}, [&](PassContext& ctx) {
        drew = true;
        EXPECT_TRUE(ctx.bindForDraw(sceneRes));
    });
    graph().addPass("drawTemp", 1, {}, {tempRes}, [&](PassContext&) { drewTemp = true; });
    ASSERT_TRUE(graph().compile());
    ASSERT_TRUE(graph().execute());
    EXPECT_TRUE(drew);
    EXPECT_FALSE(drewTemp);
    EXPECT_TRUE(pool().isValid(scene));
}

TEST_F(FrameGraphTest, ReportCountsAllocationsPerFrameAndTimesPassesOnTheCpu) {
    EXPECT_STREQ(graph().timingMethod(), "cpu-glfinish");
    for (int frame = 0; frame < 3; ++frame) {
        pool().beginFrame();
        graph().reset();
        auto a = graph().create("a", fixed(8, 8));
        auto b = graph().create("b", fixed(8, 8, ColorFormat::RG32F));
        graph().addPass("A", 0, {}, {a}, [&](PassContext& ctx) { ctx.clear(a); });
        graph().addPass("B", 1, {a}, {b}, [&](PassContext& ctx) { ctx.clear(b); });
        graph().addPass("out", 2, {b}, {}, [](PassContext&) {}, true);
        ASSERT_TRUE(graph().compile());
        ASSERT_TRUE(graph().execute());
        pool().endFrame();
        const FrameGraphReport& r = graph().report();
        EXPECT_EQ(r.targetsAllocatedThisFrame, frame == 0 ? 2 : 0) << frame;
        EXPECT_EQ(r.targetsLive, 2);
        EXPECT_EQ(r.targetsAcquired, 2);
        EXPECT_STREQ(r.timingMethod, "cpu-glfinish");
        ASSERT_EQ(r.timings.size(), 3u);
        for (const PassTiming& t : r.timings) {
            EXPECT_GE(t.lastMs, 0.0) << t.name;
            EXPECT_GE(t.medianMs, 0.0) << t.name;
            EXPECT_EQ(t.samples, frame + 1) << t.name;
        }
    }
    std::vector<float> history;
    graph().timer().history("B", &history);
    EXPECT_EQ(history.size(), 3u);
}

TEST_F(FrameGraphTest, TimingMethodFollowsTheRendererAndCanBeForced) {
    FrameGraph hardware(pool(), false);
    EXPECT_STREQ(hardware.timingMethod(), "gpu-timer-query");
    FrameGraph forced(pool(), false, TimingMode::CpuGlFinish);
    EXPECT_STREQ(forced.timingMethod(), "cpu-glfinish");
    FrameGraph off(pool(), true, TimingMode::Off);
    EXPECT_STREQ(off.timingMethod(), "off");
}

TEST_F(FrameGraphTest, GpuTimerQueriesAreReadBackInALaterFrame) {
    // llvmpipe implements timer queries; the figures mean nothing, the plumbing is what is tested.
    FrameGraph gpu(pool(), false);
    int framesWithResult = -1;
    for (int frame = 0; frame < 12; ++frame) {
        gpu.reset();
        auto a = gpu.create("a", fixed(8, 8));
        gpu.addPass("A", 0, {}, {a}, [&](PassContext& ctx) { ctx.clear(a); });
        gpu.addPass("B", 1, {a}, {}, [](PassContext&) {}, true);
        ASSERT_TRUE(gpu.compile());
        ASSERT_TRUE(gpu.execute());
        if (framesWithResult < 0 && gpu.report().timings[0].samples > 0) framesWithResult = frame;
        glFinish();  // stands in for the frame time: the GPU is done before the next frame
    }
    EXPECT_EQ(framesWithResult, 1);  // read back the next frame, never in the same one
    EXPECT_EQ(gpu.timer().droppedFrames(), 0);
    for (const PassTiming& t : gpu.report().timings) {
        EXPECT_GE(t.lastMs, 0.0);
        EXPECT_GT(t.samples, 0);
    }
}

// The thesis's prepass-EQUAL: the opaque target shares the prepass z-buffer and draws with
// depth test EQUAL and no depth writes; only what the prepass laid down passes.
TEST_F(FrameGraphTest, SharedDepthLetsOpaqueDrawWithDepthEqualOnThePrepassZ) {
    TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    TestProgram copier(testutil::kVsQuad, testutil::kFsCopyDepth);
    pool().setViewSize(8, 8);
    FrameGraph::TargetDesc depthDesc;
    depthDesc.color[0] = ColorFormat::R32F;  // linear view depth
    depthDesc.depth = DepthFormat::Depth24;  // the z-buffer, sampled below
    depthDesc.filter = Filter::Nearest;
    auto sceneDepth = graph().create("scene_depth", depthDesc);
    FrameGraph::TargetDesc colorDesc;        // relative, like the depth: same size rule
    colorDesc.sharedDepthOf = sceneDepth;
    auto sceneColor = graph().create("scene_color", colorDesc);
    auto depthCopy = graph().create("depth_copy", fixed(8, 8, ColorFormat::R32F));
    std::vector<uint8_t> color;
    std::vector<float> linear, copied;

    graph().addPass("depth_prepass", 100, [&](PassBuilder& b) { b.write(sceneDepth); }, [&](PassContext& ctx) {
        ctx.clear(sceneDepth, clearTo(1000.0f, 0, 0, 0));
        ctx.bindForDraw(sceneDepth);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        prog.set("uColor0", 7.5f, 0, 0, 0);
        prog.drawQuad(-1, -1, 0, 1, 0.25f);  // left half at NDC z 0.25
        glDisable(GL_DEPTH_TEST);
    });
    graph().addPass("opaque", 200, [&](PassBuilder& b) { b.write(sceneColor); }, [&](PassContext& ctx) {
        ClearValues cv = clearTo(0, 0, 0, 1);
        cv.clearDepth = false;  // the prepass z-buffer is the depth
        ctx.clear(sceneColor, cv);
        ctx.bindForDraw(sceneColor);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_EQUAL);
        glDepthMask(GL_FALSE);
        prog.set("uColor0", 1, 0, 0, 1);
        prog.drawQuad(-1, -1, 1, 1, 0.25f);  // whole screen, same depth
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
    });
    graph().addPass("copy_depth", 300,
                  [&](PassBuilder& b) { b.readDepth(sceneDepth); b.readDepth(sceneColor); b.write(depthCopy); },
                  [&](PassContext& ctx) {
                      ASSERT_NE(ctx.depthTexture(sceneDepth), 0u);
                      EXPECT_EQ(ctx.depthTexture(sceneDepth), ctx.depthTexture(sceneColor));
                      ctx.bindForDraw(depthCopy);
                      glBindTexture(GL_TEXTURE_2D, ctx.depthTexture(sceneDepth));
                      copier.setInt("uDepth", 0);
                      copier.drawQuad();
                      glBindTexture(GL_TEXTURE_2D, 0);
                  });
    graph().addPass("readback", 400,
                  [&](PassBuilder& b) { b.read(sceneColor); b.read(sceneDepth); b.read(depthCopy); b.sideEffect(); },
                  [&](PassContext& ctx) {
                      readRGBA8(ctx.pool(), ctx.handle(sceneColor), 0, &color);
                      readFloat(ctx.pool(), ctx.handle(sceneDepth), 0, FloatLayout::Native, &linear);
                      readFloat(ctx.pool(), ctx.handle(depthCopy), 0, FloatLayout::Native, &copied);
                  });
    ASSERT_TRUE(graph().compile()) << graph().report().error;
    ASSERT_TRUE(graph().execute()) << graph().report().error;
    EXPECT_EQ(graph().report().executed.size(), 4u);
    ASSERT_EQ(color.size(), 8u * 8u * 4u);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            const size_t i = (size_t(y) * 8u + size_t(x));
            const bool left = x < 4;
            EXPECT_EQ(color[i * 4], left ? 255 : 0) << x << "," << y;
            EXPECT_EQ(linear[i], left ? 7.5f : 1000.0f) << x << "," << y;
            EXPECT_NEAR(copied[i], left ? 0.625f : 1.0f, 4.0f / 16777215.0f) << x << "," << y;
        }
    }
}

TEST_F(FrameGraphTest, SharingTheDepthKeepsThePrepassAndNotSharingLetsItBeCulled) {
    for (bool share : {true, false}) {
        graph().reset();
        bool prepassRan = false;
        FrameGraph::TargetDesc depthDesc;
        depthDesc.width = depthDesc.height = 8;
        depthDesc.color[0] = ColorFormat::R32F;
        depthDesc.depth = DepthFormat::Depth24;
        auto sceneDepth = graph().create("scene_depth", depthDesc);
        FrameGraph::TargetDesc colorDesc;
        colorDesc.width = colorDesc.height = 8;
        if (share)
            colorDesc.sharedDepthOf = sceneDepth;
        else
            colorDesc.depth = DepthFormat::Depth24;
        auto sceneColor = graph().create("scene_color", colorDesc);
        graph().addPass("depth_prepass", 100, {}, {sceneDepth}, [&](PassContext&) { prepassRan = true; });
        graph().addPass("opaque", 200, {}, {sceneColor}, [&](PassContext& ctx) { ctx.bindForDraw(sceneColor); });
        graph().addPass("present", 900, {sceneColor}, {}, [](PassContext&) {}, true);
        ASSERT_TRUE(graph().compile()) << graph().report().error;
        ASSERT_TRUE(graph().execute()) << graph().report().error;
        EXPECT_EQ(prepassRan, share);
    }
}

// How a host can decide after the plugin declared its passes: scene colour is declared with a
// depth of its own, and switched to the prepass z-buffer only when someone reads scene depth.
TEST_F(FrameGraphTest, SharedDepthCanBeDecidedAfterThePassesAreDeclared) {
    for (bool particlesReadDepth : {false, true}) {
        graph().reset();
        std::vector<std::string> ran;
        auto log = [&ran](const char* name) { return [&ran, name](PassContext&) { ran.push_back(name); }; };
        RenderTargetDesc depthDesc = fixed(8, 8, ColorFormat::R32F, DepthFormat::Depth24);
        auto sceneDepth = graph().create("scene_depth", depthDesc);
        auto sceneColor = graph().create("scene_color", fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24));
        graph().addPass("depth_prepass", 100, {}, {sceneDepth}, log("depth_prepass"));
        graph().addPass("opaque", 200, {}, {sceneColor}, log("opaque"));
        if (particlesReadDepth)
            graph().addPass("particles", 400, [&](PassBuilder& b) { b.read(sceneDepth); b.write(sceneColor); },
                            log("particles"));
        graph().addPass("present", 900, {sceneColor}, {}, log("present"), true);
        if (particlesReadDepth) graph().setSharedDepth(sceneColor, sceneDepth);  // prepass-EQUAL on
        ASSERT_TRUE(graph().compile()) << graph().report().error;
        ASSERT_TRUE(graph().execute()) << graph().report().error;
        if (particlesReadDepth)
            EXPECT_EQ(ran, (std::vector<std::string>{"depth_prepass", "opaque", "particles", "present"}));
        else
            EXPECT_EQ(ran, (std::vector<std::string>{"opaque", "present"}));
    }
}

// The frame in pipeline order: passes declared top to bottom, and compile() picks
// who writes the linear scene depth. The prepass only offers it (writeIfRead), the opaque and
// alpha-tested passes offer it as a second render target, the colour target takes the
// prepass's z-buffer only if the prepass runs (sharedDepthIfWritten). Nobody reading it: no
// prepass, no offer taken, no depth target allocated.
TEST_F(FrameGraphTest, CompilePicksWhoWritesSceneDepthFromWhoReadsIt) {
    struct Case {
        bool prepass, reader;
    };
    for (const Case c : {Case{true, false}, Case{false, false}, Case{false, true}, Case{true, true}}) {
        SCOPED_TRACE(std::string(c.prepass ? "prepass" : "no prepass") + (c.reader ? ", read" : ", not read"));
        RenderTargetPool pool;  // this case's own, so its allocation count is exact
        FrameGraph graph(pool, true);
        auto sceneDepth = graph.create("scene_depth", fixed(8, 8, ColorFormat::R32F, DepthFormat::Depth24));
        FrameGraph::TargetDesc colorDesc;
        static_cast<RenderTargetDesc&>(colorDesc) = fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24);
        colorDesc.sharedDepthIfWritten = sceneDepth;
        auto color = graph.create("scene_color", colorDesc);
        bool prepassRan = false, opaqueRan = false, opaqueWrites = false, alphaWrites = false, shares = false;
        std::vector<float> depthRead;
        const RenderTargetDesc *depthDescUsed = nullptr, *colorDescUsed = nullptr;
        RenderTargetDesc depthSeen, colorSeen;
        if (c.prepass)
            graph.addPass("prepass", 10, [&](PassBuilder& b) { b.writeIfRead(sceneDepth); }, [&](PassContext& ctx) {
                prepassRan = true;
                EXPECT_TRUE(ctx.isNeeded(sceneDepth));
                ctx.clear(sceneDepth, clearTo(7, 0, 0, 0));
            });
        graph.addPass("opaque", 20, [&](PassBuilder& b) { b.write(color); b.writeIfRead(sceneDepth); },
                      [&](PassContext& ctx) {
                          opaqueRan = true;
                          opaqueWrites = ctx.isNeeded(sceneDepth);
                          shares = ctx.sharesDepth(color);
                          ClearValues cv = clearTo(0, 0, 0, 1);
                          cv.clearDepth = !shares;
                          ctx.clear(color, cv);
                          if (opaqueWrites) ctx.clear(sceneDepth, clearTo(3, 0, 0, 0));
                      });
        graph.addPass("alpha_tested", 30, [&](PassBuilder& b) { b.write(color); b.writeIfRead(sceneDepth); },
                      [&](PassContext& ctx) { alphaWrites = ctx.isNeeded(sceneDepth); });
        if (c.reader)
            graph.addPass("particles", 50, [&](PassBuilder& b) { b.read(sceneDepth); b.write(color); },
                          [&](PassContext& ctx) {
                              readFloat(ctx.pool(), ctx.handle(sceneDepth), 0, FloatLayout::Native, &depthRead);
                              if ((depthDescUsed = ctx.pool().desc(ctx.handle(sceneDepth)))) depthSeen = *depthDescUsed;
                          });
        graph.addPass("present", 90, [&](PassBuilder& b) { b.read(color); b.sideEffect(); },
                      [&](PassContext& ctx) {
                          if ((colorDescUsed = ctx.pool().desc(ctx.handle(color)))) colorSeen = *colorDescUsed;
                      });
        ASSERT_TRUE(graph.compile()) << graph.report().error;
        ASSERT_TRUE(graph.execute()) << graph.report().error;

        EXPECT_TRUE(opaqueRan);
        EXPECT_TRUE(graph.report().culled.empty());
        ASSERT_NE(colorDescUsed, nullptr);
        if (!c.reader) {
            EXPECT_FALSE(prepassRan) << "nobody reads scene_depth: the prepass must not run";
            EXPECT_FALSE(opaqueWrites);
            EXPECT_FALSE(alphaWrites);
            EXPECT_FALSE(shares);
            EXPECT_EQ(pool.stats().totalAllocations, 1u) << "scene_depth must never be allocated";
            EXPECT_EQ(graph.report().targetsAcquired, 1);
            EXPECT_EQ(colorSeen.depth, DepthFormat::Depth24);  // its own z-buffer
            EXPECT_EQ(graph.report().notTaken,
                      c.prepass ? std::vector<std::string>{"prepass"} : std::vector<std::string>{});
            continue;
        }
        EXPECT_EQ(pool.stats().totalAllocations, 2u);
        EXPECT_TRUE(graph.report().notTaken.empty());
        ASSERT_NE(depthDescUsed, nullptr);
        ASSERT_EQ(depthRead.size(), 64u);
        if (c.prepass) {  // prepass-EQUAL: the prepass writes it, the colour target shares its z-buffer
            EXPECT_TRUE(prepassRan);
            EXPECT_FALSE(opaqueWrites);
            EXPECT_FALSE(alphaWrites);
            EXPECT_TRUE(shares);
            EXPECT_EQ(depthSeen.depth, DepthFormat::Depth24);
            EXPECT_EQ(colorSeen.depth, DepthFormat::None);  // no z-buffer of its own
            EXPECT_EQ(depthRead[0], 7.0f);
        } else {  // the opaque and alpha-tested passes write it as a second target, no z-buffer on it
            EXPECT_TRUE(opaqueWrites);
            EXPECT_TRUE(alphaWrites);
            EXPECT_FALSE(shares);
            EXPECT_EQ(depthSeen.depth, DepthFormat::None);
            EXPECT_EQ(colorSeen.depth, DepthFormat::Depth24);
            EXPECT_EQ(depthRead[0], 3.0f);
        }
    }
}

TEST_F(FrameGraphTest, CompileRejectsBrokenGraphsWithoutRunningAnything) {
    bool ran = false;
    auto run = [&](PassContext&) { ran = true; };
    // A bad descriptor, named with its code.
    graph().create("bad", fixed(16, 0));
    graph().addPass("p", 0, {}, {}, run, true);
    EXPECT_FALSE(graph().compile());
    EXPECT_NE(graph().report().error.find("InvalidSize"), std::string::npos) << graph().report().error;
    EXPECT_FALSE(graph().execute());
    // Reading what no earlier kept pass writes.
    graph().reset();
    auto t = graph().create("t", fixed(4, 4));
    graph().addPass("reader", 0, {t}, {}, run, true);
    graph().addPass("writer", 1, {}, {t}, run);
    EXPECT_FALSE(graph().compile());
    EXPECT_NE(graph().report().error.find("no earlier kept pass writes"), std::string::npos);
    // A kept pass writing a 4x4 target `name` that shares the depth of `owner`.
    auto writeSharer = [&](const char* name, FrameGraphResource owner) {
        FrameGraph::TargetDesc sharer;
        sharer.width = sharer.height = 4;
        sharer.sharedDepthOf = owner;
        graph().addPass("w", 0, {}, {graph().create(name, sharer)}, run, true);
    };
    // Sharing the depth of a target without depth.
    graph().reset();
    writeSharer("sharer", graph().create("no_depth", fixed(4, 4)));
    EXPECT_FALSE(graph().compile());
    // Sharing the depth of a target with a different size rule.
    graph().reset();
    writeSharer("sharer4", graph().create("owner", fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24)));
    EXPECT_FALSE(graph().compile());
    EXPECT_NE(graph().report().error.find("SharedDepthSizeMismatch"), std::string::npos);
    // A stale import.
    graph().reset();
    RenderTargetHandle h = pool().acquire(fixed(4, 4));
    pool().release(h);
    auto imported = graph().import("stale", h);
    graph().addPass("w", 0, {}, {imported}, run, true);
    EXPECT_FALSE(graph().compile());
    EXPECT_FALSE(ran);
    EXPECT_EQ(pool().stats().targetsInUse, 0);
}

TEST_F(FrameGraphTest, AllocationFailureSkipsThePassesThatNeedTheTarget) {
    bool ranA = false, ranB = false;
    auto a = graph().create("a", fixed(4, 4));
    auto b = graph().create("b", fixed(4, 4, ColorFormat::R32F));
    graph().addPass("A", 0, {}, {a}, [&](PassContext&) { ranA = true; }, true);
    graph().addPass("B", 1, {}, {b}, [&](PassContext&) { ranB = true; }, true);
    ASSERT_TRUE(graph().compile());
    pool().failNextCreateForTesting(RttError::FramebufferIncomplete);  // hits "a"
    EXPECT_FALSE(graph().execute());
    EXPECT_FALSE(ranA);
    EXPECT_TRUE(ranB);
    EXPECT_NE(graph().report().error.find("FramebufferIncomplete"), std::string::npos) << graph().report().error;
    EXPECT_EQ(graph().report().culled, std::vector<std::string>{"A"});
}

TEST_F(FrameGraphTest, MinimisedViewRunsOnOnePixelTargets) {
    pool().setViewSize(0, 0);
    RenderTargetDesc half;
    half.scale = 0.5f;
    auto t = graph().create("half", half);
    int w = 0, h = 0;
    graph().addPass("draw", 0, {}, {t}, [&](PassContext& ctx) {
        w = ctx.width(t);
        h = ctx.height(t);
        ctx.clear(t);
    });
    graph().addPass("out", 1, {t}, {}, [](PassContext&) {}, true);
    ASSERT_TRUE(graph().compile());
    ASSERT_TRUE(graph().execute());
    EXPECT_EQ(w, 1);
    EXPECT_EQ(h, 1);
}

TEST_F(FrameGraphTest, ExecuteRestoresFramebufferAndViewportAfterEachPass) {
    auto t = graph().create("t", fixed(4, 2));
    GLint seen[2] = {-1, -1};
    glViewport(1, 2, 3, 4);
    graph().addPass("bind", 0, {}, {t}, [&](PassContext& ctx) { ctx.bindForDraw(t); });
    graph().addPass("check", 1, {t}, {}, [&](PassContext&) {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &seen[0]);
        GLint vp[4];
        glGetIntegerv(GL_VIEWPORT, vp);
        seen[1] = vp[2];
    }, true);
    ASSERT_TRUE(graph().compile());
    ASSERT_TRUE(graph().execute());
    EXPECT_EQ(seen[0], 0);
    EXPECT_EQ(seen[1], 3);
    glViewport(0, 0, platform().width(), platform().height());
}

// 10,000 frames of a small graph rebuilt every frame, with a view resize every 1,000: the pool

// With counting on, each pass reports the samples it wrote and, where the context has
// ARB_pipeline_statistics_query, the fragments it shaded: a quad over a 64 x 64 target whose
// shader discards the left half writes 32 x 64 samples and shades at least every pixel. A pass
// that draws nothing counts 0 of both; with counting off, both are -1.
TEST_F(FrameGraphTest, CountsTheSamplesEachPassWroteAndTheFragmentsItShaded) {
    static constexpr const char* kFsDiscardLeft = R"(#version 330 core
layout(location = 0) out vec4 o0;
void main() {
    if (gl_FragCoord.x < 32.0) discard;
    o0 = vec4(1.0);
}
)";
    TestProgram prog(testutil::kVsQuad, kFsDiscardLeft);
    for (const bool counting : {true, false}) {
        SCOPED_TRACE(counting ? "counting" : "not counting");
        graph().reset();
        pool().beginFrame();
        auto t = graph().create("t", fixed(64, 64));
        graph().addPass("half", 0, {}, {t}, [&](PassContext& ctx) {
            ctx.bindForDraw(t);
            prog.drawQuad();
        });
        graph().addPass("nothing", 1, {t}, {t}, [&](PassContext& ctx) { ctx.bindForDraw(t); });
        graph().addPass("present", 2, {t}, {}, [](PassContext&) {}, true);
        graph().setCountFragments(counting);
        ASSERT_TRUE(graph().compile());
        ASSERT_TRUE(graph().execute());
        graph().setCountFragments(false);
        pool().endFrame();
        const std::vector<PassTiming>& timings = graph().report().timings;
        ASSERT_EQ(timings.size(), 3u);
        ASSERT_EQ(timings[0].name, "half");
        ASSERT_EQ(timings[1].name, "nothing");
        if (!counting) {
            for (const PassTiming& p : timings) {
                EXPECT_EQ(p.fragments, -1);
                EXPECT_EQ(p.shaded, -1);
            }
            continue;
        }
        EXPECT_EQ(timings[0].fragments, 32 * 64);
        EXPECT_EQ(timings[1].fragments, 0);
        if (!GLAD_GL_ARB_pipeline_statistics_query) {
            EXPECT_EQ(timings[0].shaded, -1);
            continue;
        }
        // llvmpipe: 4352, the 4096 pixels and the 16 4x4 blocks on the quad's diagonal once more
        // (it shades whole 4x4 blocks, each triangle its own).
        std::printf("[ measured ] shaded %lld, written %lld\n", timings[0].shaded, timings[0].fragments);
        EXPECT_GE(timings[0].shaded, 64 * 64);  // the discarded half was shaded too
        EXPECT_EQ(timings[1].shaded, 0);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
// must keep the number of live GL objects flat and create nothing after the first frame.
TEST_F(FrameGraphTest, TenThousandFramesKeepGlObjectCountsFlat) {
    uint32_t maxTexture = 0, maxFramebuffer = 0;
    auto countLive = [&](int* textures, int* framebuffers) {
        *textures = *framebuffers = 0;
        for (GLuint id = 1; id <= maxTexture + 64; ++id) *textures += glIsTexture(id) ? 1 : 0;
        for (GLuint id = 1; id <= maxFramebuffer + 64; ++id) *framebuffers += glIsFramebuffer(id) ? 1 : 0;
    };
    int textures1000 = -1, framebuffers1000 = -1;
    RenderTargetPoolStats stats1000;
    uint64_t allocationsAfterFirstFrame = 0;
    int executedCount = 0;
    bool culledRan = false;
    for (int frame = 1; frame <= 10000; ++frame) {
        if (frame % 1000 == 1) pool().setViewSize(16 + (frame / 1000) % 2, 16 - (frame / 1000) % 3);
        pool().beginFrame();
        graph().reset();
        RenderTargetDesc full;
        full.color[0] = ColorFormat::RGBA8;
        full.depth = DepthFormat::Depth24;
        RenderTargetDesc half;
        half.scale = 0.5f;
        half.color[0] = ColorFormat::RGBA16F;
        auto scene = graph().create("scene", full);
        auto small = graph().create("small", half);
        auto unused = graph().create("unused", fixed(16, 16, ColorFormat::R32F));
        graph().addPass("scene", 0, {}, {scene}, [&](PassContext& ctx) {
            ctx.clear(scene);
            maxTexture = std::max(maxTexture, ctx.texture(scene));
            maxFramebuffer = std::max(maxFramebuffer, ctx.pool().framebuffer(ctx.handle(scene)));
        });
        graph().addPass("downsample", 1, {scene}, {small}, [&](PassContext& ctx) {
            blitColor(ctx.pool(), ctx.handle(scene), 0, ctx.handle(small), 0);
            maxTexture = std::max(maxTexture, ctx.texture(small));
            maxFramebuffer = std::max(maxFramebuffer, ctx.pool().framebuffer(ctx.handle(small)));
        });
        graph().addPass("orphan", 2, {}, {unused}, [&](PassContext&) { culledRan = true; });
        graph().addPass("present", 3, {small}, {}, [&](PassContext&) { ++executedCount; }, true);
        ASSERT_TRUE(graph().compile()) << frame;
        ASSERT_TRUE(graph().execute()) << frame;
        pool().endFrame();
        if (frame == 1) allocationsAfterFirstFrame = pool().stats().totalAllocations;
        if (frame == 1000) {
            countLive(&textures1000, &framebuffers1000);
            stats1000 = pool().stats();
        }
    }
    int textures = 0, framebuffers = 0;
    countLive(&textures, &framebuffers);
    const RenderTargetPoolStats stats = pool().stats();
    EXPECT_EQ(textures, textures1000);
    EXPECT_EQ(framebuffers, framebuffers1000);
    EXPECT_EQ(textures, 2);  // scene colour + small colour (scene depth is a renderbuffer)
    EXPECT_EQ(framebuffers, 2);
    EXPECT_EQ(stats.liveTextures, stats1000.liveTextures);
    EXPECT_EQ(stats.liveFramebuffers, stats1000.liveFramebuffers);
    EXPECT_EQ(stats.liveRenderbuffers, stats1000.liveRenderbuffers);
    EXPECT_EQ(stats.liveTextures, textures);
    EXPECT_EQ(stats.liveFramebuffers, framebuffers);
    EXPECT_EQ(stats.totalAllocations, allocationsAfterFirstFrame);
    EXPECT_EQ(stats.totalAllocations, 2u);
    EXPECT_GE(stats.reallocations, 9u * 2u);  // resizes re-specify storage in place
    EXPECT_EQ(executedCount, 10000);
    EXPECT_FALSE(culledRan);
}

}  // namespace
}  // namespace cube::rtt
