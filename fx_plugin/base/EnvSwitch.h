#pragma once
// A switch a GPU session sets from the environment for an A/B run without a rebuild (on by default):
// the variable read once, when the library loads; "0" turns it off, "1" or unset leaves it on, and
// anything else is kept as a problem for the renderer to log once and ignored. Tests set and reset
// it. (TiledPath's CUBEFX_TILED_DEFER_BINS, CUBEFX_TILED_GPU_BINS and CUBEFX_TILED_GATHER_IN_PASS,
// QuarterResPath's CUBEFX_QUARTER_CHOICE_IN_PASS.)
#include <atomic>
#include <cstdlib>
#include <cstring>

namespace fx {

class EnvSwitch {
public:
    /// `problemIfBad`: the line to log where the variable is set to neither 0 nor 1.
    EnvSwitch(const char* variable, const char* problemIfBad) {
        const char* v = std::getenv(variable);
        if (v && *v) {
            if (std::strcmp(v, "0") == 0 || std::strcmp(v, "1") == 0) {
                fromEnvironment_ = v[0] - '0';
            } else {
                problem_ = problemIfBad;
            }
        }
        value_.store(fromEnvironment_, std::memory_order_relaxed);
    }
    bool on() const { return value_.load(std::memory_order_relaxed) != 0; }
    void set(bool on) { value_.store(on ? 1 : 0, std::memory_order_relaxed); }
    void reset() { value_.store(fromEnvironment_, std::memory_order_relaxed); }  ///< back to the environment's
    const char* problem() const { return problem_; }  ///< what was wrong with the variable, or null

private:
    int fromEnvironment_ = -1;  // -1: unset or unreadable (on)
    const char* problem_ = nullptr;
    std::atomic<int> value_{-1};
};

}  // namespace fx
