#include "fxbench_stats.h"

#include <algorithm>
#include <cmath>

namespace fxbench {

double quantile(std::vector<double> samples, double q) {
    if (samples.empty()) return 0.0;
    std::sort(samples.begin(), samples.end());
    const double pos = std::clamp(q, 0.0, 1.0) * double(samples.size() - 1);
    const size_t lo = size_t(std::floor(pos));
    const size_t hi = std::min(lo + 1, samples.size() - 1);
    const double t = pos - double(lo);
    return samples[lo] + (samples[hi] - samples[lo]) * t;
}

double mean(const std::vector<double>& samples) {
    if (samples.empty()) return 0.0;
    double s = 0.0;
    for (double v : samples) s += v;
    return s / double(samples.size());
}

double minOf(const std::vector<double>& samples) {
    return samples.empty() ? 0.0 : *std::min_element(samples.begin(), samples.end());
}

double maxOf(const std::vector<double>& samples) {
    return samples.empty() ? 0.0 : *std::max_element(samples.begin(), samples.end());
}

}  // namespace fxbench
