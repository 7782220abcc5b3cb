// DrawListBuilder culls a pool and sorts only what it draws. The order must be the one sorting
// the whole pool back to front and then culling gives (the sort is stable, so culling first
// cannot change it), with ties, culled particles, zero sizes and faded-out ones in the pool.
#include <random>
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "../../fx_plugin/render/DrawList.h"
#include "../../fx_plugin/render/ViewFrustum.h"

namespace {

struct Scene {
    fx::ParticlePool pool{3000};
    fx::ReactionDesc desc = fx::defaultReaction(fx::ReactionType::WheelSmoke);
    fx::ViewInfo view;
    Scene() {
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> across(-40.0f, 40.0f), ahead(-10.0f, 90.0f), unit(0.0f, 1.0f);
        for (int k = 0; k < 3000; ++k) {
            const int i = pool.spawn();
            // Every fourth particle shares a depth with the one before it (ties keep pool order).
            const float z = (k % 4 == 1) ? pool.stream(fx::ParticlePool::PosZ)[i - 1] : -ahead(rng);
            pool.stream(fx::ParticlePool::PosX)[i] = across(rng);
            pool.stream(fx::ParticlePool::PosY)[i] = unit(rng) * 6.0f;
            pool.stream(fx::ParticlePool::PosZ)[i] = z;
            pool.stream(fx::ParticlePool::Size)[i] = (k % 37 == 0) ? 0.0f : 0.2f + 2.0f * unit(rng);
            pool.stream(fx::ParticlePool::Life)[i] = unit(rng);
            pool.stream(fx::ParticlePool::Rotation)[i] = unit(rng);
            pool.stream(fx::ParticlePool::Fade)[i] = (k % 41 == 0) ? 0.0f : 0.1f + unit(rng);  // some above 1
            pool.frame()[i] = uint8_t(k);
        }
        view.eye = glm::vec3(0.0f, 1.0f, 0.0f);
        view.view = glm::lookAt(view.eye, glm::vec3(0.0f, 1.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        view.proj = glm::perspective(glm::radians(50.0f), 16.0f / 9.0f, 0.1f, 500.0f);
        view.width = 640;
        view.height = 360;
    }
    fx::ParticleBatch batch(bool sort) const {
        fx::ParticleBatch b;
        b.pool = &pool;
        b.desc = &desc;
        b.sortBackToFront = sort;
        return b;
    }
    // The pool indices drawn, in the order of sorting the whole pool (or pool order) and then culling.
    std::vector<uint32_t> reference(bool sort) const {
        fx::ParticleSorter sorter;
        const glm::vec3 forward(-view.view[0][2], -view.view[1][2], -view.view[2][2]);
        const fx::ParticleSorter::Order order = sorter.update(pool, view.eye, forward, sort);
        const fx::ViewFrustum frustum(view.view, view.proj, view.nearPlane, view.farPlane);
        std::vector<uint32_t> kept;
        for (int k = 0; k < order.count; ++k) {
            const uint32_t i = order.indices[k];
            const float size = pool.size()[i];
            if (!(size > 0.0f) || !(pool.fade()[i] > 0.0f)) continue;
            const glm::vec3 c(pool.posX()[i], pool.posY()[i], pool.posZ()[i]);
            if (frustum.intersectsSphere(c, size * 0.70710678f)) kept.push_back(i);
        }
        return kept;
    }
};

void expectDrawn(const Scene& s, const fx::DrawList& list, const std::vector<uint32_t>& expected) {
    ASSERT_EQ(list.particleCount(), int(expected.size()));
    for (size_t k = 0; k < expected.size(); ++k) {
        const uint32_t i = expected[k];
        const fx::ParticleInstance& p = list.instances[k];
        ASSERT_EQ(p.x, s.pool.posX()[i]) << "instance " << k;
        ASSERT_EQ(p.y, s.pool.posY()[i]) << "instance " << k;
        ASSERT_EQ(p.z, s.pool.posZ()[i]) << "instance " << k;
        ASSERT_EQ(p.size, s.pool.size()[i]) << "instance " << k;
        ASSERT_EQ(p.life, s.pool.life()[i]) << "instance " << k;
        ASSERT_EQ(p.rotation, s.pool.rotation()[i]) << "instance " << k;
        ASSERT_EQ(p.fade, std::min(s.pool.fade()[i], 1.0f)) << "instance " << k;
        ASSERT_EQ(p.frame, float(s.pool.frame()[i] & 3u)) << "instance " << k;
    }
}

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
