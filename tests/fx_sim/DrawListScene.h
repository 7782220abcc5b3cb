#pragma once
// A pool for the draw-list tests (DrawListOrderTest, ParallelBuildTest): particles ahead of and
// around the camera, a part culled, every fourth sharing its depth with the one before it, some of
// zero size and some faded out.
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "../../fx_plugin/render/DrawList.h"
#include "../../fx_plugin/render/ViewFrustum.h"

namespace drawlist_test {

struct Scene {
    fx::ParticlePool pool;
    fx::ReactionDesc desc = fx::defaultReaction(fx::ReactionType::WheelSmoke);
    fx::ViewInfo view;
    explicit Scene(int count = 3000) : pool(count) {
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> across(-40.0f, 40.0f), ahead(-10.0f, 90.0f), unit(0.0f, 1.0f);
        for (int k = 0; k < count; ++k) {
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

inline void expectDrawn(const Scene& s, const fx::DrawList& list, const std::vector<uint32_t>& expected) {
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

}  // namespace drawlist_test
