// DrawListBuilder culls a pool and sorts only what it draws. The order must be the one sorting
// the whole pool back to front and then culling gives (the sort is stable, so culling first
// cannot change it), with ties, culled particles, zero sizes and faded-out ones in the pool.
#include <cmath>
#include <limits>
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

namespace {

// ViewFrustum::intersectsSpheres4 (the cull's four lanes) against intersectsSphere one at a time,
// for spheres inside, outside and straddling each plane, right on them, and not finite in each
// component; under a finite and an infinite reversed-Z far plane. And the build keeps the same
// particles with such values in its pool as the one-lane reference does.
TEST(DrawListOrder, FourSpheresAtATimeGiveTheAnswersOneAtATimeGives) {
#if FX_SSE2
    Scene s;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float odd[] = {nan, inf, -inf, 0.0f, -0.0f, 1e30f, -1e30f};
    for (int projection = 0; projection < 2; ++projection) {
        glm::mat4 proj = s.view.proj;
        if (projection == 1) {
            proj[2][2] = 0.0f;  // reversed-Z, infinite far plane
            proj[3][2] = s.view.nearPlane;
        }
        const fx::ViewFrustum frustum(s.view.view, proj, s.view.nearPlane, s.view.farPlane);
        int in = 0, out = 0;
        for (int group = 0; group < 20000; ++group) {
            alignas(16) float x[4], y[4], z[4], r[4];
            for (int k = 0; k < 4; ++k) {
                // Across the frustum's side planes (slopes up to 1.2 and 0.7), 0.04-720 m away
                // (a fifth of them 50 times closer), radii 0-5 m.
                const float depth = std::exp2(u(rng) * 7.0f + 2.5f) * (group % 5 == 0 ? 0.02f : 1.0f);
                x[k] = depth * 1.2f * u(rng);
                y[k] = 1.0f + depth * 0.7f * u(rng);
                z[k] = -depth;
                r[k] = group % 7 == 0 ? 0.0f : 5.0f * (0.5f + 0.5f * u(rng));
                if (group % 11 == 0) {
                    const float v = odd[(group / 11 + k) % 7];
                    float* field[4] = {&x[k], &y[k], &z[k], &r[k]};
                    *field[(group / 77 + k) % 4] = v;
                }
            }
            const int mask = frustum.intersectsSpheres4(_mm_load_ps(x), _mm_load_ps(y), _mm_load_ps(z), _mm_load_ps(r));
            for (int k = 0; k < 4; ++k) {
                const bool one = frustum.intersectsSphere(glm::vec3(x[k], y[k], z[k]), r[k]);
                ASSERT_EQ(one, (mask >> k & 1) != 0) << "projection " << projection << ", sphere (" << x[k] << ", " << y[k]
                                                      << ", " << z[k] << ") r " << r[k];
                (one ? in : out) += 1;
            }
        }
        EXPECT_GT(in, 10000);  // both answers, many times
        EXPECT_GT(out, 10000);
    }
    // The build with such values in its pool: the reference's particles, the same bits.
    float* posX = s.pool.stream(fx::ParticlePool::PosX);
    float* size = s.pool.stream(fx::ParticlePool::Size);
    for (int i = 0; i < s.pool.alive(); i += 13) (i % 2 ? posX : size)[i] = odd[(i / 13) % 7];
    for (bool sort : {false, true}) {
        const fx::ParticleBatch batch = s.batch(sort);
        fx::DrawListBuilder builder;
        fx::DrawList list;
        builder.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list);
        expectDrawn(s, list, s.reference(sort));
    }
#else
    GTEST_SKIP() << "no SSE2 on this target: the cull runs one particle at a time only";
#endif
}

}  // namespace
