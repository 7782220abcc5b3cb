// bench_sim: how close the particle update is to the memory bandwidth of this machine.
//
//   BM_ReactionRuntimeStep/N  a full pool of N particles stepped by fx::ReactionRuntime::step
//   BM_ReactionRuntimeStepJobs/N/T  the same step in pieces on the engine's job system of T threads
//                             (exact drag, age/kill test, rotation, size, life, fade); bytes =
//                             the 15 float streams of the pool, N * 60 B per step
//   BM_StreamRmw/15/N         reference: read-modify-write sweep over 15 float arrays of N
//                             (the same 60 N bytes read and written once)
//   BM_ApplyDragStep/N        the integrator alone: fx::applyDragStep with coefficients made once
//                             per step (fx::makeDragStep), over N positions and velocities, N * 24 B
//   BM_StreamRmw/6/N          its reference: 6 float arrays, 24 N bytes
//   BM_Memcpy/N               memcpy of N * 60 B (each byte read once and written once)
//   BM_StatelessStep/N        the same N particles as technique: stateless (a full ring of birth
//                             records, 60 s lives): ReactionRuntime::step's CPU cost per frame, which
//                             touches no particle (items = particles kept alive, so the per-particle
//                             figure falls as N grows)
//   BM_StatelessVertexWork/N  what the vertex shader does per frame for N stateless particles, run on
//                             this CPU: the closed form (position, velocity, life, size, alpha) of
//                             sim/StatelessParticle.h, once per quad corner (4 per particle). On a GPU
//                             this runs in parallel off the CPU; under llvmpipe (no GPU) it IS CPU time.
//
// Stateless vs CPU: compare BM_ReactionRuntimeStep (CPU path, per particle per frame, before its
// instance packing and upload) with BM_StatelessStep (stateless CPU cost) and
// BM_StatelessVertexWork (where the work went). Run interleaved for ratios on a noisy machine:
//   bench_sim --benchmark_filter='RuntimeStep|Stateless' --benchmark_repetitions=5
//             --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
//             --benchmark_min_time=0.05
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
#include "sim/Lifecycle.h"
#include "sim/ReactionRuntime.h"
#include "sim/StatelessParticle.h"
#include "BenchJobsHost.h"

namespace {

// The 15 float streams the update touches without turbulence (OriginX/OriginZ, the vortex axis,
// are read only by turbulent reactions and written once at birth).
constexpr int kPoolStreams = fx::ParticlePool::OriginX;
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

// BM_ReactionRuntimeStep, or with `threads` > 0 the step in pieces on the engine's job system of
// that many threads (BM_ReactionRuntimeStepJobs/N/T).
void runtimeStep(benchmark::State& state, int threads) {
    const int n = int(state.range(0));
    std::unique_ptr<bench::JobsHost> host = threads > 0 ? std::make_unique<bench::JobsHost>(threads) : nullptr;
    const fx::Jobs jobs(host.get());
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
        runtime->step(kDt, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(0.5f, 0.0f, 0.0f), jobs);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(updates);
    state.SetBytesProcessed(updates * kPoolStreams * int64_t(sizeof(float)));
    state.counters["alive"] = double(runtime->pool().alive());
}

void BM_ReactionRuntimeStep(benchmark::State& state) { runtimeStep(state, 0); }
void BM_ReactionRuntimeStepJobs(benchmark::State& state) { runtimeStep(state, int(state.range(1))); }

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

std::unique_ptr<fx::ReactionRuntime> filledStateless(int n) {
    fx::ReactionDesc d = fullPoolDesc(n);
    d.render.stateless = true;
    d.render.blend = fx::BlendMode::Additive;
    auto r = std::make_unique<fx::ReactionRuntime>(d);
    r->step(kDt, nullptr, 0, 1.0f, glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0.5f, 0.0f, 0.0f));
    return r;
}

void BM_StatelessStep(benchmark::State& state) {
    const int n = int(state.range(0));
    auto runtime = filledStateless(n);
    for (auto _ : state) {
        runtime->step(kDt, nullptr, 0, 0.0f, glm::vec3(0.0f), glm::vec3(0.5f, 0.0f, 0.0f));
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n);
    state.counters["records"] = double(runtime->ring().written());
}

void BM_StatelessVertexWork(benchmark::State& state) {
    const int n = int(state.range(0));
    auto runtime = filledStateless(n);
    const fx::StatelessRecord* rec = runtime->ring().data();
    const fx::ParticleDesc& p = runtime->desc().particle;
    const glm::vec3 u = runtime->terminal(), g(0.0f, -p.gravity, 0.0f);
    float now = 1.0f;
    for (auto _ : state) {
        now += kDt;
        float sink = 0.0f;
        for (int i = 0; i < n; ++i) {
            const fx::StatelessRecord& r = rec[i];
            for (int corner = 0; corner < 4; ++corner) {  // the shader runs per vertex
                const float age = now - r.birth;
                const glm::vec3 p0(r.p0[0], r.p0[1], r.p0[2]), v0(r.v0[0], r.v0[1], r.v0[2]);
                const glm::vec3 x = fx::statelessPosition(p0, v0, u, g, p.drag, age);
                const glm::vec3 v = fx::statelessVelocity(v0, u, g, p.drag, age);
                const float f = age / r.lifetime;
                const float size = fx::sizeAt(p, r.startSize, r.endSize, f);
                const float alpha = fx::fadeAt(p, f) * fx::evalColorRamp(p.colorRamp, f).a;
                sink += x.x + x.y + x.z + v.x + size * alpha + float(corner);
            }
        }
        benchmark::DoNotOptimize(sink);
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n);
}

// 1k (L1/L2), 10k, 100k (L2/L3), 1M particles (DRAM: 60 MB of pool).
BENCHMARK(BM_ReactionRuntimeStep)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
BENCHMARK(BM_ReactionRuntimeStepJobs)->ArgsProduct({{100000, 1000000}, {1, 2}})->UseRealTime();
BENCHMARK(BM_StreamRmw)->Args({15, 1000})->Args({15, 10000})->Args({15, 100000})->Args({15, 1000000});
BENCHMARK(BM_ApplyDragStep)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
BENCHMARK(BM_StreamRmw)->Args({6, 1000})->Args({6, 10000})->Args({6, 100000})->Args({6, 1000000});
BENCHMARK(BM_Memcpy)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
BENCHMARK(BM_StatelessStep)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
BENCHMARK(BM_StatelessVertexWork)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);

}  // namespace

BENCHMARK_MAIN();
