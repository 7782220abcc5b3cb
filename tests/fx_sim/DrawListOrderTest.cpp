// DrawListBuilder culls a pool and sorts only what it draws. The order must be the one sorting
// the whole pool back to front and then culling gives (the sort is stable, so culling first
// cannot change it), with ties, culled particles, zero sizes and faded-out ones in the pool.
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "DrawListScene.h"

namespace {

using drawlist_test::Scene;
using drawlist_test::expectDrawn;

TEST(DrawListOrder, CullingBeforeSortingGivesTheWholePoolSortOrder) {
    const Scene s;
    const std::vector<uint32_t> expected = s.reference(true);
    // The scene culls a good part of the pool and keeps most of it: both sides are exercised.
    ASSERT_GT(expected.size(), 1000u);
    ASSERT_LT(expected.size(), 2700u);
    const fx::ParticleBatch batch = s.batch(true);
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list);
    expectDrawn(s, list, expected);
    ASSERT_EQ(list.batches.size(), 1u);
    EXPECT_EQ(list.batches[0].count, int(expected.size()));
    // Back to front: the camera looks down -z, so z never decreases along the list.
    for (int k = 1; k < list.particleCount(); ++k) ASSERT_GE(list.instances[k].z, list.instances[k - 1].z);
}

TEST(DrawListOrder, UnsortedBatchesKeepPoolOrderAndBatchesFollowEachOther) {
    const Scene s;
    const fx::ParticleBatch batches[2] = {s.batch(false), s.batch(true)};
    fx::DrawListBuilder builder;
    fx::DrawList list;
    // Twice: the builder's scratch from the first build must not leak into the second.
    for (int round = 0; round < 2; ++round) {
        builder.build(s.view, batches, 2, fx::Technique::FromReaction, ~0u, &list);
        std::vector<uint32_t> expected = s.reference(false);
        const std::vector<uint32_t> sorted = s.reference(true);
        expected.insert(expected.end(), sorted.begin(), sorted.end());
        expectDrawn(s, list, expected);
        ASSERT_EQ(list.batches.size(), 2u);
        EXPECT_EQ(list.batches[1].first, list.batches[0].count);
    }
}

TEST(DrawListOrder, SeeingMoreOfThePoolThanBeforeAllocatesNothing) {
#if !defined(__GLIBC__)
    GTEST_SKIP() << "counts the heap with glibc's mallinfo2";
#else
    Scene s;
    const fx::ParticleBatch batch = s.batch(true);
    fx::DrawList list;
    {
        fx::DrawListBuilder warm;  // the list's own capacity, for the whole view
        warm.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list);
    }
    fx::ViewInfo narrow = s.view;
    narrow.proj = glm::perspective(glm::radians(5.0f), 16.0f / 9.0f, 0.1f, 500.0f);
    fx::DrawListBuilder builder;
    builder.build(narrow, &batch, 1, fx::Technique::FromReaction, ~0u, &list);
    const int few = list.particleCount();
    const size_t before = mallinfo2().uordblks;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list);
    const size_t after = mallinfo2().uordblks;
    ASSERT_LT(few * 4, list.particleCount());  // the second view saw far more of the pool
    EXPECT_EQ(before, after);
#endif
}

}  // namespace
