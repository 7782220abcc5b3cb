// fxbench's command line, parsed in-process: --threads reaches the game's options, with the
// range and default of cube_game's flag.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fxbench_options.h"
#include "fxbench_scenarios.h"

namespace fxbenchoptions_test {

bool parse(std::vector<const char*> args, fxbench::BenchOptions* o, std::string* err) {
    args.insert(args.begin(), "fxbench");
    return fxbench::parseBenchOptions(int(args.size()), args.data(), o, err);
}

}  // namespace fxbenchoptions_test

using fxbenchoptions_test::parse;

TEST(FxbenchOptions, ThreadsDefaultsToOnePerHardwareThreadAndReachesTheGame) {
    fxbench::BenchOptions o;
    std::string err;
    ASSERT_TRUE(parse({}, &o, &err)) << err;
    EXPECT_EQ(o.threads, 0);
    const fxbench::Scenario* standard = fxbench::findScenario("standard");
    ASSERT_NE(standard, nullptr);
    EXPECT_EQ(fxbench::gameOptions(*standard, o).threads, 0);
    for (const char* n : {"0", "1", "3", "64"}) {
        ASSERT_TRUE(parse({"--quick", "--threads", n}, &o, &err)) << n << ": " << err;
        EXPECT_EQ(o.threads, std::stoi(n));
        EXPECT_EQ(fxbench::gameOptions(*standard, o).threads, std::stoi(n));
    }
    EXPECT_NE(fxbench::benchUsage().find("--threads N"), std::string::npos);
}

TEST(FxbenchOptions, BadThreadCountsAreRejectedNamingTheFlagAndTheRange) {
    for (const char* bad : {"65", "-1", "junk", "2.5"}) {
        SCOPED_TRACE(bad);
        fxbench::BenchOptions o;
        std::string err;
        EXPECT_FALSE(parse({"--threads", bad}, &o, &err));
        EXPECT_EQ(err, std::string("--threads: expected an integer in 0..64, got '") + bad + "'");
    }
    fxbench::BenchOptions o;
    std::string err;
    EXPECT_FALSE(parse({"--threads"}, &o, &err));
    EXPECT_EQ(err, "--threads: missing value");
}
