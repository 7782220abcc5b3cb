// The view's CPU work through the host's job system (HostAdapter::parallelFor): the draw list, the
// sort and the screen bound come out the same bit for bit whether the pieces run on one thread,
// on several at once, in reverse, twice (the second call does nothing), or not at all (a host
// that drops tasks).
#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "DrawListScene.h"
#include "JobHosts.h"
#include "../../fx_plugin/render/ScreenTiles.h"
#include "../../fx_plugin/render/TileBins.h"
#include "../../fx_plugin/base/Sse2.h"

namespace {

using drawlist_test::Scene;
using drawlist_test::expectDrawn;
using jobhost_test::HowRun;
using jobhost_test::JobHost;
using jobhost_test::kRuns;


TEST(ParallelBuild, DrawListIsTheSerialOneHoweverThePiecesRun) {
    const Scene s(120000);
    const fx::ParticleBatch batches[2] = {s.batch(false), s.batch(true)};
    std::vector<uint32_t> expected = s.reference(false);
    const std::vector<uint32_t> sorted = s.reference(true);
    expected.insert(expected.end(), sorted.begin(), sorted.end());
    ASSERT_GT(sorted.size(), 40000u);  // enough for the sort's pieces too
    for (HowRun how : kRuns) {
        JobHost host(how);
        fx::DrawListBuilder builder;
        fx::DrawList list;
        for (int round = 0; round < 2; ++round) {  // the scratch of the first build is reused
            builder.build(s.view, batches, 2, fx::Technique::FromReaction, ~0u, &list, fx::Jobs(&host));
            expectDrawn(s, list, expected);
            ASSERT_EQ(list.batches.size(), 2u);
            EXPECT_EQ(list.batches[1].first, list.batches[0].count);
        }
        EXPECT_GT(host.calls, 0) << int(how);
        EXPECT_GE(host.largest, 16u) << "120000 particles in pieces of 2048";
    }
}

// Several reactions, sorted and not, in one build through the job system: each batch comes out as
// building its reaction alone gives it, also where particles of different reactions have the same
// depths (b's particles are a's first ones: same seed) and where one pool is drawn twice; then a
// build with fewer reactions reuses the scratch of the larger one.
TEST(ParallelBuild, EachReactionComesOutAsBuiltAlone) {
    const Scene a(60000), b(30000);
    const fx::ParticleBatch batches[5] = {a.batch(true), b.batch(false), a.batch(true), b.batch(true), b.batch(false)};
    fx::DrawList alone;
    std::vector<fx::ParticleInstance> expected;
    std::vector<int> counts;
    for (const fx::ParticleBatch& one : batches) {
        fx::DrawListBuilder builder;
        builder.build(a.view, &one, 1, fx::Technique::FromReaction, ~0u, &alone);
        expected.insert(expected.end(), alone.instances.begin(), alone.instances.end());
        counts.push_back(alone.particleCount());
    }
    ASSERT_GT(counts[0], 30000);  // enough for the sort's pieces
    for (HowRun how : kRuns) {
        JobHost host(how);
        fx::DrawListBuilder builder;
        fx::DrawList list;
        for (int round = 0; round < 3; ++round) {
            const int n = round == 1 ? 1 : 5;  // 5, then 1 (fewer slots than the last build), then 5
            builder.build(a.view, batches, n, fx::Technique::FromReaction, ~0u, &list, fx::Jobs(&host));
            ASSERT_EQ(list.batches.size(), size_t(n));
            int first = 0;
            for (int k = 0; k < n; ++k) {
                EXPECT_EQ(list.batches[size_t(k)].first, first) << "batch " << k;
                EXPECT_EQ(list.batches[size_t(k)].count, counts[size_t(k)]) << "batch " << k;
                EXPECT_EQ(list.batches[size_t(k)].rampRow, k);
                first += counts[size_t(k)];
            }
            ASSERT_EQ(list.particleCount(), first);
            EXPECT_EQ(std::memcmp(list.instances.data(), expected.data(), size_t(first) * sizeof(fx::ParticleInstance)), 0)
                << "how " << int(how) << ", round " << round;
        }
    }
}

// A list built without its back-to-front sort (deferOrder, for the tiled path's GPU sort) holds
// each batch's visible particles in pool order and says so; order() then makes it the sorted
// build bit for bit, however the pieces run, in one batch of three that is drawn unsorted.
TEST(ParallelBuild, DeferredOrderPutInPlaceIsTheSortedBuild) {
    const Scene a(60000), b(30000);
    const fx::ParticleBatch batches[3] = {a.batch(true), b.batch(false), b.batch(true)};
    for (HowRun how : kRuns) {
        JobHost host(how);
        fx::DrawListBuilder builder;
        fx::DrawList sorted, deferred, poolOrder;
        builder.build(a.view, batches, 3, fx::Technique::FromReaction, ~0u, &sorted, fx::Jobs(&host));
        const fx::ParticleBatch unsortedA = a.batch(false);
        fx::DrawListBuilder other;
        other.build(a.view, &unsortedA, 1, fx::Technique::FromReaction, ~0u, &poolOrder);
        ASSERT_EQ(poolOrder.particleCount(), sorted.batches[0].count);
        EXPECT_FALSE(sorted.orderPending);
        for (int round = 0; round < 2; ++round) {
            builder.build(a.view, batches, 3, fx::Technique::FromReaction, ~0u, &deferred, fx::Jobs(&host), true);
            EXPECT_TRUE(deferred.orderPending);
            ASSERT_EQ(deferred.particleCount(), sorted.particleCount());
            ASSERT_EQ(deferred.batches.size(), 3u);
            EXPECT_TRUE(deferred.batches[0].backToFront);
            EXPECT_FALSE(deferred.batches[1].backToFront);
            EXPECT_TRUE(deferred.batches[2].backToFront);
            // Pool order: the first batch is what drawing a's pool unsorted gives, not the sorted one.
            EXPECT_EQ(std::memcmp(deferred.instances.data(), poolOrder.instances.data(),
                                  size_t(poolOrder.particleCount()) * sizeof(fx::ParticleInstance)), 0);
            EXPECT_NE(std::memcmp(deferred.instances.data(), sorted.instances.data(),
                                  size_t(poolOrder.particleCount()) * sizeof(fx::ParticleInstance)), 0);
            builder.order(a.view, &deferred, fx::Jobs(&host));
            EXPECT_FALSE(deferred.orderPending);
            EXPECT_EQ(std::memcmp(deferred.instances.data(), sorted.instances.data(),
                                  size_t(sorted.particleCount()) * sizeof(fx::ParticleInstance)), 0)
                << "how " << int(how) << ", round " << round;
            builder.order(a.view, &deferred, fx::Jobs(&host));  // nothing pending: nothing moves
            EXPECT_EQ(std::memcmp(deferred.instances.data(), sorted.instances.data(),
                                  size_t(sorted.particleCount()) * sizeof(fx::ParticleInstance)), 0);
        }
    }
    // Additive alone: no order is pending.
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(b.view, &batches[1], 1, fx::Technique::FromReaction, ~0u, &list, fx::Jobs(), true);
    EXPECT_GT(list.particleCount(), 0);
    EXPECT_FALSE(list.orderPending);
}

// A list built with its gather deferred too (deferGather, for the tiled path to write the
// particles straight into its storage buffer) is only counted: the batches' places and counts are
// final, nothing is written, and gatherInto() or settle() then write what the build without it
// writes, bit for bit: pools of several pieces and of one, one whose particles are all culled,
// however the pieces run, four particles at a time or one, and for a sliced view (one at a time).
// order() settles first. A build without it after one with it leaves nothing pending.
TEST(ParallelBuild, DeferredGatherWritesTheDeferredOrderList) {
    Scene a(60000), b(30000), small(1500), hidden(5000);
    for (int i = 0; i < hidden.pool.alive(); ++i) hidden.pool.stream(fx::ParticlePool::PosZ)[i] = 50.0f;  // behind
    const fx::ParticleBatch batches[5] = {a.batch(true), hidden.batch(true), b.batch(false), small.batch(true),
                                          b.batch(true)};
    struct LanesBack {
        ~LanesBack() { fx::setFourLanes(true); }
    } lanesBack;
    for (int variant = 0; variant < 3; ++variant) {
        fx::setFourLanes(variant != 1);
        fx::ViewInfo view = a.view;
        if (variant == 2) view.slice = fx::DistanceSlice{5.0f, 60.0f};
        for (HowRun how : kRuns) {
            SCOPED_TRACE("variant " + std::to_string(variant) + ", how " + std::to_string(int(how)));
            JobHost host(how);
            fx::DrawListBuilder builder;
            fx::DrawList written, pending, sorted;
            builder.build(view, batches, 5, fx::Technique::FromReaction, ~0u, &written, fx::Jobs(&host), true);
            builder.build(view, batches, 5, fx::Technique::FromReaction, ~0u, &sorted, fx::Jobs(&host));
            ASSERT_GT(written.particleCount(), 40000);
            for (int round = 0; round < 2; ++round) {
                builder.build(view, batches, 5, fx::Technique::FromReaction, ~0u, &pending, fx::Jobs(&host), true, true);
                ASSERT_TRUE(pending.gatherPending());
                EXPECT_TRUE(pending.instances.empty()) << "nothing written while declaring";
                EXPECT_TRUE(pending.orderPending);
                ASSERT_EQ(pending.particleCount(), written.particleCount());
                ASSERT_EQ(pending.batches.size(), written.batches.size());
                EXPECT_EQ(pending.batches.size(), 4u) << "the hidden pool has no batch";
                for (size_t k = 0; k < written.batches.size(); ++k) {
                    EXPECT_EQ(pending.batches[k].first, written.batches[k].first) << k;
                    EXPECT_EQ(pending.batches[k].count, written.batches[k].count) << k;
                }
                const size_t bytes = size_t(written.particleCount()) * sizeof(fx::ParticleInstance);
                std::vector<fx::ParticleInstance> to(size_t(written.particleCount()) + 1);
                std::memset(static_cast<void*>(to.data()), 0xAB, (to.size()) * sizeof(fx::ParticleInstance));
                const fx::ParticleInstance past = to.back();
                pending.gatherInto(to.data(), fx::Jobs(&host));
                EXPECT_EQ(std::memcmp(to.data(), written.instances.data(), bytes), 0);
                EXPECT_EQ(std::memcmp(&to.back(), &past, sizeof past), 0) << "nothing written past the list";
                EXPECT_TRUE(pending.gatherPending()) << "gatherInto leaves the list pending";
                if (round == 0) {
                    pending.settle(fx::Jobs(&host));
                    EXPECT_FALSE(pending.gatherPending());
                    ASSERT_EQ(pending.particleCount(), written.particleCount());
                    EXPECT_EQ(std::memcmp(pending.instances.data(), written.instances.data(), bytes), 0);
                    pending.settle(fx::Jobs(&host));  // nothing pending: nothing moves
                    EXPECT_EQ(std::memcmp(pending.instances.data(), written.instances.data(), bytes), 0);
                }
                builder.order(view, &pending, fx::Jobs(&host));
                EXPECT_FALSE(pending.gatherPending());
                ASSERT_EQ(pending.particleCount(), sorted.particleCount());
                EXPECT_EQ(std::memcmp(pending.instances.data(), sorted.instances.data(), bytes), 0);
            }
            builder.build(view, batches, 5, fx::Technique::FromReaction, ~0u, &pending, fx::Jobs(&host), true, false);
            EXPECT_FALSE(pending.gatherPending());
            EXPECT_EQ(std::memcmp(pending.instances.data(), written.instances.data(),
                                  size_t(written.particleCount()) * sizeof(fx::ParticleInstance)), 0);
        }
    }
    // Without deferOrder there is nothing to defer: the list is written.
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(a.view, batches, 1, fx::Technique::FromReaction, ~0u, &list, fx::Jobs(), false, true);
    EXPECT_FALSE(list.gatherPending());
    EXPECT_GT(list.particleCount(), 0);
}

TEST(ParallelBuild, SmallPoolsNeverReachTheHost) {
    const Scene s(3000);
    const fx::ParticleBatch batch = s.batch(true);
    JobHost host(HowRun::Threads);
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list, fx::Jobs(&host));
    expectDrawn(s, list, s.reference(true));
    EXPECT_EQ(host.calls, 0);
}

