#pragma once
// Figures from a run's raw samples: what the table, JSON, CSV and chart print.
#include <string>
#include <utility>
#include <vector>

#include "fxbench_measure.h"

namespace fxbench {

/// One mode's figures. Every number is finite (ratios without a base are 0, PSNR is capped).
struct ModeSummary {
    std::string name, setup, reference;
    bool selected = true;
    int samples = 0;
    double fpsMin = 0, fpsAvg = 0, fpsMax = 0;  ///< avg = 1000 / mean frame ms
    double p50 = 0, p95 = 0, p99 = 0;           ///< frame ms
    double ratioVsHard = 0, ratioVsNofx = 0;    ///< median frame ms / base's median
    std::vector<std::pair<std::string, double>> passes;  ///< median ms per pass, run order
    double particleMs = 0;                      ///< median of the per-frame sum of particle passes
    double outsidePassesMs = 0;                 ///< median of frame ms - sum of pass ms (ModeRun)
    double declareMs = 0, executeMs = 0, finishMs = 0;  ///< medians of the frame's CPU stretches (ModeRun)
    double particleFragments = 0;               ///< median over error frames of the samples the particle passes wrote
    std::vector<std::pair<std::string, double>> passFragments;  ///< the same per particle pass, run order
    std::vector<std::pair<std::string, double>> passShaded;     ///< per particle pass: fragment shader invocations
    double particles = 0;                       ///< median particles drawn (0 for nofx)
    double coveragePct = 0;                     ///< share of pixels the particles changed
    double fillLimitMs = 0;                     ///< median fill-limit draw over that coverage
    double fillLimitRatio = 0;                  ///< median of particleMs / fillLimitMs; 0 = none
    double rmse = 0, psnrDb = 0, maxAbs = 0, edgePct = 0;
    int errorFrames = 0;
    int allocatingRenders = 0;
};

/// Defaults: empty.
struct Report {
    std::string scenario, description;
    int width = 0, height = 0, frames = 0, rounds = 0, warmup = 0, errorFrames = 0;
    unsigned seed = 0;
    bool mirror = false;
    std::string renderer, backend, timingMethod;
    int threads = 0;  ///< job-system threads the plugin's parallel work ran on
    double particlesAlive = 0, edgePixelPct = 0, simMsPerFrame = 0;
    /// The live particles a particle sweep point asked for (0: not a sweep point) and the run's
    /// pool slots, emitted and dropped particles (RunResult).
    double particlesRequested = 0, particleCapacity = 0, particlesEmitted = 0, particlesDropped = 0;
    std::vector<ModeSummary> modes;     ///< the selected modes, table order
    std::vector<ModeSummary> internal;  ///< measured only as references / bases
    std::vector<std::string> notes;
};

ModeSummary summarise(const ModeRun& run, const ModeRun* hard, const ModeRun* nofx);
Report makeReport(const RunConfig& config, const RunResult& result, unsigned seed);

/// The edge, coverage and timing definitions, for the table's footer and the JSON.
const char* edgeDefinition();
const char* coverageDefinition();
const char* outsidePassesDefinition();
const char* frameCpuDefinition();

/// A particle sweep point reached its count when the median live particles are within this
/// share below the requested count (never above: capacity = count).
constexpr double kSweepReachTolerance = 0.05;
/// Sets r.particlesRequested and, when the point fell short of it by more than
/// kSweepReachTolerance, adds a note saying why (pool capacity, emission, deaths).
void noteParticlesReached(Report* r, double requested);

}  // namespace fxbench
