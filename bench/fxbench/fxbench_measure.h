#pragma once
// The interleaved measurement: one Game, one simulation; every simulated frame is rendered in
// every mode (rounds x, mode order rotated), and a few frames also get image error, coverage
// and the fill limit. Raw samples only; fxbench_summary turns them into figures.
#include <map>
#include <string>
#include <vector>

#include "fxbench_image_error.h"
#include "fxbench_modes.h"
#include "fxbench_scenarios.h"
#include "game/Options.h"

namespace fxbench {

/// Defaults: nothing to run.
struct RunConfig {
    const Scenario* scenario = nullptr;
    cube::Options game;                  ///< from gameOptions()
    cube::CameraQuads cameraQuads;       ///< from cameraQuads(): the scenario's overdraw panels
    int frames = 0, rounds = 1, warmup = 0, errorFrames = 0;
    std::vector<std::string> selected;   ///< modes asked for (empty = all)
    std::string imagesDir;               ///< PNGs of the last error frame (empty = none)
    std::string progressLabel;           ///< prefix of the stderr progress line
};

/// Every sample one mode produced.
struct ModeRun {
    const Mode* mode = nullptr;
    bool selected = false;                          ///< asked for (else measured as a reference)
    std::vector<double> frameMs;                    ///< one per timed render (RenderFrame wall ms)
    std::vector<double> particleMs;                 ///< per timed render: passes named *particles*
    /// Per timed render: frame ms minus the sum of every pass's ms of that render (the CPU
    /// clock's frame less the timer's passes): declaring, compiling and culling the graph, the
    /// CPU work between passes and, with GPU timer queries, GPU time outside any pass.
    std::vector<double> outsidePassesMs;
    /// Per timed render, Game::lastFrameCpu: the CPU's declaring (before any pass runs: the
    /// plugin's cull, sort and bins among it), executing (issuing the passes) and glFinish wait.
    std::vector<double> declareMs, executeMs, finishMs;
    std::map<std::string, std::vector<double>> passMs;
    std::vector<std::string> passOrder;             ///< pass names in first-run order
    std::vector<double> particlesDrawn;
    int allocatingRenders = 0;                      ///< timed renders that created pool targets
    ErrorAccum error;
    std::vector<double> fillMs, fillRatio, coveragePct;  ///< one per error frame
    std::vector<double> particleFragments;          ///< per error frame: samples the particle passes wrote
    /// Per particle pass, per error frame: the samples it wrote (GL_SAMPLES_PASSED: fragments
    /// neither discarded nor depth-rejected), e.g. the pixels a composite blended.
    std::map<std::string, std::vector<double>> passFragments;
    /// The same, fragment shader invocations (GL_FRAGMENT_SHADER_INVOCATIONS_ARB: what the pass
    /// shaded, discarded fragments included); empty without ARB_pipeline_statistics_query.
    std::map<std::string, std::vector<double>> passShaded;
    std::vector<double> frameParticleMs;            ///< scratch: this simulated frame's rounds
};

struct RunResult {
    std::string renderer, backend, timingMethod;
    int threads = 0;                   ///< the game's job-system threads, the frame thread included
    std::vector<ModeRun> modes;        ///< measured modes in table order (selected + references)
    double particlesAlive = 0.0;       ///< median over timed frames
    double edgePixelPct = 0.0;         ///< share of pixels next to depth edges (error frames)
    double simMsPerFrame = 0.0;        ///< median Game::Update wall ms
    /// At the end of the run, over every reaction (Plugin::stats, reactionStats): pool slots,
    /// particles that entered a pool, particles due while their pool was full.
    double particleCapacity = 0.0, particlesEmitted = 0.0, particlesDropped = 0.0;
    int glErrors = 0;
};

/// The run of `scenario` that `bench` asks for: its game options, overdraw panels, frame counts
/// and modes; no images, no progress label.
RunConfig runConfig(const Scenario& scenario, const BenchOptions& bench);

/// The modes a run measures for `selected`: those plus nofx (coverage), hard (ratio base) and
/// each selected mode's reference, in table order.
std::vector<const Mode*> measuredModes(const std::vector<std::string>& selected);

/// Runs it. False + error when the game cannot start.
bool runBench(const RunConfig& config, RunResult* out, std::string* error);

}  // namespace fxbench
