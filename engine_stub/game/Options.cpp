#include "game/Options.h"

#include "game/TechniqueModes.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include <unistd.h>

#include <glm/glm.hpp>

namespace cube {

bool parseInt(const std::string& s, long long lo, long long hi, long long* out) {
    if (s.empty()) return false;
    errno = 0;
    char* end = nullptr;
    long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) return false;
    *out = v;
    return true;
}

bool parseDouble(const std::string& s, double lo, double hi, double* out) {
    if (s.empty()) return false;
    errno = 0;
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (errno != 0 || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) return false;
    *out = v;
    return true;
}

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> parts;
    for (size_t start = 0;;) {
        const size_t comma = text.find(',', start);
        parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return parts;
}

namespace {

bool parseSize(const std::string& s, int* w, int* h) {
    size_t x = s.find('x');
    if (x == std::string::npos) return false;
    long long a = 0, b = 0;
    if (!parseInt(s.substr(0, x), 1, 16384, &a) || !parseInt(s.substr(x + 1), 1, 16384, &b)) return false;
    *w = int(a);
    *h = int(b);
    return true;
}

// The folder an output file goes into ("." for a bare name).
std::string folderOf(const std::string& file) {
    const size_t slash = file.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : file.substr(0, slash);
}

bool writableFolder(const std::string& flag, const std::string& folder, std::string* error) {
    if (::access(folder.c_str(), F_OK) != 0) {
        *error = flag + ": folder '" + folder + "' does not exist; create it first";
        return false;
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0) {
        *error = flag + ": folder '" + folder + "' is not writable";
        return false;
    }
    return true;
}

}  // namespace

bool checkOptions(const Options& o, std::string* error) {
    if (o.split && o.splitAlone != 0) {
        *error = "--split and --split-alone: the first draws both halves, the second one of them alone; give one";
        return false;
    }
    if (o.split && o.prepassEqual) {
        // The split views share one colour target, so neither can swap in its own prepass z-buffer.
        *error = "--split and --prepass-equal: the two views draw into one framebuffer, which cannot take "
                 "either view's prepass z-buffer; leave one out";
        return false;
    }
    if (o.frames == 0 && !o.window) {
        *error = "--frames 0 runs until the window closes, and without --window there is none; "
                 "give --frames N (N >= 1) or add --window";
        return false;
    }
    if (o.fixedCamera) {
        const glm::vec3 eye(o.cameraEye[0], o.cameraEye[1], o.cameraEye[2]);
        const glm::vec3 target(o.cameraTarget[0], o.cameraTarget[1], o.cameraTarget[2]);
        const glm::vec3 d = target - eye;
        const float len = glm::length(d);
        if (!(len > 1e-3f)) {
            *error = "--camera: the eye is on the target (distance " + std::to_string(len) +
                     " m); expected them at least 1 mm apart";
            return false;
        }
        // The camera's up is +Y: a view along Y leaves its roll undefined.
        if (glm::length(glm::cross(d / len, glm::vec3(0.0f, 1.0f, 0.0f))) < 1e-3f) {
            *error = "--camera: the view from eye to target is parallel to the up axis (+Y); "
                     "expected a view that is not straight up or down";
            return false;
        }
    }
    // --explode-at T acts in the first step whose end reaches T; T = --start (0 by default) is the
    // first step. The drive starts at --start, so a T before it never comes; legacy smoke has no
    // explosion. Whether an on_demand "explosion" is loaded is checked once the reactions are
    // (Game::checkExplodeAt), still before the first frame.
    if (o.explodeAt >= 0.0 && o.fx == FxPath::Legacy) {
        *error = "--explode-at: fires the plugin's explosion recipe; expected --fx plugin (the default), got --fx legacy";
        return false;
    }
    auto seconds = [](double s) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", s);
        return std::string(text);
    };
    if (o.explodeAt >= 0.0 && o.explodeAt < o.startTime) {
        *error = "--explode-at " + seconds(o.explodeAt) + ": the drive starts at --start " + seconds(o.startTime) +
                 " s, so it would never fire; expected a time at or after the start";
        return false;
    }
    // With a fixed step the run's last drive time is known: a T past it never comes.
    if (o.explodeAt >= 0.0 && o.fixedDt > 0.0 && o.frames > 0) {
        const double end = o.startTime + double(o.frames) * double(float(o.fixedDt));
        if (o.explodeAt > end + 1e-6 * std::max(1.0, end)) {
            *error = "--explode-at " + seconds(o.explodeAt) + ": the run ends at drive time " + seconds(end) +
                     " s (--start + --frames x --fixed-dt), so it would never fire; expected a time up to the end";
            return false;
        }
    }
    if (o.panel && o.fx == FxPath::Legacy) {
        *error = "--panel: edits the plugin's reactions; expected --fx plugin (the default), got --fx legacy";
        return false;
    }
    if (!o.screenshot.empty() && !writableFolder("--screenshot", folderOf(o.screenshot), error)) return false;
    if (!o.statsJson.empty() && !writableFolder("--stats-json", folderOf(o.statsJson), error)) return false;
    if (o.screenshotEvery > 0 && !writableFolder("--screenshot-every", o.screenshotDir, error)) return false;
    return true;
}