TEST(ParallelBuild, SortInPiecesIsTheSerialSortWithItsPayload) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> depth(-50.0f, 400.0f);
    for (int n : {40000, 100000}) {
        std::vector<float> d(static_cast<size_t>(n));
        std::vector<uint32_t> payload(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) {
            d[size_t(i)] = (i % 5 == 2) ? d[size_t(i - 1)] : depth(rng);  // ties keep their order
            if (i % 97 == 0) d[size_t(i)] = -0.0f;
            if (i % 89 == 0) d[size_t(i)] = 0.0f;
            payload[size_t(i)] = uint32_t(3 * i + 7);
        }
        fx::ParticleSorter serial;
        const fx::ParticleSorter::Order want = serial.sortDescending(d.data(), n);
        for (HowRun how : kRuns) {
            JobHost host(how);
            fx::ParticleSorter pieces;
            const fx::ParticleSorter::Order got = pieces.sortDescending(d.data(), payload.data(), n, fx::Jobs(&host));
            ASSERT_EQ(got.count, n);
            for (int k = 0; k < n; ++k) ASSERT_EQ(got.indices[k], payload[want.indices[k]]) << "n " << n << " at " << k;
            EXPECT_GT(host.calls, 0);
        }
        fx::ParticleSorter noHost;  // the same entry without a job system, and without a payload
        const fx::ParticleSorter::Order plain = noHost.sortDescending(d.data(), nullptr, n, fx::Jobs());
        for (int k = 0; k < n; ++k) ASSERT_EQ(plain.indices[k], want.indices[k]);
    }
}

