#pragma once
// `--sweep`: the same interleaved measurement at several amounts of work, printed as cost curves.
#include <string>

#include "fxbench_options.h"

namespace fxbench {

/// Runs every sweep point (a new Game each), prints each point's report and then the cost
/// curves to stdout, and writes --json / --csv / --chart. Returns the process exit code.
int runSweep(const BenchOptions& options);

/// A reaction file (reactions/README.md schema) that keeps `particles` live particles: rear-wheel
/// smoke with capacity = particles, a rate that fills the pool within about 1.5 s of the donut,
/// and lifetimes (8-10 s) longer than the run, so the pool stays full. Small puffs (0.15 -> 0.6 m)
/// so the curve shows per-particle cost more than fill.
std::string particleSweepYaml(int particles);

}  // namespace fxbench