std::string usage() {
    return
        "usage: cube_game [options]\n"
        "  --help                 this text\n"
        "  --frames N             frames to run (default 300; 0 = until the window closes,\n"
        "                         with --window only)\n"
        "  --size WxH             view size, 1..16384 each (default 1280x1024)\n"
        "  --fixed-dt S           fixed time step in seconds, 0..10 (default: wall clock)\n"
        "  --start S              seconds into the scripted drive at frame 0 (default 0)\n"
        "  --explode-at T         fire reactions/explosion.yaml at the car at drive time T s\n"
        "  --seed N               random seed, 0..4294967295 (default 1)\n"
        "  --screenshot PATH      PNG of the last frame\n"
        "  --screenshot-every K DIR  PNG every K frames into DIR\n"
        "  --scene PATH           glTF scene (default data/race.gltf)\n"
        "  --reactions PATH       reaction .yaml file or folder (default reactions/)\n"
        "  --legacy-reactions PATH  legacy smoke data file (default data/legacy_smoke.yaml)\n"
        "  --car-node NAME        the scene node that drives (default car; without one the\n"
        "                         camera frames the model and nothing drives)\n"
        "  --fx legacy|plugin     old hard sprites or the plugin (default plugin)\n"
        "  --mode hard|soft|spherical|mega|reaction  technique override (default: each reaction's)\n"
        "  --prepass-equal        opaque pass reuses the prepass z-buffer with depth test EQUAL\n"
        "  --fx-depth graph|linear|zbuffer  the plugin's scene depth: frame-graph passes that sample\n"
        "                         the z-buffer the opaque pass drew, in place (default); frame-graph\n"
        "                         passes reading a linear R32F target the opaque pass writes as a\n"
        "                         second render target (API 2.0's contract, for comparison); or the\n"
        "                         plugin's immediate path (Plugin::renderView) on the z-buffer\n"
        "  --quarter-res          particles into a half x half target, depth-aware composite, in each\n"
        "                         view where that is cheaper than full res (enough smoke overdraw)\n"
        "  --quarter-res-always   quarter res in every view (implies --quarter-res)\n"
        "  --bilinear-upsample    quarter-res with plain bilinear upsampling (comparison)\n"
        "  --watch                reload changed reaction files while running\n"
        "  --window               open a window (same as --backend glfw)\n"
        "  --backend osmesa|egl|glfw  context backend (default osmesa)\n"
        "  --near N --far F       chase camera clip planes (default 0.1, 2000)\n"
        "  --depth reversed|standard  z-buffer: reversed-Z in 32-bit float where the context\n"
        "                         has clip control (default), or 24-bit standard depth\n"
        "  --camera ex,ey,ez,tx,ty,tz  pin the main camera (world metres) instead of chasing the car\n"
        "  --sun AZ,EL            sun direction in degrees: azimuth in the ground plane from +X\n"
        "                         (the track) toward +Z, any value (wraps); elevation above the\n"
        "                         horizon, 1..90 (default 131.2,58.0)\n"
        "  --fog START,END | exp,D | exp2,D  fog the track and the smoke as GL's fixed-function\n"
        "                         fog does: linear from START to END metres, or exp / exp2 with\n"
        "                         density D per metre, in the horizon's haze colour (default off)\n"
        "  --no-mirror            leave out the rear-view mirror view\n"
        "  --split                two-player split screen: two chase cameras (behind the car, and\n"
        "                         beside it from its left) side by side in one framebuffer, each\n"
        "                         with its own smoke; no mirror, no HUD\n"
        "  --split-alone left|right  only that half's camera over the whole window (no mirror,\n"
        "                         no HUD): what each half of --split must equal\n"
        "  --no-hud               leave out the HUD\n"
        "  --unlit-smoke          draw the smoke without the sun (no lighting, no smoke shadow)\n"
        "  --panel                the live tweak panel: every reaction key on a widget, render\n"
        "                         switches, pass timings; Save writes the file back (also headless)\n"
        "  --threads N            threads for the plugin's culling, sorting and bounding, the frame\n"
        "                         thread included, 0..64 (default 0: one per hardware thread; 1 = all\n"
        "                         on the frame thread)\n"
        "  --stats-json PATH      write frame statistics at exit\n"
        "SIGINT/SIGTERM finish the current frame, write --screenshot and --stats-json, exit 130/143.\n"
        "Environment: CUBE_OSMESA_LIBRARY, CUBE_EGL_LIBRARY, CUBE_GLFW_LIBRARY load a back end from\n"
        "another file; CUBE_SHADER_DIR reads shaders (the plugin's too) from a folder; CUBE_ROOT.\n"
        "Window keys: P prepass-EQUAL, Q quarter-res, M technique, B bilinear, H HUD,\n"
        "E the explosion recipe at the car (reactions/explosion.yaml), Esc quit.\n";
}

