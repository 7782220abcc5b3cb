// bench_draw: the CPU work a view's particles cost before any GL call, per particle, against a
// memory reference that touches the same bytes. This is the "CPU outside the passes" of fxbench's
// particle sweep, measured without a GL context.
//
//   BM_DrawListBuild/N    fx::DrawListBuilder::build for one view: the back-to-front radix sort of
//                         the pool, the frustum test and the gather into 32-byte instances
//   BM_ScreenRect/N       fx::screenRect over those instances with ScreenTiles (the quarter-res
//                         path's bound, tiles and overdraw estimate; billboard footprints)
//   BM_ScreenRectBox/N    the same with box footprints (a view with spherical particles)
//   BM_ScreenRectTrimmed/N  billboards bounded by their trimmed polygons' reach (BillboardReach):
//                         the quarter-res path's bound for trimmed billboards
//   BM_TileBins/N/T/F     fx::binParticles (the tiled path's bins: every particle into the 16 px
//                         tiles its trimmed bound touches, front to back) on T job threads (T = 1:
//                         the pieces on the calling thread). F = 0: Fill::Entries, the lists
//                         written here (the reference); F = 1: Fill::Pairs, what the tiled path
//                         runs (bounds, counts and first entries; the GPU writes the lists);
//                         F = 2: Fill::Ranges, a view whose particles the GPU orders (two words a
//                         particle: the tile range)
//   BM_TileBinsLarge/N/T/F  the same with every particle 8 m across (the fill scene's kind: a few
//                         hundred particles over thousands of tiles each)
//   BM_InstanceCopy/N     reference: memcpy of the N instances (32 N bytes read and written)
//   BM_GatherJobs/N/T     DrawList::gatherInto of a list built with D = 2 (the tiled pass writing
//                         the instances into its mapped buffer; D = 1 left the pass a copy of the
//                         list instead, which BM_CopyJobs/N/T times: the pieces copyMappedInPieces
//                         makes)
//   BM_DrawListBuildJobs/N/T/D, BM_ScreenRectJobs/N/T
//                         the build (D = 1: without the back-to-front sort, deferOrder, what a view
//                         the GPU orders took until session 36; D = 2: without the gather as well,
//                         deferGather, what it takes now) and the bound through the host's job system
//                         (HostAdapter::parallelFor) on the engine's cube::JobSystem of T threads
//                         (T = 1: the pieces on the calling thread, what a host without one pays;
//                         T is 1, 2 and, where the machine has more, all its hardware threads)
//
// The particles: N in a 60 m wide slab 5 to 80 m in front of a 1920x1080 camera (about one in
// eight outside the frustum), sizes 0.3 to 3 m, in pool order unrelated to depth.
// Run interleaved for ratios on a noisy machine:
//   bench_draw --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
//              --benchmark_report_aggregates_only=true --benchmark_min_time=0.05
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>
#include <glm/gtc/matrix_transform.hpp>

#include "reactions/ReactionDesc.h"
#include "render/DrawList.h"
#include "render/ScreenTiles.h"
#include "render/TileBins.h"
#include "sim/ParticlePool.h"
#include "BenchJobsHost.h"

