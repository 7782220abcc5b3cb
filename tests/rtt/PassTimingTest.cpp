// Per-pass GPU timings land on the frame they measure. fxbench renders the same pass names in
// interleaved modes; results that arrive frames late used to be filed under whichever mode was
// current (on an H100: hard's particle pass 2.95 ms, soft's 1.73 ms, while soft's frame was
// 1.74 ms longer). FrameGraph::resolveTimings, which Game::RenderFrame calls after its glFinish,
// gives each frame its own results.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "GlTestContext.h"
#include "RttTestUtil.h"
#include "rtt/FrameGraph.h"
#include "rtt/RenderTargetPool.h"

using namespace cube;
using namespace cube::rtt;

namespace {

class PassTimingTest : public test::GlTest {};

// Frames alternate between a heavy and a light version of the same pass "work" (as two modes
// do), with GL timer queries forced on. After resolveTimings every frame's sample must be its
// own: the heavy frames' samples all above the light frames'.
TEST_F(PassTimingTest, AlternatingModesGetTheirOwnGpuTimes) {
    RenderTargetPool pool;
    FrameGraph graph(pool, false, TimingMode::GpuTimerQuery);
    std::vector<double> heavy, light;
    for (int frame = 0; frame < 16; ++frame) {
        const bool isHeavy = frame % 2 == 0;
        graph.reset();
        pool.beginFrame();
        auto big = graph.create("big", testutil::fixed(1024, 1024));
        graph.addPass("work", 0, {}, {big}, [&](PassContext& ctx) {
            // Clearing a 1024x1024 target costs a few ms on any renderer; the light mode clears once.
            for (int i = 0; i < (isHeavy ? 40 : 1); ++i) ctx.clear(big);
        });
        graph.addPass("present", 1, {big}, {}, [](PassContext&) {}, true);
        ASSERT_TRUE(graph.compile());
        ASSERT_TRUE(graph.execute());
        glFinish();
        graph.resolveTimings();
        pool.endFrame();
        const PassTiming& t = graph.report().timings[0];
        ASSERT_EQ(t.name, "work");
        ASSERT_GT(t.samples, 0) << "frame " << frame << ": no GPU result after resolveTimings";
        (isHeavy ? heavy : light).push_back(t.lastMs);
    }
    ASSERT_EQ(heavy.size(), 8u);
    const double heavyMin = *std::min_element(heavy.begin(), heavy.end());
    const double lightMax = *std::max_element(light.begin(), light.end());
    EXPECT_GT(heavyMin, lightMax) << "a light frame was given a heavy frame's time, or the reverse";
    EXPECT_EQ(graph.timer().droppedFrames(), 0);
}

}  // namespace