bool parseOptions(int argc, const char* const* argv, Options* out, std::string* error) {
    // The flags without a value: each sets one option.
    struct Switch {
        const char* flag;
        bool Options::*option;
        bool value;
    };
    static const Switch kSwitches[] = {
        {"--prepass-equal", &Options::prepassEqual, true}, {"--quarter-res", &Options::quarterRes, true},
        {"--quarter-res-always", &Options::quarterResAlways, true},
        {"--bilinear-upsample", &Options::bilinearUpsample, true}, {"--watch", &Options::watch, true},
        {"--no-mirror", &Options::mirror, false}, {"--no-hud", &Options::hud, false},
        {"--unlit-smoke", &Options::litSmoke, false}, {"--panel", &Options::panel, true},
        {"--split", &Options::split, true}};
    Options o;
    auto need = [&](int& i, int count, const std::string& flag) -> bool {
        if (i + count >= argc) {
            *error = flag + ": missing value";
            return false;
        }
        return true;
    };
    // A path flag given an empty value would silently mean "the default": refuse it.
    auto path = [&](int& i, const std::string& flag, std::string* dst) -> bool {
        if (!need(i, 1, flag)) return false;
        const std::string v = argv[++i];
        if (v.empty()) {
            *error = flag + ": expected a path, got an empty string";
            return false;
        }
        *dst = v;
        return true;
    };
    // The next argument as a number in [lo, hi] into *dst; else "flag: expected <what>, got '...'".
    auto real = [&](int& i, const std::string& flag, double lo, double hi, const char* what, double* dst) -> bool {
        if (!need(i, 1, flag)) return false;
        if (parseDouble(argv[++i], lo, hi, dst)) return true;
        *error = flag + ": expected " + what + ", got '" + argv[i] + "'";
        return false;
    };
    // The same for a whole number.
    auto whole = [&](int& i, const std::string& flag, long long lo, long long hi, const char* what,
                     long long* dst) -> bool {
        if (!need(i, 1, flag)) return false;
        if (parseInt(argv[++i], lo, hi, dst)) return true;
        *error = flag + ": expected " + what + ", got '" + argv[i] + "'";
        return false;
    };
    // The next argument, one of two words: *isFirst says whether it is `first`. Else
    // "flag: expected <first> or <second>, got '...'".
    auto either = [&](int& i, const std::string& flag, const char* first, const char* second, bool* isFirst) -> bool {
        if (!need(i, 1, flag)) return false;
        const std::string v = argv[++i];
        if (v != first && v != second) {
            *error = flag + ": expected " + first + " or " + second + ", got '" + v + "'";
            return false;
        }
        *isFirst = v == first;
        return true;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        long long n = 0;
        double d = 0.0;
        const Switch* const sw = std::find_if(std::begin(kSwitches), std::end(kSwitches),
                                              [&](const Switch& s) { return a == s.flag; });
        if (sw != std::end(kSwitches)) {
            o.*(sw->option) = sw->value;
        } else if (a == "--help" || a == "-h") {
            o.help = true;
        } else if (a == "--frames") {
            if (!whole(i, a, 0, 100000000, "a whole number 0..100000000", &n)) return false;
            o.frames = int(n);
        } else if (a == "--size") {
            if (!need(i, 1, a)) return false;
            if (!parseSize(argv[++i], &o.width, &o.height)) {
                *error = "--size: expected WxH with each 1..16384, got '" + std::string(argv[i]) + "'";
                return false;
            }
        } else if (a == "--fixed-dt") {
            if (!real(i, a, 0.0, 10.0, "seconds in 0..10", &d)) return false;
            o.fixedDt = d;
        } else if (a == "--start") {
            if (!real(i, a, 0.0, 1e6, "seconds in 0..1e6", &d)) return false;
            o.startTime = d;
        } else if (a == "--explode-at") {
            if (!real(i, a, 0.0, 1e6, "seconds in 0..1e6", &d)) return false;
            o.explodeAt = d;
        } else if (a == "--seed") {
            if (!whole(i, a, 0, 4294967295LL, "a whole number 0..4294967295", &n)) return false;
            o.seed = unsigned(n);
        } else if (a == "--screenshot") {
            if (!path(i, a, &o.screenshot)) return false;
        } else if (a == "--screenshot-every") {
            if (!need(i, 2, a)) return false;
            if (!whole(i, a, 1, 100000000, "K >= 1", &n)) return false;
            o.screenshotEvery = int(n);
            if (!path(i, a, &o.screenshotDir)) return false;
        } else if (a == "--scene") {
            if (!path(i, a, &o.scene)) return false;
        } else if (a == "--reactions") {
            if (!path(i, a, &o.reactions)) return false;
        } else if (a == "--legacy-reactions") {
            if (!path(i, a, &o.legacyReactions)) return false;
        } else if (a == "--car-node") {
            if (!need(i, 1, a)) return false;
            o.carNode = argv[++i];
            if (o.carNode.empty()) {
                *error = "--car-node: expected a node name, got an empty string";
                return false;
            }
        } else if (a == "--fx") {
            bool legacy = false;
            if (!either(i, a, "legacy", "plugin", &legacy)) return false;
            o.fx = legacy ? FxPath::Legacy : FxPath::Plugin;
        } else if (a == "--mode") {
            if (!need(i, 1, a)) return false;
            std::string v = argv[++i];
            if (!findTechniqueMode(v)) {
                std::string words;
                for (const TechniqueMode& m : kTechniqueModes) words += std::string(words.empty() ? "" : ", ") + m.word;
                *error = "--mode: expected one of " + words + ", got '" + v + "'";
                return false;
            }
            o.mode = v;
        } else if (a == "--split-alone") {
            bool right = false;
            if (!either(i, a, "right", "left", &right)) return false;
            o.splitAlone = right ? 2 : 1;
        } else if (a == "--fx-depth") {
            if (!need(i, 1, a)) return false;
            const std::string v = argv[++i];
            if (v != "graph" && v != "linear" && v != "zbuffer") {
                *error = a + ": expected graph, linear or zbuffer, got '" + v + "'";
                return false;
            }
            o.pluginZBuffer = v == "zbuffer";
            o.pluginLinearDepth = v == "linear";
        } else if (a == "--window") {
            o.window = true;
            o.backend = Backend::GLFW;
        } else if (a == "--backend") {
            if (!need(i, 1, a)) return false;
            if (!parseBackend(argv[++i], &o.backend)) {
                *error = "--backend: expected osmesa, egl or glfw, got '" + std::string(argv[i]) + "'";
                return false;
            }
            if (o.backend == Backend::GLFW) o.window = true;
        } else if (a == "--near" || a == "--far") {
            if (!real(i, a, 1e-4, 1e9, "a distance in 1e-4..1e9 metres", &d)) return false;
            (a == "--near" ? o.nearPlane : o.farPlane) = float(d);
        } else if (a == "--depth") {
            if (!either(i, a, "reversed", "standard", &o.reversedZ)) return false;
        } else if (a == "--camera") {
            if (!need(i, 1, a)) return false;
            const std::string text = argv[++i];
            const std::vector<std::string> parts = splitCommas(text);
            double v[6] = {};
            bool ok = parts.size() == 6;
            for (size_t k = 0; ok && k < 6; ++k) ok = parseDouble(parts[k], -1e6, 1e6, &v[k]);
            if (!ok) {
                *error = "--camera: expected ex,ey,ez,tx,ty,tz (six numbers in metres), got '" + text + "'";
                return false;
            }
            o.fixedCamera = true;
            for (int k = 0; k < 3; ++k) {
                o.cameraEye[k] = float(v[k]);
                o.cameraTarget[k] = float(v[3 + k]);
            }
        } else if (a == "--sun") {
            if (!need(i, 1, a)) return false;
            const std::string text = argv[++i];
            const std::vector<std::string> parts = splitCommas(text);
            constexpr double kHuge = std::numeric_limits<double>::max();
            double az = 0.0, el = 0.0;
            if (parts.size() != 2 || !parseDouble(parts[0], -kHuge, kHuge, &az) ||
                !parseDouble(parts[1], -kHuge, kHuge, &el)) {
                *error = "--sun: expected AZIMUTH,ELEVATION (two finite numbers in degrees, e.g. 200,10), got '" +
                         text + "'";
                return false;
            }
            if (!validSunAngles(az, el)) {
                *error = "--sun: expected an elevation in 1..90 degrees above the horizon, got '" + parts[1] + "'";
                return false;
            }
            o.sunAzimuth = az;
            o.sunElevation = el;
        } else if (a == "--fog") {
            if (!need(i, 1, a)) return false;
            const std::string text = argv[++i];
            const std::vector<std::string> parts = splitCommas(text);
            double x = 0.0, y = 0.0;
            SceneFog fog;
            bool ok = parts.size() == 2;
            if (ok && (parts[0] == "exp" || parts[0] == "exp2")) {
                fog.mode = parts[0] == "exp" ? SceneFog::Mode::Exp : SceneFog::Mode::Exp2;
                ok = parseDouble(parts[1], 0.0, 1e3, &x);
                fog.density = float(x);
            } else if (ok) {
                fog.mode = SceneFog::Mode::Linear;
                ok = parseDouble(parts[0], 0.0, 1e7, &x) && parseDouble(parts[1], 0.0, 1e7, &y) && y > x;
                fog.start = float(x);
                fog.end = float(y);
            }
            if (!ok) {
                *error = "--fog: expected START,END (metres, 0 <= START < END), exp,DENSITY or exp2,DENSITY "
                         "(0..1000 per metre), got '" + text + "'";
                return false;
            }
            o.fog = fog;
        } else if (a == "--threads") {
            if (!whole(i, a, 0, 64, "a whole number 0..64 (0 = one per hardware thread)", &n)) return false;
            o.threads = int(n);
        } else if (a == "--stats-json") {
            if (!path(i, a, &o.statsJson)) return false;
        } else {
            *error = "unknown option '" + a + "' (see --help)";
            return false;
        }
    }
    if (o.nearPlane >= o.farPlane) {
        *error = "--near must be smaller than --far";
        return false;
    }
    if (o.window && o.backend != Backend::GLFW) {
        *error = "--window needs --backend glfw (or no --backend)";
        return false;
    }
    if (!o.help && !checkOptions(o, error)) return false;
    *out = o;
    return true;
}

}  // namespace cube
