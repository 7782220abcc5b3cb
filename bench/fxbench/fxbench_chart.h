#pragma once
// SVG charts, written as text: per-mode frame time bars next to an error-vs-time scatter, and
// cost curves for sweeps.
#include <string>
#include <vector>

#include "fxbench_summary.h"

namespace fxbench {

/// Left: median frame ms per mode as bars (the particle passes' share darker, a whisker to p95).
/// Right: RMSE (8-bit) against median frame ms, one labelled point per mode.
std::string chartSvg(const Report& report);

/// One curve per mode: median frame ms (y) against the sweep's work measure (x); `logScale`:
/// both axes logarithmic (decades), so cost proportional to work is a line of slope 1.
struct SweepSeries {
    std::string mode;
    std::vector<double> x, y;
};
std::string sweepChartSvg(const std::string& title, const std::string& xLabel, const std::vector<SweepSeries>& series,
                          bool logScale);

}  // namespace fxbench
