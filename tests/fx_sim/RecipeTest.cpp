// The barrier recipe (reactions/barrier_scrape.yaml): its layers fire together on one contact,
// sparks only while the car is in contact, additive layers unsorted, and the same seed and dt
// give the same particles.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "../../fx_plugin/reactions/ReactionLoader.h"
#include "../../fx_plugin/sim/ReactionRuntime.h"

namespace {

const std::string kFile = std::string(CUBE_SOURCE_DIR) + "/reactions/barrier_scrape.yaml";

std::vector<fx::ReactionRuntime> load(uint64_t seed) {
    fx::ReactionSet set;
    fx::Diagnostics diags;
    EXPECT_TRUE(fx::loadReactionFile(kFile, &set, &diags));
    std::vector<fx::ReactionRuntime> out;
    for (const fx::ReactionDesc& d : set.reactions) out.emplace_back(d, seed);
    return out;
}

const fx::ReactionRuntime& byName(const std::vector<fx::ReactionRuntime>& rs, const char* name) {
    for (const fx::ReactionRuntime& r : rs) {
        if (r.name() == name) return r;
    }
    ADD_FAILURE() << "no reaction " << name;
    return rs.front();
}

// 1 s free, 2 s scraping at `amount` (moving along the barrier), 1 s free; 60 Hz.
void drive(std::vector<fx::ReactionRuntime>& rs, float amount) {
    for (int i = 0; i < 240; ++i) {
        const bool contact = i >= 60 && i < 180;
        const glm::vec3 point(0.2f * float(i), 0.5f, 8.4f);
        for (fx::ReactionRuntime& r : rs) {
            r.step(1.0f / 60.0f, nullptr, 0, contact ? amount : 0.0f, point, glm::vec3(0.5f, 0.0f, 0.0f));
        }
    }
}

TEST(Recipe, BarrierScrapeExpandsIntoItsLayers) {
    const auto rs = load(1);
    ASSERT_EQ(rs.size(), 3u);
    EXPECT_TRUE(byName(rs, "barrier_scrape.sparks").stateless());
    EXPECT_EQ(byName(rs, "barrier_scrape.sparks").desc().type, fx::ReactionType::CollisionScrape);
    // Additive layers are never sorted; the smoke (alpha) is.
    EXPECT_FALSE(byName(rs, "barrier_scrape.sparks").needsSorting());
    EXPECT_FALSE(byName(rs, "barrier_scrape.flash").needsSorting());
    EXPECT_TRUE(byName(rs, "barrier_scrape.smoke").needsSorting());
}

TEST(Recipe, SparksOnlyWhileInContactAndTheLayersFireTogether) {
    auto rs = load(1);
    fx::ReactionRuntime& sparks = rs[0];
    ASSERT_EQ(sparks.name(), "barrier_scrape.sparks");
    const glm::vec3 point(0.0f, 0.5f, 8.4f);
    for (int i = 0; i < 60; ++i) {  // no contact: nothing
        for (auto& r : rs) r.step(1.0f / 60.0f, nullptr, 0, 0.0f, point, glm::vec3(0.0f));
    }
    for (auto& r : rs) EXPECT_EQ(r.counters().emitted, 0u) << r.name();
    uint64_t during = 0;
    for (int i = 0; i < 120; ++i) {  // 2 s of a hard scrape (amount 0.8)
        for (auto& r : rs) r.step(1.0f / 60.0f, nullptr, 0, 0.8f, point, glm::vec3(0.0f));
        EXPECT_GT(sparks.counters().emitted, during) << "step " << i;  // sparks every step in contact
        during = sparks.counters().emitted;
    }
    EXPECT_NEAR(double(during), 900.0 * 0.8 * 2.0, 2.0);  // rate x amount x time
    // The hard hit fired the flash and smoke layers once, on the same contact.
    EXPECT_EQ(byName(rs, "barrier_scrape.flash").counters().bursts, 1u);
    EXPECT_EQ(byName(rs, "barrier_scrape.smoke").counters().bursts, 1u);
    for (int i = 0; i < 60; ++i) {  // contact over: no more sparks, the last ones fade
        for (auto& r : rs) r.step(1.0f / 60.0f, nullptr, 0, 0.0f, point, glm::vec3(0.0f));
    }
    EXPECT_EQ(sparks.counters().emitted, during);
    EXPECT_EQ(sparks.alive(), 0);  // 0.7 s at most
}

TEST(Recipe, AGentleScrapeSparksWithoutTheFlash) {
    auto rs = load(1);
    drive(rs, 0.3f);  // above the sparks' 0.15, below the flash's 0.6
    EXPECT_GT(byName(rs, "barrier_scrape.sparks").counters().emitted, 100u);
    EXPECT_EQ(byName(rs, "barrier_scrape.flash").counters().emitted, 0u);
}

TEST(Recipe, TheScrapeIsDeterministicAtFixedSeedAndDt) {
    auto a = load(7), b = load(7), c = load(8);
    drive(a, 0.8f);
    drive(b, 0.8f);
    drive(c, 0.8f);
    const fx::StatelessRing& ra = a[0].ring();
    const fx::StatelessRing& rb = b[0].ring();
    ASSERT_EQ(ra.written(), rb.written());
    EXPECT_EQ(std::memcmp(ra.data(), rb.data(), sizeof(fx::StatelessRecord) * size_t(ra.capacity())), 0);
    EXPECT_NE(std::memcmp(ra.data(), c[0].ring().data(), sizeof(fx::StatelessRecord) * size_t(ra.capacity())), 0);
    for (size_t i = 1; i < a.size(); ++i) {
        ASSERT_EQ(a[i].pool().alive(), b[i].pool().alive());
        const size_t n = size_t(a[i].pool().alive());
        EXPECT_EQ(std::memcmp(a[i].pool().posX(), b[i].pool().posX(), n * sizeof(float)), 0) << a[i].name();
    }
}

TEST(Recipe, TheExplosionIsDeterministicAtFixedSeedAndDt) {
    auto run = [](uint64_t seed) {
        fx::ReactionSet set;
        EXPECT_TRUE(fx::loadReactionFile(std::string(CUBE_SOURCE_DIR) + "/reactions/explosion.yaml", &set, nullptr));
        std::vector<fx::ReactionRuntime> rs;
        for (const fx::ReactionDesc& d : set.reactions) rs.emplace_back(d, seed);
        for (auto& r : rs) r.fire(glm::vec3(3.0f, 0.5f, -1.0f));
        for (int i = 0; i < 45; ++i) {
            for (auto& r : rs) r.step(1.0f / 60.0f, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(0.5f, 0.0f, 0.0f));
        }
        return rs;
    };
    auto a = run(3), b = run(3);
    ASSERT_EQ(a.size(), 5u);
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].counters().bursts, 1u) << a[i].name();  // every layer fired once, together
        if (a[i].stateless()) {
            ASSERT_EQ(a[i].ring().written(), b[i].ring().written());
            EXPECT_EQ(std::memcmp(a[i].ring().data(), b[i].ring().data(),
                                  sizeof(fx::StatelessRecord) * size_t(a[i].ring().capacity())), 0);
            continue;
        }
        ASSERT_EQ(a[i].pool().alive(), b[i].pool().alive()) << a[i].name();
        const size_t n = size_t(a[i].pool().alive());
        for (auto s : {fx::ParticlePool::PosX, fx::ParticlePool::PosY, fx::ParticlePool::PosZ}) {
            EXPECT_EQ(std::memcmp(a[i].pool().stream(s), b[i].pool().stream(s), n * sizeof(float)), 0) << a[i].name();
        }
    }
}

}  // namespace