// The tiles a bound's runs cover, as a set of tile indices.
std::vector<int> coveredTiles(const fx::ScreenTiles& t) {
    const int k = fx::ScreenTiles::kTileSize, tilesX = (t.viewWidth + k - 1) / k;
    std::vector<int> out;
    for (size_t v = 0; v + 12 <= t.vertices.size(); v += 12) {
        const int x0 = int(t.vertices[v]) / k, x1 = (int(t.vertices[v + 2]) + k - 1) / k;
        const int y0 = int(t.vertices[v + 1]) / k, y1 = (int(t.vertices[v + 5]) + k - 1) / k;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) out.push_back(y * tilesX + x);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(ParallelBuild, ScreenBoundInPiecesIsTheUnionOfEveryParticlesBound) {
    const Scene s(150000);
    const fx::ParticleBatch batch = s.batch(true);
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list);
    // Those at least 3 m ahead (none reaches the near plane) and right of the camera: the bound
    // is not the whole view.
    std::vector<fx::ParticleInstance> ahead;
    for (const fx::ParticleInstance& p : list.instances) {
        if (p.z < s.view.eye.z - 3.0f && p.x > 4.0f) ahead.push_back(p);
    }
    const int n = int(ahead.size());
    ASSERT_GT(n, 32768);  // at least two pieces
    for (fx::Footprint footprint : {fx::Footprint::Box, fx::Footprint::Billboard}) {
        fx::ScreenTiles serialTiles;
        const fx::ScreenRect serial = fx::screenRect(s.view, ahead.data(), n, &serialTiles, footprint);
        ASSERT_FALSE(serial.whole);
        // Particle by particle: the rect is the union of their rects, the tiles the union of
        // their tiles, the pixels their sum (summed in another order: to 1e-12).
        fx::ScreenRect each;
        int x0 = s.view.width, y0 = s.view.height, x1 = 0, y1 = 0;
        double pixels = 0.0;
        std::vector<int> tiles;
        fx::ScreenTiles one;
        for (int i = 0; i < n; ++i) {
            each = fx::screenRect(s.view, &ahead[size_t(i)], 1, &one, footprint);
            pixels += each.footprintPixels;
            if (each.x1 <= each.x0) continue;
            x0 = std::min(x0, each.x0), y0 = std::min(y0, each.y0), x1 = std::max(x1, each.x1), y1 = std::max(y1, each.y1);
            const std::vector<int> mine = coveredTiles(one);
            tiles.insert(tiles.end(), mine.begin(), mine.end());
        }
        std::sort(tiles.begin(), tiles.end());
        tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
        EXPECT_EQ(serial.x0, x0);
        EXPECT_EQ(serial.y0, y0);
        EXPECT_EQ(serial.x1, x1);
        EXPECT_EQ(serial.y1, y1);
        EXPECT_NEAR(serial.footprintPixels, pixels, 1e-12 * pixels);
        EXPECT_EQ(coveredTiles(serialTiles), tiles);
        for (HowRun how : kRuns) {
            JobHost host(how);
            fx::ScreenTiles tilesRun;
            const fx::ScreenRect r = fx::screenRect(s.view, ahead.data(), n, &tilesRun, footprint, fx::Jobs(&host));
            EXPECT_GT(host.calls, 0);
            EXPECT_EQ(r.x0, serial.x0);
            EXPECT_EQ(r.y0, serial.y0);
            EXPECT_EQ(r.x1, serial.x1);
            EXPECT_EQ(r.y1, serial.y1);
            EXPECT_EQ(r.whole, serial.whole);
            EXPECT_EQ(r.footprintPixels, serial.footprintPixels) << "bit for bit: summed piece by piece, in order";
            EXPECT_EQ(tilesRun.vertices, serialTiles.vertices);
            EXPECT_EQ(tilesRun.pixels, serialTiles.pixels);
        }
    }
}

