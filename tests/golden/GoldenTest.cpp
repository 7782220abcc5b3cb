// Golden hashes of what the engine produces, kept equal across restructurings: the pixels of
// small frames in every mode and optimization (fixed seed and time step), the CUBE call trace,
// and the deterministic part of the stats JSON. An intended change regenerates golden.txt with
// scripts/update_golden.sh and says why in its commit.
//
// Pixels depend on the rasterizer: the file records the GL renderer it was made with, and on
// another renderer the frame hashes are skipped (the trace and stats are still compared).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../engine/GameTestUtil.h"
#include "gl/Gl.h"
#include "platform/Trace.h"

using namespace cube;

namespace {

const std::string kGoldenFile = std::string(CUBE_SOURCE_DIR) + "/tests/golden/golden.txt";

uint64_t fnv1a(const void* data, size_t size, uint64_t h = 1469598103934665603ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

std::string hex(uint64_t v) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

struct Config {
    const char* name;
    FxPath fx;
    const char* mode;  // "" = each reaction's own technique
    bool equal, quarter, bilinear, mirror, hud;
    const char* reactions;  // "" = reactions/
};

const Config kConfigs[] = {
    {"legacy", FxPath::Legacy, "", false, false, false, false, false, ""},
    {"reaction", FxPath::Plugin, "", false, false, false, false, false, ""},
    {"reaction_mirror_hud", FxPath::Plugin, "", false, false, false, true, true, ""},
    {"none_yaml", FxPath::Plugin, "", false, false, false, true, false, "/reactions/none.yaml"},
    {"hard", FxPath::Plugin, "hard", false, false, false, false, false, ""},
    {"hard_equal", FxPath::Plugin, "hard", true, false, false, false, false, ""},
    {"hard_quarter", FxPath::Plugin, "hard", false, true, false, false, false, ""},
    {"soft", FxPath::Plugin, "soft", false, false, false, false, false, ""},
    {"soft_equal", FxPath::Plugin, "soft", true, false, false, false, false, ""},
    {"soft_quarter", FxPath::Plugin, "soft", false, true, false, false, false, ""},
    {"soft_quarter_bilinear", FxPath::Plugin, "soft", false, true, true, false, false, ""},
    {"soft_equal_quarter", FxPath::Plugin, "soft", true, true, false, false, false, ""},
    {"spherical", FxPath::Plugin, "spherical", false, false, false, false, false, ""},
    {"spherical_equal", FxPath::Plugin, "spherical", true, false, false, false, false, ""},
    {"spherical_quarter", FxPath::Plugin, "spherical", false, true, false, false, false, ""},
};

Options optionsFor(const Config& c) {
    Options o = cubetest::smallOptions(160, 128);
    o.startTime = 4.5;
    o.fx = c.fx;
    o.mode = c.mode;
    o.prepassEqual = c.equal;
    o.quarterRes = c.quarter;
    o.quarterResAlways = c.quarter;  // the quarter-res path itself, however light the smoke
    o.bilinearUpsample = c.bilinear;
    o.mirror = c.mirror;
    o.hud = c.hud;
    if (*c.reactions) o.reactions = std::string(CUBE_SOURCE_DIR) + c.reactions;
    return o;
}

// The stats JSON without what depends on the machine (renderer, timings, memory).
std::string deterministicStats(const Game& game) {
    const std::string path = testing::TempDir() + "/golden_stats.json";
    std::string error;
    if (!game.writeStatsJson(path, &error)) return "cannot write: " + error;
    std::ifstream in(path);
    std::string line, kept;
    while (std::getline(in, line)) {
        static const char* kSkip[] = {"\"renderer\"", "\"timing_method\"", "\"rss_", "\"frame_ms",
                                      "\"pool_max_live", "\"backend\""};
        bool skip = false;
        for (const char* k : kSkip) skip = skip || line.find(k) != std::string::npos;
        if (!skip) kept += line + "\n";
    }
    return kept;
}

struct Measured {
    std::string renderer;
    std::map<std::string, std::string> values;  // "frame NAME" / "stats NAME" / "trace" -> hash
};

Measured measure() {
    Measured m;
    for (const Config& c : kConfigs) {
        Game game;
        std::string err;
        if (!game.Init(optionsFor(c), &err)) {
            ADD_FAILURE() << c.name << ": " << err;
            continue;
        }
        m.renderer = game.platform().rendererName();
        const bool traced = std::string(c.name) == "reaction_mirror_hud";
        if (traced) {
            Trace::clear();
            Trace::enable(true);
        }
        cubetest::runFrames(game, 45);
        if (traced) {
            Trace::enable(false);
            std::string joined;
            for (const std::string& call : Trace::calls()) joined += call + "\n";
            m.values["trace"] = hex(fnv1a(joined.data(), joined.size()));
        }
        const ImageRGBA8& img = game.lastFrame();
        m.values[std::string("frame ") + c.name] = hex(fnv1a(img.pixels.data(), img.pixels.size()));
        const std::string stats = deterministicStats(game);
        m.values[std::string("stats ") + c.name] = hex(fnv1a(stats.data(), stats.size()));
        EXPECT_EQ(gl::errorCount(), 0) << c.name << ": " << gl::lastError();
    }
    return m;
}

TEST(Golden, FramesTraceAndStatsAreUnchanged) {
    const Measured now = measure();
    if (std::getenv("CUBE_GOLDEN_UPDATE")) {
        std::ofstream out(kGoldenFile);
        out << "# Regenerate with scripts/update_golden.sh after an intended change; say why in the commit.\n";
        out << "renderer " << now.renderer << "\n";
        for (const auto& [key, value] : now.values) out << key << " " << value << "\n";
        GTEST_SKIP() << "wrote " << kGoldenFile;
    }
    std::ifstream in(kGoldenFile);
    ASSERT_TRUE(in) << kGoldenFile << " is missing: run scripts/update_golden.sh";
    std::string line, renderer;
    std::map<std::string, std::string> golden;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (line.rfind("renderer ", 0) == 0) {
            renderer = line.substr(9);
            continue;
        }
        const size_t sp = line.rfind(' ');
        golden[line.substr(0, sp)] = line.substr(sp + 1);
    }
    const bool sameRenderer = renderer == now.renderer;
    int compared = 0;
    for (const auto& [key, value] : golden) {
        if (!sameRenderer && key.rfind("frame ", 0) == 0) continue;
        auto it = now.values.find(key);
        ASSERT_NE(it, now.values.end()) << key << " is no longer measured";
        EXPECT_EQ(it->second, value) << key << " changed";
        ++compared;
    }
    EXPECT_EQ(golden.size(), now.values.size()) << "configurations added or removed: update golden.txt";
    EXPECT_GE(compared, 17);
    if (!sameRenderer) {
        GTEST_SKIP() << "frame hashes not compared: golden.txt was made on \"" << renderer
                     << "\", this is \"" << now.renderer << "\" (trace and stats were)";
    }
}

}  // namespace
