#pragma once
// Order statistics over timing samples.
#include <vector>

namespace fxbench {

/// The q-quantile (q in [0, 1]) by linear interpolation between closest ranks; 0 for no samples.
double quantile(std::vector<double> samples, double q);
inline double median(const std::vector<double>& samples) { return quantile(samples, 0.5); }
double mean(const std::vector<double>& samples);
double minOf(const std::vector<double>& samples);
double maxOf(const std::vector<double>& samples);

}  // namespace fxbench
