// bench_loaders: how long a hostile YAML file costs the loaders before they refuse it. Speed is
// measured here, not in a timed test (STYLE.md 12); the tests assert only the refusal's code.
//
//   BM_LegacyAliasBomb/L    data/legacy_smoke.yaml's loader (cube::loadLegacySmokeText) on an
//                           alias bomb of L levels, ten aliases wide (10^L paths in ~60 L bytes)
//                           in the `reactions:` list: L = 9 nests 10 levels, past the 8-level
//                           limit (error[TooDeep], the alias bomb); L = 7 nests 8, within it, so
//                           only the 20,000-visit budget of the nesting check bounds the walk
//                           (then WrongType: lists where reaction maps belong)
//   BM_ReactionAliasBomb/L  the same text as a reaction file (fx::loadReactionText), whose
//                           YamlCheck::subtreeDepth has the same budget: the reference
//
// Before the budget the legacy loader took 9.5 s of CPU on L = 9. Run:
//   bench_loaders --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "reactions/ReactionLoader.h"
#include "scene/LegacySmokeDesc.h"

namespace {

// reactions: a list of `levels` alias levels, each a list of ten aliases of the one before
// (fuzz/seeds/legacy/alias_bomb_9x10.yaml is levels = 9).
std::string aliasBomb(int levels) {
    std::string text = "reactions:\n  - &l0 [x, x, x, x, x, x, x, x, x, x]\n";
    for (int l = 1; l < levels; ++l) {
        const std::string below = "*l" + std::to_string(l - 1);
        text += "  - &l" + std::to_string(l) + " [";
        for (int k = 0; k < 10; ++k) text += below + (k < 9 ? ", " : "]\n");
    }
    return text;
}

void BM_LegacyAliasBomb(benchmark::State& state) {
    const std::string text = aliasBomb(int(state.range(0)));
    for (auto _ : state) {
        std::vector<cube::LegacySmokeDesc> out;
        fx::Diagnostics diags;
        benchmark::DoNotOptimize(cube::loadLegacySmokeText(text, "bomb.yaml", &out, &diags));
        if (diags.empty()) state.SkipWithError("the bomb was accepted");
    }
}
BENCHMARK(BM_LegacyAliasBomb)->Arg(7)->Arg(9)->Unit(benchmark::kMillisecond);

void BM_ReactionAliasBomb(benchmark::State& state) {
    const std::string text = aliasBomb(int(state.range(0)));
    for (auto _ : state) {
        fx::ReactionSet set;
        fx::Diagnostics diags;
        benchmark::DoNotOptimize(fx::loadReactionText(text, "bomb.yaml", &set, &diags));
        if (diags.empty()) state.SkipWithError("the bomb was accepted");
    }
}
BENCHMARK(BM_ReactionAliasBomb)->Arg(7)->Arg(9)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
