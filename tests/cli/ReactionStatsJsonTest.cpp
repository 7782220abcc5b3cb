// --stats-json's reaction_stats: one entry per running reaction with its name,
// technique, particles alive at exit and emitted in total, as the plugin counts them.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "RunCommand.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace reaction_stats_json_test {
namespace {

int runGame(const std::string& args) {
    const std::string cmd = std::string(CUBE_TEST_BIN_DIR) + "/cube_game " + args + " >/dev/null 2>&1";
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128;
}

std::string slurp(const std::string& path) { return cubetest::readFile(path); }

struct Entry {
    std::string technique;
    long alive = -1;
    long emitted = -1;
};

// The entry of reaction `name` in the JSON text, or alive = -1 when it is missing.
Entry entryOf(const std::string& json, const std::string& name) {
    const std::regex re("\\{\"name\": \"" + std::regex_replace(name, std::regex("\\."), "\\.") +
                        "\", \"technique\": \"([a-z_]+)\", \"alive\": ([0-9]+), \"emitted\": ([0-9]+)\\}");
    std::smatch m;
    Entry e;
    if (std::regex_search(json, m, re)) {
        e.technique = m[1];
        e.alive = std::stol(m[2]);
        e.emitted = std::stol(m[3]);
    }
    return e;
}

TEST(ReactionStatsJson, EveryReactionWithNameTechniqueAliveAndEmitted) {
    const std::string s = "/tmp/cube_rstats_" + std::to_string(::getpid()) + ".json";
    // 2 s of the donut burnout (t = 5-7 s): smoke is emitted and alive, nothing else is.
    ASSERT_EQ(runGame("--frames 120 --size 96x80 --fixed-dt 0.0166667 --start 5 --stats-json " + s), 0);
    const std::string j = slurp(s);
    ASSERT_NE(j.find("\"reaction_stats\": ["), std::string::npos) << j;
    const Entry smoke = entryOf(j, "burnout_smoke");
    EXPECT_EQ(smoke.technique, "soft");
    EXPECT_GT(smoke.alive, 100) << j;           // two rear wheels smoking for 2 s
    EXPECT_GE(smoke.emitted, smoke.alive) << j;
    for (const char* quiet : {"barrier_burst", "barrier_scrape.sparks", "offtrack_dust", "tyre_steam"}) {
        const Entry e = entryOf(j, quiet);
        EXPECT_EQ(e.alive, 0) << quiet << " in " << j;   // present, and idle on the asphalt
        EXPECT_EQ(e.emitted, 0) << quiet << " in " << j;
    }
    std::remove(s.c_str());
}

TEST(ReactionStatsJson, NoReactionsGiveAnEmptyList) {
    const std::string s = "/tmp/cube_rstats_none_" + std::to_string(::getpid()) + ".json";
    ASSERT_EQ(runGame("--frames 3 --size 96x80 --fixed-dt 0.0166667 --reactions " + std::string(CUBE_SOURCE_DIR) +
                      "/reactions/none.yaml --stats-json " + s), 0);
    EXPECT_NE(slurp(s).find("\"reaction_stats\": [],"), std::string::npos) << slurp(s);
    std::remove(s.c_str());
}

}  // namespace
}  // namespace reaction_stats_json_test
