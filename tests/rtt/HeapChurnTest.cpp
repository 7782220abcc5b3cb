// A small graph rebuilt every frame must not churn the heap once warm: the graph keeps its
// storage across reset(), the pool hands back the same targets, the report reuses its strings.
// Counts operator new calls on this thread only (the driver's worker threads are not ours).
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>

#include "GlTestContext.h"
#include "rtt/Blit.h"
#include "rtt/FrameGraph.h"
#include "rtt/RenderTargetPool.h"

namespace {
thread_local bool t_counting = false;
thread_local long t_allocations = 0;
}  // namespace

#if defined(__SANITIZE_ADDRESS__)
#define CUBE_COUNT_ALLOCATIONS 0  // ASan owns operator new; replacing it mixes allocators
#else
#define CUBE_COUNT_ALLOCATIONS 1
// Replaces the global allocation functions for this test binary (plain, array and sized
// forms, so every new/delete pair matches); only counting is added. Not inlined: GCC's
// -Wmismatched-new-delete would otherwise see free() meet operator new at a call site.
[[gnu::noinline]] void* operator new(std::size_t size) {
    if (t_counting) ++t_allocations;
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace cube::rtt {
namespace {

class HeapChurnTest : public test::GlTest {};

TEST_F(HeapChurnTest, SteadyFramesOfASmallGraphAllocateNothing) {
    if (!CUBE_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
    RenderTargetPool pool;
    pool.setViewSize(16, 16);
    FrameGraph graph(pool, true);
    long allocations = 0;
    for (int frame = 0; frame < 200; ++frame) {
        if (frame == 100) {  // warm: measure the next 100 frames
            t_allocations = 0;
            t_counting = true;
        }
        pool.beginFrame();
        graph.reset();
        RenderTargetDesc sceneDesc;
        sceneDesc.depth = DepthFormat::Depth24;
        sceneDesc.name = "a_name_longer_than_small_string_storage";
        RenderTargetDesc quarterDesc;
        quarterDesc.scale = 0.25f;
        quarterDesc.color[0] = ColorFormat::RGBA16F;
        FrameGraph::TargetDesc sharerDesc;
        sharerDesc.sharedDepthOf = FrameGraphResource{1};
        auto scene = graph.create("scene_color_with_a_long_debug_name", sceneDesc);
        auto sharer = graph.create("sharer", sharerDesc);
        auto quarter = graph.create("quarter", quarterDesc);
        auto unused = graph.create("unused", quarterDesc);
        graph.addPass("opaque_pass_with_a_long_name", 0, {}, {scene}, [&](PassContext& ctx) { ctx.clear(scene); });
        graph.addPass("overlay", 1, {}, {sharer}, [&](PassContext& ctx) { ctx.clear(sharer); });
        graph.addPass("downsample", 2, [&](PassBuilder& b) { b.read(sharer); b.write(quarter); },
                      [&](PassContext& ctx) { blitColor(ctx.pool(), ctx.handle(sharer), 0, ctx.handle(quarter), 0); });
        graph.addPass("culled", 3, {}, {unused}, [&](PassContext& ctx) { ctx.clear(unused); });
        graph.addPass("present", 4, [&](PassBuilder& b) { b.read(quarter); b.sideEffect(); }, [](PassContext&) {});
        ASSERT_TRUE(graph.compile()) << graph.report().error;
        ASSERT_TRUE(graph.execute()) << graph.report().error;
        pool.endFrame();
    }
    t_counting = false;
    allocations = t_allocations;
    EXPECT_EQ(allocations, 0) << "operator new calls in 100 steady frames";
    EXPECT_EQ(pool.stats().totalAllocations, 3u);
    EXPECT_EQ(graph.report().executed.size(), 4u);
}

}  // namespace
}  // namespace cube::rtt
