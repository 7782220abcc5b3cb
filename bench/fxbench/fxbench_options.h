#pragma once
// fxbench's command line. Parsing is separate from main() so tests and other tools can feed it
// bad values; every rejection names the flag and what was expected.
#include <string>
#include <vector>

#include "platform/Platform.h"

namespace fxbench {

/// One `--sweep` request: `particles=1000,10000` (live particle counts) or
/// `size=640x512,1280x1024` (view sizes).
struct Sweep {
    enum class Kind { None, Particles, Size };
    Kind kind = Kind::None;
    std::vector<int> counts;                     ///< Particles: live particles per point
    std::vector<std::pair<int, int>> sizes;      ///< Size: (width, height) per point
};

/// Defaults: the standard scenario at 1280x1024 on OSMesa, every mode, 30 timed frames with
/// 2 rounds each after 5 warm-up frames, seed 1, 3 error frames, mirror off, HUD off, one
/// job-system thread per hardware thread (about 3 minutes for standard on 2 llvmpipe cores).
/// `--quick` (applied before the other flags, which still override it): 320x256, 8 frames,
/// 2 rounds, 2 warm-up frames, 2 error frames.
struct BenchOptions {
    std::string scenario = "standard";
    std::vector<std::string> modes;  ///< empty = every mode, in the table order
    int width = 1280;
    int height = 1024;
    int frames = 30;       ///< timed simulated frames
    int rounds = 2;        ///< renders of each simulated frame per mode (order rotated)
    int warmup = 5;        ///< rendered in every mode, not timed
    int errorFrames = 3;   ///< simulated frames (evenly spaced) that also get image error + fill limit
    unsigned seed = 1;
    cube::Backend backend = cube::Backend::OSMesa;
    bool reversedZ = true;  ///< --depth: the engine's reversed-Z float depth where available
    int threads = 0;       ///< --threads: cube::Options::threads (0 = one per hardware thread)
    bool mirror = false;   ///< the rear-view mirror view and its inset
    bool quick = false;
    bool integrators = false;
    bool help = false;
    Sweep sweep;
    std::string json, csv, chart;
    std::string imagesDir;  ///< PNGs of every mode's last error frame (for eyeballing)
};

/// Parses argv[1..]. False + a message naming the flag and the expected value on bad input.
bool parseBenchOptions(int argc, const char* const* argv, BenchOptions* out, std::string* error);
std::string benchUsage();

}  // namespace fxbench
