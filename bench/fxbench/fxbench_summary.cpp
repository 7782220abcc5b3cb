#include "fxbench_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fxbench_stats.h"

namespace fxbench {

const char* edgeDefinition() {
    return "pixels within 1 px of a depth edge of the chase view (second difference of inverse linear "
           "depth > 10% of the pixel's, along x or y; fxbench renders the depth with the engine's prepass "
           "program); edge % = share of those whose max RGB error > 8/255";
}

const char* coverageDefinition() {
    return "pixels whose RGB differs from the nofx frame of the same simulated frame";
}

const char* outsidePassesDefinition() {
    return "median over timed renders of the frame's ms (CPU clock around glFinish) minus the sum of that "
           "render's pass ms: declaring, culling and compiling the frame graph and the CPU work between "
           "passes; with GPU timer queries also GPU time outside any pass";
}

const char* frameCpuDefinition() {
    return "the frame's CPU wall ms in three stretches (Game::lastFrameCpu): declare, from the frame's start to "
           "its graph's first pass (culling, declaring, the plugin's particle cull, sort and bins, the graph's "
           "compile: the GPU has nothing of this frame yet); execute, issuing the passes (draws, dispatches, "
           "uploads); finish, glFinish's wait for the GPU";
}

ModeSummary summarise(const ModeRun& run, const ModeRun* hard, const ModeRun* nofx) {
    ModeSummary s;
    s.name = run.mode->name;
    s.setup = run.mode->setup;
    s.reference = run.mode->reference;
    s.selected = run.selected;
    s.samples = int(run.frameMs.size());
    if (!run.frameMs.empty()) {
        s.fpsMin = 1000.0 / maxOf(run.frameMs);
        s.fpsMax = 1000.0 / minOf(run.frameMs);
        s.fpsAvg = 1000.0 / mean(run.frameMs);
        s.p50 = median(run.frameMs);
        s.p95 = quantile(run.frameMs, 0.95);
        s.p99 = quantile(run.frameMs, 0.99);
    }
    const double hardP50 = hard ? median(hard->frameMs) : 0.0;
    const double nofxP50 = nofx ? median(nofx->frameMs) : 0.0;
    s.ratioVsHard = hardP50 > 0.0 ? s.p50 / hardP50 : 0.0;
    s.ratioVsNofx = nofxP50 > 0.0 ? s.p50 / nofxP50 : 0.0;
    for (const std::string& name : run.passOrder) s.passes.emplace_back(name, median(run.passMs.at(name)));
    s.particleMs = median(run.particleMs);
    s.outsidePassesMs = median(run.outsidePassesMs);
    s.declareMs = median(run.declareMs);
    s.executeMs = median(run.executeMs);
    s.finishMs = median(run.finishMs);
    s.particleFragments = median(run.particleFragments);
    for (const std::string& name : run.passOrder) {
        const auto it = run.passFragments.find(name);
        if (it != run.passFragments.end()) s.passFragments.emplace_back(name, median(it->second));
        const auto sh = run.passShaded.find(name);
        if (sh != run.passShaded.end()) s.passShaded.emplace_back(name, median(sh->second));
    }
    s.particles = median(run.particlesDrawn);
    s.coveragePct = median(run.coveragePct);
    s.fillLimitMs = median(run.fillMs);
    s.fillLimitRatio = median(run.fillRatio);
    s.rmse = run.error.rmse();
    s.psnrDb = run.error.frames ? run.error.psnrDb() : kPsnrCapDb;
    s.maxAbs = run.error.maxAbs;
    s.edgePct = run.error.edgePct();
    s.errorFrames = run.error.frames;
    s.allocatingRenders = run.allocatingRenders;
    return s;
}

Report makeReport(const RunConfig& config, const RunResult& result, unsigned seed) {
    Report r;
    r.scenario = config.scenario->name;
    r.description = config.scenario->description;
    r.width = config.game.width;
    r.height = config.game.height;
    r.frames = config.frames;
    r.rounds = config.rounds;
    r.warmup = config.warmup;
    r.errorFrames = config.errorFrames;
    r.seed = seed;
    r.mirror = config.game.mirror;
    r.renderer = result.renderer;
    r.backend = result.backend;
    r.timingMethod = result.timingMethod;
    r.threads = result.threads;
    r.particlesAlive = result.particlesAlive;
    r.edgePixelPct = result.edgePixelPct;
    r.simMsPerFrame = result.simMsPerFrame;
    r.particleCapacity = result.particleCapacity;
    r.particlesEmitted = result.particlesEmitted;
    r.particlesDropped = result.particlesDropped;
    const ModeRun* hard = nullptr;
    const ModeRun* nofx = nullptr;
    for (const ModeRun& m : result.modes) {
        if (std::string(m.mode->name) == "hard") hard = &m;
        if (std::string(m.mode->name) == "nofx") nofx = &m;
    }
    std::string added;
    for (const ModeRun& m : result.modes) {
        ModeSummary s = summarise(m, hard, nofx);
        if (m.selected) {
            r.modes.push_back(std::move(s));
        } else {
            added += (added.empty() ? "" : ", ") + s.name;
            r.internal.push_back(std::move(s));
        }
    }
    if (!added.empty())
        r.notes.push_back("also measured (not shown) as reference / base: " + added);
    int allocs = 0;
    for (const ModeRun& m : result.modes) allocs += m.allocatingRenders;
    if (allocs > 0) {
        char line[320];
        std::snprintf(line, sizeof line,
                      "%d timed renders created or freed render targets (a target's first use or a pool trim); each "
                      "was repeated and the repeat timed (see allocating_renders)",
                      allocs);
        r.notes.push_back(line);
    }
    if (r.scenario == "empty") {
        // The claim this scenario checks: a frame with no reactions costs what the bare engine costs.
        double lo = 1e300, hi = 0.0;
        for (const ModeSummary& m : r.modes) {
            if (m.name == "nofx") continue;
            lo = std::min(lo, m.ratioVsNofx);
            hi = std::max(hi, m.ratioVsNofx);
        }
        if (hi > 0.0) {
            char line[200];
            std::snprintf(line, sizeof line, "empty scenario: median frame ms / nofx's ranges %.3f .. %.3f over the "
                                             "particle modes (1 = costs what the bare engine costs)", lo, hi);
            r.notes.push_back(line);
        }
    }
    if (result.glErrors > 0) r.notes.push_back("GL errors were reported during the run: " + std::to_string(result.glErrors));
    return r;
}

void noteParticlesReached(Report* r, double requested) {
    r->particlesRequested = requested;
    if (requested <= 0.0 || r->particlesAlive >= (1.0 - kSweepReachTolerance) * requested) return;
    char line[400];
    std::snprintf(line, sizeof line, "reached %.0f of %.0f particles asked (%.1f%%; tolerance %.0f%%): ",
                  r->particlesAlive, requested, 100.0 * r->particlesAlive / requested, 100.0 * kSweepReachTolerance);
    std::string why = line;
    if (r->particleCapacity < requested) {
        std::snprintf(line, sizeof line, "the pools hold %.0f", r->particleCapacity);
    } else if (r->particlesEmitted < requested) {
        std::snprintf(line, sizeof line, "emission too slow: %.0f emitted by the end of the run", r->particlesEmitted);
    } else {
        std::snprintf(line, sizeof line,
                      "%.0f emitted (%.0f due at full pools, dropped), but particles died before or during the "
                      "timed frames",
                      r->particlesEmitted, r->particlesDropped);
    }
    r->notes.push_back(why + line);
}

}  // namespace fxbench
