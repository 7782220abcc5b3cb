// Back-to-front order, and the no-allocation-per-frame promise of the sorter and the
// simulation step, checked by counting every operator new in this test binary.
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "../../fx_plugin/sim/ParticleSorter.h"
#include "../../fx_plugin/sim/ReactionRuntime.h"

namespace {
std::atomic<long> gAllocations{0};
}  // namespace

// Replaces the global (unaligned) allocator for this test binary, every form of it so that new
// and delete always pair up (sanitizers check); counting is always on (tests read deltas).
void* operator new(std::size_t n) {
    ++gAllocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    ++gAllocations;
    return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
// GCC's -Wmismatched-new-delete takes free() in a replacement delete for a mismatch once the
// replacement new above is inlined (-O1): the pair is malloc/free, as written.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace {

fx::ReactionRuntime smokeWithParticles(fx::BlendMode blend = fx::BlendMode::Alpha) {
    fx::ReactionDesc d = fx::defaultReaction(fx::ReactionType::WheelSmoke);
    d.name = "smoke";
    d.emission.rate = 500.0f;
    d.emission.capacity = 4000;
    d.particle.spreadSpeed = 4.0f;
    d.emission.jitterRadius = 2.0f;
    d.render.blend = blend;
    fx::ReactionRuntime rt(d);
    fx::WheelContact w;
    w.grounded = w.rear = true;
    w.slip = 1.0f;
    w.velocity = glm::vec3(5.0f, 0.0f, 2.0f);
    for (int i = 0; i < 120; ++i) {
        w.position += w.velocity / 60.0f;
        rt.step(1.0f / 60.0f, &w, 1, 0.0f, glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    }
    return rt;
}

float depth(const fx::ParticlePool& p, uint32_t i, glm::vec3 eye, glm::vec3 dir) {
    return glm::dot(glm::vec3(p.posX()[i], p.posY()[i], p.posZ()[i]) - eye, dir);
}

TEST(Sorter, OrdersLiveParticlesFarToNear) {
    const fx::ReactionRuntime rt = smokeWithParticles();
    const fx::ParticlePool& pool = rt.pool();
    ASSERT_GT(pool.alive(), 500);
    // The eye sits inside the cloud, so depths of both signs occur.
    const glm::vec3 eye(4.0f, 1.0f, 1.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(1.0f, -0.2f, 0.3f));
    fx::ParticleSorter sorter;
    const fx::ParticleSorter::Order order = sorter.update(pool, eye, dir, true);
    ASSERT_EQ(order.count, pool.alive());
    std::vector<uint32_t> seen(order.indices, order.indices + order.count);
    for (int i = 1; i < order.count; ++i) {
        ASSERT_GE(depth(pool, order.indices[i - 1], eye, dir), depth(pool, order.indices[i], eye, dir));
    }
    EXPECT_LT(depth(pool, order.indices[order.count - 1], eye, dir), 0.0f);
    EXPECT_GT(depth(pool, order.indices[0], eye, dir), 0.0f);
    std::sort(seen.begin(), seen.end());  // a permutation of [0, alive)
    for (int i = 0; i < order.count; ++i) ASSERT_EQ(seen[i], static_cast<uint32_t>(i));
}

TEST(Sorter, EqualDepthsKeepPoolOrderAndUnsortedIsIdentity) {
    fx::ReactionRuntime rt = smokeWithParticles();
    fx::ParticleSorter sorter;
    // A view direction orthogonal to... everything: all depths 0 -> stable = identity.
    const fx::ParticleSorter::Order same = sorter.update(rt.pool(), glm::vec3(0.0f), glm::vec3(0.0f), true);
    for (int i = 0; i < same.count; ++i) ASSERT_EQ(same.indices[i], static_cast<uint32_t>(i));
    const fx::ParticleSorter::Order off = sorter.update(rt.pool(), glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), false);
    for (int i = 0; i < off.count; ++i) ASSERT_EQ(off.indices[i], static_cast<uint32_t>(i));
}

TEST(Sorter, AdditiveBlendingIsNeverSorted) {
    EXPECT_TRUE(smokeWithParticles(fx::BlendMode::Alpha).needsSorting());
    EXPECT_TRUE(smokeWithParticles(fx::BlendMode::Premultiplied).needsSorting());
    EXPECT_FALSE(smokeWithParticles(fx::BlendMode::Additive).needsSorting());
}

TEST(NoAllocation, SortAndStepAllocateNothingAfterWarmUp) {
    fx::ReactionRuntime rt = smokeWithParticles();
    fx::ParticleSorter sorter;
    fx::WheelContact w[4];
    for (fx::WheelContact& x : w) {
        x.grounded = x.rear = true;
        x.slip = 0.9f;
        x.velocity = glm::vec3(3.0f, 0.0f, 0.0f);
    }
    sorter.update(rt.pool(), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), true);  // warm-up
    const long before = gAllocations.load();
    for (int frame = 0; frame < 600; ++frame) {  // 10 s: particles are born and die
        rt.step(1.0f / 60.0f, w, 4, frame % 100 == 0 ? 1.0f : 0.0f, glm::vec3(0.0f), glm::vec3(2.0f, 0.0f, 0.0f));
        sorter.update(rt.pool(), glm::vec3(0.0f, 2.0f, 10.0f), glm::vec3(0.0f, 0.0f, -1.0f), true);
    }
    rt.step(2.0f, w, 4, 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));  // a hitch
    EXPECT_EQ(gAllocations.load() - before, 0);
    EXPECT_GT(rt.counters().emitted, 1000u);
}

}  // namespace
