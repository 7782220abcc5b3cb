#include "fxbench_options.h"

#include <algorithm>
#include <cstring>
#include <iterator>

#include "fxbench_modes.h"
#include "fxbench_scenarios.h"
#include "game/Options.h"

namespace fxbench {

namespace {

bool parseSize(const std::string& s, int* w, int* h) {
    const size_t x = s.find('x');
    long long a = 0, b = 0;
    if (x == std::string::npos || !cube::parseInt(s.substr(0, x), 16, 8192, &a) ||
        !cube::parseInt(s.substr(x + 1), 16, 8192, &b))
        return false;
    *w = int(a);
    *h = int(b);
    return true;
}

bool parseSweep(const std::string& text, Sweep* out, std::string* error) {
    const size_t eq = text.find('=');
    const std::string kind = text.substr(0, eq);
    if (eq == std::string::npos || (kind != "particles" && kind != "size")) {
        *error = "--sweep: expected particles=N,N,... or size=WxH,WxH,..., got '" + text + "'";
        return false;
    }
    *out = Sweep{};
    for (const std::string& item : cube::splitCommas(text.substr(eq + 1))) {
        if (kind == "particles") {
            long long n = 0;
            if (!cube::parseInt(item, 1, 1000000, &n)) {
                *error = "--sweep particles: expected particle counts 1..1000000, got '" + item + "'";
                return false;
            }
            out->kind = Sweep::Kind::Particles;
            out->counts.push_back(int(n));
        } else {
            int w = 0, h = 0;
            if (!parseSize(item, &w, &h)) {
                *error = "--sweep size: expected WxH with each 16..8192, got '" + item + "'";
                return false;
            }
            out->kind = Sweep::Kind::Size;
            out->sizes.emplace_back(w, h);
        }
    }
    return true;
}

}  // namespace

std::string benchUsage() {
    return "usage: fxbench [options]\n"
           "Renders every simulated frame of a scripted drive in several particle modes, interleaved,\n"
           "and prints Table 1 of the thesis (min/max/average FPS) with frame-time percentiles, per-pass\n"
           "times, the fill limit and image error against a reference mode.\n"
           "  --help                 this text\n"
           "  --quick                small configuration: 320x256, 8 frames, 2 rounds, 2 warm-up, 2 error frames\n"
           "                         (later flags still override it)\n"
           "  --scenario NAME        " + scenarioNameList() + " (default standard)\n"
           "  --modes a,b,...        subset of: " + modeNameList() + " (default all)\n"
           "  --size WxH             view size, 16..8192 each (default 1280x1024)\n"
           "  --frames N             timed simulated frames, 1..100000 (default 30)\n"
           "  --rounds R             renders of each simulated frame per mode, 1..1000 (default 2)\n"
           "  --warmup N             untimed frames rendered in every mode first, 0..10000 (default 5)\n"
           "  --error-frames N       frames that also get image error and the fill limit, 0..1000 (default 3)\n"
           "  --seed N               random seed, 0..4294967295 (default 1)\n"
           "  --backend osmesa|egl   GL context (default osmesa: llvmpipe)\n"
           "  --depth reversed|standard  engine z-buffer: reversed-Z float (default; soft and spherical\n"
           "                         particles are z-tested) or standard 24-bit (they are not)\n"
           "  --mirror               draw the rear-view mirror (default off)\n"
           "  --threads N            job-system threads for the plugin's culling, sorting and bounding,\n"
           "                         the frame thread included, 0..64 (default 0: one per hardware thread)\n"
           "  --json PATH            results as JSON\n"
           "  --csv PATH             results as CSV (one row per mode)\n"
           "  --chart PATH           SVG: frame time per mode and error vs time (sweeps: cost curves)\n"
           "  --images DIR           PNG of every mode's last error frame, and the depth-edge mask\n"
           "  --sweep particles=N,N,...   cost curve over live particle counts 1..1000000 (generated reactions;\n"
           "                              each point reports the count it asked for and the count reached)\n"
           "  --sweep size=WxH,WxH,...    cost curve over view sizes (a new game per size)\n"
           "  --integrators          integrator error vs the analytic drag solution, and CPU cost\n";
}

bool parseBenchOptions(int argc, const char* const* argv, BenchOptions* out, std::string* error) {
    *out = BenchOptions{};
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) {
            out->quick = true;
            out->width = 320;
            out->height = 256;
            out->frames = 8;
            out->rounds = 2;
            out->warmup = 2;
            out->errorFrames = 2;
        }
    }
    // The flags that set a whole-number option, with the range each accepts.
    struct IntFlag {
        const char* flag;
        long long lo, hi;
        int BenchOptions::*option;
    };
    static const IntFlag kIntFlags[] = {{"--frames", 1, 100000, &BenchOptions::frames},
                                        {"--rounds", 1, 1000, &BenchOptions::rounds},
                                        {"--warmup", 0, 10000, &BenchOptions::warmup},
                                        {"--error-frames", 0, 1000, &BenchOptions::errorFrames},
                                        {"--threads", 0, 64, &BenchOptions::threads}};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](std::string* v) {
            if (i + 1 >= argc || argv[i + 1][0] == '\0') {
                *error = a + ": missing value";
                return false;
            }
            *v = argv[++i];
            return true;
        };
        auto integer = [&](long long lo, long long hi, long long* v) {
            std::string s;
            if (!value(&s)) return false;
            if (!cube::parseInt(s, lo, hi, v)) {
                *error = a + ": expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got '" +
                         s + "'";
                return false;
            }
            return true;
        };
        std::string s;
        long long n = 0;
        const IntFlag* const intFlag = std::find_if(std::begin(kIntFlags), std::end(kIntFlags),
                                                    [&](const IntFlag& f) { return a == f.flag; });
        if (intFlag != std::end(kIntFlags)) {
            if (!integer(intFlag->lo, intFlag->hi, &n)) return false;
            out->*(intFlag->option) = int(n);
        } else if (a == "--help" || a == "-h") {
            out->help = true;
        } else if (a == "--quick") {
            // applied above
        } else if (a == "--integrators") {
            out->integrators = true;
        } else if (a == "--mirror") {
            out->mirror = true;
        } else if (a == "--scenario") {
            if (!value(&s)) return false;
            if (!findScenario(s)) {
                *error = "--scenario: unknown scenario '" + s + "'; valid scenarios: " + scenarioNameList();
                return false;
            }
            out->scenario = s;
        } else if (a == "--modes") {
            if (!value(&s) || !parseModeList(s, &out->modes, error)) return false;
        } else if (a == "--size") {
            if (!value(&s)) return false;
            if (!parseSize(s, &out->width, &out->height)) {
                *error = "--size: expected WxH with each 16..8192, got '" + s + "'";
                return false;
            }
        } else if (a == "--seed") {
            if (!integer(0, 4294967295LL, &n)) return false;
            out->seed = unsigned(n);
        } else if (a == "--backend") {
            if (!value(&s)) return false;
            if (s == "osmesa") out->backend = cube::Backend::OSMesa;
            else if (s == "egl") out->backend = cube::Backend::EGL;
            else {
                *error = "--backend: expected osmesa or egl, got '" + s + "'";
                return false;
            }
        } else if (a == "--depth") {
            if (!value(&s)) return false;
            if (s != "reversed" && s != "standard") {
                *error = "--depth: expected reversed or standard, got '" + s + "'";
                return false;
            }
            out->reversedZ = s == "reversed";
        } else if (a == "--json") {
            if (!value(&out->json)) return false;
        } else if (a == "--csv") {
            if (!value(&out->csv)) return false;
        } else if (a == "--chart") {
            if (!value(&out->chart)) return false;
        } else if (a == "--images") {
            if (!value(&out->imagesDir)) return false;
        } else if (a == "--sweep") {
            if (!value(&s) || !parseSweep(s, &out->sweep, error)) return false;
        } else {
            *error = "unknown option '" + a + "' (see --help)";
            return false;
        }
    }
    return true;
}

}  // namespace fxbench
