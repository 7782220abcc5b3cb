// bench_sim: how close the particle update is to the memory bandwidth of this machine.
//
//   BM_ReactionRuntimeStep/N  a full pool of N particles stepped by fx::ReactionRuntime::step
//                             (exact drag, age/kill test, rotation, size, life, fade); bytes =
//                             the 15 float streams of the pool, N * 60 B per step
//   BM_StreamRmw/15/N         reference: read-modify-write sweep over 15 float arrays of N
//                             (the same 60 N bytes read and written once)
//   BM_ApplyDragStep/N        the integrator alone: fx::applyDragStep with coefficients made once
//                             per step (fx::makeDragStep), over N positions and velocities, N * 24 B
//   BM_StreamRmw/6/N          its reference: 6 float arrays, 24 N bytes
//   BM_Memcpy/N               memcpy of N * 60 B (each byte read once and written once)
//
// items_per_second = particle updates per second; bytes_per_second compares each simulation
// benchmark with the reference of the same size: sim / reference = share of the bandwidth-bound
// speed (1 = the update costs no more than touching its data once).
#include <cstring>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "reactions/ReactionDesc.h"
#include "sim/Integrator.h"
#include "sim/ParticlePool.h"
#include "sim/ReactionRuntime.h"

namespace {

constexpr int kPoolStreams = fx::ParticlePool::StreamCount;  // 15 float streams
constexpr float kDt = 1.0f / 60.0f;

// A collision burst that fills the whole pool at once with particles that live 60 s, so the
// pool stays full for 3600 steps (the loop refills it before that).
fx::ReactionDesc fullPoolDesc(int n) {
    fx::ReactionDesc d = fx::defaultReaction(fx::ReactionType::CollisionBurst);
    d.name = "bench_full_pool";
    d.emission.capacity = n;
    d.emission.burst = n;
    d.particle.lifetimeMin = d.particle.lifetimeMax = 60.0f;
    d.particle.spreadSpeed = 3.0f;
    return d;
}

std::unique_ptr<fx::ReactionRuntime> filledRuntime(int n) {
    auto r = std::make_unique<fx::ReactionRuntime>(fullPoolDesc(n));
    r->step(kDt, nullptr, 0, 1.0f, glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0.5f, 0.0f, 0.0f));
    return r;
}

void BM_ReactionRuntimeStep(benchmark::State& state) {
    const int n = int(state.range(0));
    auto runtime = filledRuntime(n);
    int steps = 0;
    int64_t updates = 0;
    for (auto _ : state) {
        if (++steps > 3000) {  // particles would start dying at 60 s: refill, untimed
            state.PauseTiming();
            runtime = filledRuntime(n);
            steps = 1;
            state.ResumeTiming();
        }
        updates += runtime->pool().alive();
        runtime->step(kDt, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(0.5f, 0.0f, 0.0f));
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(updates);
    state.SetBytesProcessed(updates * kPoolStreams * int64_t(sizeof(float)));
    state.counters["alive"] = double(runtime->pool().alive());
}

void BM_ApplyDragStep(benchmark::State& state) {
    const size_t n = size_t(state.range(0));
    std::vector<glm::vec3> x(n, glm::vec3(0.0f, 0.5f, 0.0f)), v(n, glm::vec3(3.0f, 1.0f, -2.0f));
    const glm::vec3 u(0.5f, 0.45f, 0.0f);
    for (auto _ : state) {
        const fx::DragStep s = fx::makeDragStep(1.2f, kDt);  // once per reaction and frame, as the pool does
        for (size_t i = 0; i < n; ++i) fx::applyDragStep(s, u, x[i], v[i]);
        benchmark::DoNotOptimize(x.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(n) * 6 * int64_t(sizeof(float)));
}

void BM_StreamRmw(benchmark::State& state) {
    const int streams = int(state.range(0));
    const size_t n = size_t(state.range(1));
    std::vector<std::vector<float>> a(size_t(streams), std::vector<float>(n, 1.0f));
    for (auto _ : state) {
        for (auto& s : a) {
            float* p = s.data();
            size_t i = 0;
            // Eight independent lanes per iteration, so the sweep runs at SIMD width (-O2's SLP
            // vectoriser) and measures memory, not a scalar dependency chain.
            for (; i + 8 <= n; i += 8) {
                p[i + 0] = p[i + 0] * 0.999f + 0.001f;
                p[i + 1] = p[i + 1] * 0.999f + 0.001f;
                p[i + 2] = p[i + 2] * 0.999f + 0.001f;
                p[i + 3] = p[i + 3] * 0.999f + 0.001f;
                p[i + 4] = p[i + 4] * 0.999f + 0.001f;
                p[i + 5] = p[i + 5] * 0.999f + 0.001f;
                p[i + 6] = p[i + 6] * 0.999f + 0.001f;
                p[i + 7] = p[i + 7] * 0.999f + 0.001f;
            }
            for (; i < n; ++i) p[i] = p[i] * 0.999f + 0.001f;
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(n) * streams * int64_t(sizeof(float)));
}

void BM_Memcpy(benchmark::State& state) {
    const size_t bytes = size_t(state.range(0)) * kPoolStreams * sizeof(float);
    std::vector<char> src(bytes, 1), dst(bytes, 0);
    for (auto _ : state) {
        std::memcpy(dst.data(), src.data(), bytes);
        benchmark::DoNotOptimize(dst.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * state.range(0));
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes));
}

// 1k (L1/L2), 10k, 100k (L2/L3), 1M particles (DRAM: 60 MB of pool).
BENCHMARK(BM_ReactionRuntimeStep)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
BENCHMARK(BM_StreamRmw)->Args({15, 1000})->Args({15, 10000})->Args({15, 100000})->Args({15, 1000000});
BENCHMARK(BM_ApplyDragStep)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
BENCHMARK(BM_StreamRmw)->Args({6, 1000})->Args({6, 10000})->Args({6, 100000})->Args({6, 1000000});
BENCHMARK(BM_Memcpy)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);

}  // namespace

BENCHMARK_MAIN();
