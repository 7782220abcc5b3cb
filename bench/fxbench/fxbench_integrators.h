#pragma once
// `fxbench --integrators`: explicit Euler, semi-implicit Euler and the plugin's exact drag step,
// position error against the analytic solution at several dt and stiffness, next to CPU cost.
#include <string>

namespace fxbench {

/// The comparison as Markdown (deterministic figures plus CPU timings of this machine).
std::string integratorReport();

}  // namespace fxbench