TEST(ParallelBuild, OneParticleAtTheNearPlaneInAnyPieceMakesTheWholeView) {
    const Scene s(60000);
    const fx::ParticleBatch batch = s.batch(true);
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list);
    const int n = list.particleCount();
    fx::ParticleInstance& last = list.instances[size_t(n - 1)];  // in the last piece
    last.x = s.view.eye.x, last.y = s.view.eye.y, last.z = s.view.eye.z - 0.05f;
    JobHost host(HowRun::Threads);
    fx::ScreenTiles tiles;
    const fx::ScreenRect r = fx::screenRect(s.view, list.instances.data(), n, &tiles, fx::Footprint::Box, fx::Jobs(&host));
    EXPECT_TRUE(r.whole);
    EXPECT_EQ(tiles.pixels, int64_t(s.view.width) * s.view.height);
}

TEST(ParallelBuild, AViewThatSeesNothingGivesAnEmptyList) {
    const Scene s(40000);
    fx::ViewInfo away = s.view;  // looking straight up, past every particle (they are below 6 m)
    away.view = glm::lookAt(glm::vec3(0.0f, 50.0f, 0.0f), glm::vec3(0.0f, 100.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    away.eye = glm::vec3(0.0f, 50.0f, 0.0f);
    const fx::ParticleBatch batches[2] = {s.batch(false), s.batch(true)};
    for (HowRun how : kRuns) {
        JobHost host(how);
        fx::DrawListBuilder builder;
        fx::DrawList list;
        builder.build(away, batches, 2, fx::Technique::FromReaction, ~0u, &list, fx::Jobs(&host));
        EXPECT_EQ(list.particleCount(), 0);
        EXPECT_TRUE(list.batches.empty());
    }
}

// The tiled path's bins (binParticles) in pieces: the same entries, tiles and runs as one
// thread's, bit for bit, however the pieces run; many small particles (pieces of the particles)
// and a few that cover much of the view (pieces of nearly equal entries), billboards and spheres.
// A view of 16,000 particles (the tiled sweep's second point) goes to the host's threads in
// pieces of about 2,048, the cull and the bins alike: with pieces of 8,192 it was one piece, all
// of it on the calling thread. The same list and bins as serially.
TEST(ParallelBuild, SixteenThousandParticlesAreSharedOut) {
    const Scene s(16000);
    const fx::ParticleBatch batch = s.batch(false);
    fx::DrawListBuilder builder;
    fx::DrawList list;
    JobHost cullHost(HowRun::Threads);
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, ~0u, &list, fx::Jobs(&cullHost));
    expectDrawn(s, list, s.reference(false));
    EXPECT_EQ(cullHost.largest, 7u) << "16000 particles in pieces of 2048 or more";
    const fx::TileBins::Range range{0, list.particleCount(), false};
    ASSERT_GT(list.particleCount(), 10000);
    fx::TileBins serial, shared;
    ASSERT_TRUE(fx::binParticles(s.view, list.instances.data(), &range, 1, nullptr, &serial));
    JobHost binHost(HowRun::Threads);
    ASSERT_TRUE(fx::binParticles(s.view, list.instances.data(), &range, 1, nullptr, &shared, fx::Jobs(&binHost)));
    EXPECT_GE(binHost.largest, uint32_t(list.particleCount() / 2048));  // the bins, then the lists in bands
    EXPECT_EQ(shared.entries, serial.entries);
    EXPECT_EQ(shared.tiles, serial.tiles);
    EXPECT_EQ(shared.cover.vertices, serial.cover.vertices);
}

TEST(ParallelBuild, TileBinsInPiecesAreTheSerialOnes) {
    const Scene s(120000);
    const fx::ParticleBatch batches[2] = {s.batch(false), s.batch(true)};
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, batches, 2, fx::Technique::FromReaction, ~0u, &list);
    ASSERT_EQ(list.batches.size(), 2u);
    // The same particles, and the first 300 of them grown to 20 m (each over hundreds of tiles).
    std::vector<fx::ParticleInstance> large(list.instances.begin(), list.instances.begin() + 300);
    for (fx::ParticleInstance& p : large) p.size = 20.0f;
    struct Case {
        const fx::ParticleInstance* instances;
        fx::TileBins::Range ranges[2];
    };
    const Case cases[] = {
        {list.instances.data(), {{list.batches[0].first, list.batches[0].count, false},
                                 {list.batches[1].first, list.batches[1].count, true}}},
        {large.data(), {{0, 150, false}, {150, 150, true}}},
    };
    for (const Case& c : cases) {
        fx::TileBins serial;
        ASSERT_TRUE(fx::binParticles(s.view, c.instances, c.ranges, 2, nullptr, &serial));
        ASSERT_GT(serial.entries.size(), 65536u) << "two pieces of 32768 entries at least";
        // Every tile's list runs front to back across the pieces' seams: (batch, instance) falls.
        for (int t = 0; t < serial.tileCount(); ++t) {
            const uint32_t first = serial.tiles[size_t(t) * 4 + 2], count = serial.tiles[size_t(t) * 4 + 3];
            for (uint32_t e = first + 1; e < first + count; ++e) {
                const uint32_t a = serial.entries[e - 1], b = serial.entries[e];
                const uint32_t mask = (1u << fx::TileBins::kBatchShift) - 1u;
                const uint64_t keyA = (uint64_t(a >> fx::TileBins::kBatchShift) << 32) | (a & mask);
                const uint64_t keyB = (uint64_t(b >> fx::TileBins::kBatchShift) << 32) | (b & mask);
                ASSERT_GT(keyA, keyB) << "tile " << t << " entry " << e;
            }
        }
        for (HowRun how : kRuns) {
            JobHost host(how);
            fx::TileBins bins;
            for (int round = 0; round < 2; ++round) {  // the scratch of the first is reused
                ASSERT_TRUE(fx::binParticles(s.view, c.instances, c.ranges, 2, nullptr, &bins, fx::Jobs(&host)));
                EXPECT_EQ(bins.entries, serial.entries) << int(how);
                EXPECT_EQ(bins.tiles, serial.tiles) << int(how);
                EXPECT_EQ(bins.cover.vertices, serial.cover.vertices) << int(how);
            }
            EXPECT_GT(host.calls, 0) << int(how);
        }
    }
}

}  // namespace