namespace {

struct Scene {
    fx::ParticlePool pool;
    fx::ReactionDesc desc = fx::defaultReaction(fx::ReactionType::CollisionBurst);
    fx::ViewInfo view;
    explicit Scene(int n) : pool(n) {
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> across(-30.0f, 30.0f), up(0.0f, 8.0f), ahead(5.0f, 80.0f),
            size(0.3f, 3.0f), unit(0.0f, 1.0f);
        for (int k = 0; k < n; ++k) {
            const int i = pool.spawn();
            pool.stream(fx::ParticlePool::PosX)[i] = across(rng);
            pool.stream(fx::ParticlePool::PosY)[i] = up(rng);
            pool.stream(fx::ParticlePool::PosZ)[i] = -ahead(rng);
            pool.stream(fx::ParticlePool::Size)[i] = size(rng);
            pool.stream(fx::ParticlePool::Life)[i] = unit(rng);
            pool.stream(fx::ParticlePool::Rotation)[i] = unit(rng) * 6.0f - 3.0f;
            pool.stream(fx::ParticlePool::Fade)[i] = 0.2f + 0.8f * unit(rng);
            pool.frame()[i] = uint8_t(k & 3);
        }
        view.eye = glm::vec3(0.0f, 2.0f, 0.0f);
        view.view = glm::lookAt(view.eye, glm::vec3(0.0f, 1.5f, -10.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        view.proj = glm::perspective(glm::radians(60.0f), 1920.0f / 1080.0f, 0.1f, 1000.0f);
        view.width = 1920;
        view.height = 1080;
    }
    fx::ParticleBatch batch() const {
        fx::ParticleBatch b;
        b.pool = &pool;
        b.desc = &desc;
        return b;
    }
};

constexpr uint32_t kAll = ~0u;

void BM_DrawListBuild(benchmark::State& state) {
    Scene s(int(state.range(0)));
    const fx::ParticleBatch batch = s.batch();
    fx::DrawListBuilder builder;
    fx::DrawList list;
    for (auto _ : state) {
        builder.build(s.view, &batch, 1, fx::Technique::FromReaction, kAll, &list);
        benchmark::DoNotOptimize(list.instances.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * state.range(0));
    state.counters["drawn"] = double(list.particleCount());
}

// A reach table of the size the plugin's has (its values change no work: one lookup a
// particle), at the LOD scale of a 1080p view's half-size target and a 256-texel atlas cell.
fx::BillboardReach benchReach(const fx::ViewInfo& view) {
    fx::BillboardReach r;
    r.buckets = 6;
    r.table.fill(0.6f);
    r.lodScale = 256.0f * 2.0f / (view.proj[1][1] * 0.5f * float(view.height));
    return r;
}

void screenRectBench(benchmark::State& state, fx::Footprint footprint, bool trimmed = false) {
    Scene s(int(state.range(0)));
    const fx::ParticleBatch batch = s.batch();
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, kAll, &list);
    fx::ScreenTiles tiles;
    fx::ScreenRect rect;
    const fx::BillboardReach reach = benchReach(s.view);
    for (auto _ : state) {
        rect = fx::screenRect(s.view, list.instances.data(), list.particleCount(), &tiles, footprint, fx::Jobs(),
                              trimmed ? &reach : nullptr);
        benchmark::DoNotOptimize(tiles.vertices.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * list.particleCount());
    state.counters["runs"] = double(tiles.runs());
    state.counters["overdraw"] = tiles.pixels > 0 ? rect.footprintPixels / double(tiles.pixels) : 0.0;
}

void BM_ScreenRect(benchmark::State& state) { screenRectBench(state, fx::Footprint::Billboard); }
void BM_ScreenRectBox(benchmark::State& state) { screenRectBench(state, fx::Footprint::Box); }
void BM_ScreenRectTrimmed(benchmark::State& state) { screenRectBench(state, fx::Footprint::Billboard, true); }

void BM_InstanceCopy(benchmark::State& state) {
    const size_t n = size_t(state.range(0));
    std::vector<fx::ParticleInstance> a(n), b(n);
    for (auto _ : state) {
        std::memcpy(b.data(), a.data(), n * sizeof(fx::ParticleInstance));
        benchmark::DoNotOptimize(b.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
}

void tileBinsBench(benchmark::State& state, float size) {
    Scene s(int(state.range(0)));
    bench::JobsHost host(int(state.range(1)));
    const fx::ParticleBatch batch = s.batch();
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, kAll, &list);
    if (size > 0.0f) {
        for (fx::ParticleInstance& p : list.instances) p.size = size;
    }
    const fx::BillboardReach reach = benchReach(s.view);
    const fx::TileBins::Range range{0, list.particleCount(), false};
    fx::TileBins bins;
    // range(2): 0 the lists (Entries), 1 the GPU's words (Pairs), 2 the words without first entries
    // (Ranges: the GPU orders the particles).
    const fx::TileBins::Fill fill = state.range(2) == 2 ? fx::TileBins::Fill::Ranges
                                    : state.range(2)    ? fx::TileBins::Fill::Pairs
                                                        : fx::TileBins::Fill::Entries;
    for (auto _ : state) {
        fx::binParticles(s.view, list.instances.data(), &range, 1, &reach, &bins, fx::Jobs(&host), fill);
        benchmark::DoNotOptimize(bins.entries.data());
        benchmark::DoNotOptimize(bins.particles.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * list.particleCount());
    state.counters["entries"] = double(bins.entryCount);
    state.counters["tiles"] = double(bins.tileCount());
}

void BM_TileBins(benchmark::State& state) { tileBinsBench(state, 0.0f); }
void BM_TileBinsLarge(benchmark::State& state) { tileBinsBench(state, 8.0f); }

// range(2): 1 builds without the back-to-front sort (deferOrder: what the tiled path's GPU order
// leaves the CPU), 2 without the gather either (deferGather).
void BM_DrawListBuildJobs(benchmark::State& state) {
    Scene s(int(state.range(0)));
    bench::JobsHost host(int(state.range(1)));
    const fx::ParticleBatch batch = s.batch();
    fx::DrawListBuilder builder;
    fx::DrawList list;
    for (auto _ : state) {
        builder.build(s.view, &batch, 1, fx::Technique::FromReaction, kAll, &list, fx::Jobs(&host), state.range(2) != 0,
                      state.range(2) == 2);
        benchmark::DoNotOptimize(list.instances.data());
        benchmark::DoNotOptimize(list.pendingKeep.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * state.range(0));
}

void BM_GatherJobs(benchmark::State& state) {
    Scene s(int(state.range(0)));
    bench::JobsHost host(int(state.range(1)));
    const fx::ParticleBatch batch = s.batch();
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, kAll, &list, fx::Jobs(&host), true, true);
    std::vector<fx::ParticleInstance> to(size_t(list.particleCount()));
    for (auto _ : state) {
        list.gatherInto(to.data(), fx::Jobs(&host));
        benchmark::DoNotOptimize(to.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * list.particleCount());
    state.SetBytesProcessed(int64_t(state.iterations()) * list.particleCount() * int64_t(sizeof(fx::ParticleInstance)));
}

void BM_CopyJobs(benchmark::State& state) {
    Scene s(int(state.range(0)));
    bench::JobsHost host(int(state.range(1)));
    const fx::ParticleBatch batch = s.batch();
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, kAll, &list, fx::Jobs(&host), true);
    std::vector<fx::ParticleInstance> to(size_t(list.particleCount()));
    const size_t bytes = size_t(list.particleCount()) * sizeof(fx::ParticleInstance);
    const fx::Pieces pieces = fx::splitWork(bytes, 512 * 1024, 16);  // copyMappedInPieces's
    const fx::Jobs jobs(&host);
    for (auto _ : state) {
        jobs.run(pieces, [&](uint32_t piece) {
            const size_t first = pieces.begin(piece);
            std::memcpy(reinterpret_cast<char*>(to.data()) + first,
                        reinterpret_cast<const char*>(list.instances.data()) + first, pieces.end(piece) - first);
        });
        benchmark::DoNotOptimize(to.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * list.particleCount());
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes));
}

void BM_ScreenRectJobs(benchmark::State& state) {
    Scene s(int(state.range(0)));
    bench::JobsHost host(int(state.range(1)));
    const fx::ParticleBatch batch = s.batch();
    fx::DrawListBuilder builder;
    fx::DrawList list;
    builder.build(s.view, &batch, 1, fx::Technique::FromReaction, kAll, &list);
    fx::ScreenTiles tiles;
    for (auto _ : state) {
        fx::screenRect(s.view, list.instances.data(), list.particleCount(), &tiles, fx::Footprint::Billboard,
                       fx::Jobs(&host));
        benchmark::DoNotOptimize(tiles.vertices.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * list.particleCount());
}

}  // namespace

// Thread counts: 1, 2 and, on a machine with more, every hardware thread (a GPU machine's 16).
std::vector<int64_t> threadCounts() {
    const int64_t all = int64_t(std::thread::hardware_concurrency());
    std::vector<int64_t> t = {1, 2};
    if (all > 2) t.push_back(all);
    return t;
}
BENCHMARK(BM_DrawListBuildJobs)->ArgsProduct({{16000, 256000, 1000000}, threadCounts(), {0, 1, 2}})->UseRealTime();
BENCHMARK(BM_GatherJobs)->ArgsProduct({{16000, 256000, 1000000}, threadCounts()})->UseRealTime();
BENCHMARK(BM_CopyJobs)->ArgsProduct({{16000, 256000, 1000000}, threadCounts()})->UseRealTime();
BENCHMARK(BM_ScreenRectJobs)->ArgsProduct({{16000, 256000, 1000000}, threadCounts()})->UseRealTime();
BENCHMARK(BM_DrawListBuild)->Arg(1000)->Arg(16000)->Arg(256000)->Arg(1000000);
BENCHMARK(BM_ScreenRect)->Arg(1000)->Arg(16000)->Arg(256000)->Arg(1000000);
BENCHMARK(BM_ScreenRectBox)->Arg(1000)->Arg(16000)->Arg(256000)->Arg(1000000);
BENCHMARK(BM_ScreenRectTrimmed)->Arg(1000)->Arg(16000)->Arg(256000)->Arg(1000000);
BENCHMARK(BM_TileBins)->ArgsProduct({{1000, 16000, 256000, 1000000}, threadCounts(), {0, 1, 2}})->UseRealTime();
BENCHMARK(BM_TileBinsLarge)->ArgsProduct({{300, 1000}, {1, 2}, {0, 1}})->UseRealTime();
BENCHMARK(BM_InstanceCopy)->Arg(1000)->Arg(16000)->Arg(256000)->Arg(1000000);

BENCHMARK_MAIN();
