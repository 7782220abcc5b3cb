#pragma once
// `--sweep`: the same interleaved measurement at several amounts of work, printed as cost curves.
#include <string>

#include "fxbench_options.h"

namespace fxbench {

/// Runs every sweep point (a new Game each), prints each point's report and then the cost
/// curves to stdout, and writes --json / --csv / --chart. Returns the process exit code.
int runSweep(const BenchOptions& options);

/// The most particles one generated reaction holds: the schema's highest `rate` (particles/s per
/// wheel), so that its pool fills within about 1.5 s of the burnout donut at any count.
constexpr int kSweepParticlesPerReaction = 100000;
/// Simulated before a particle sweep point's warm-up: every point starts at the same drive time.
constexpr double kSweepPrerollSeconds = 2.0;

/// Reactions particleSweepYaml(particles) writes: ceil(particles / kSweepParticlesPerReaction).
int sweepReactionCount(int particles);

/// A reaction file (reactions/README.md schema) that keeps `particles` live particles: rear-wheel
/// smoke split into sweepReactionCount() reactions whose capacities add up to `particles`, each
/// with rate = capacity (at least 10) so that every pool fills within about 1.5 s of the donut,
/// and lifetimes (8-10 s) longer than the run, so the pools stay full. Small puffs
/// (0.15 -> 0.6 m) so the curve shows per-particle cost more than fill.
std::string particleSweepYaml(int particles);

}  // namespace fxbench
