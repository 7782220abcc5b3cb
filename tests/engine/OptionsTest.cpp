#include <gtest/gtest.h>

#include "game/Options.h"

using cube::Options;

namespace {
bool parse(std::vector<const char*> args, Options* o, std::string* err) {
    args.insert(args.begin(), "cube_game");
    return cube::parseOptions(int(args.size()), args.data(), o, err);
}
}  // namespace

TEST(Options, DefaultsMatchTheDocumentation) {
    Options o;
    std::string err;
    ASSERT_TRUE(parse({}, &o, &err));
    EXPECT_EQ(o.width, 1280);
    EXPECT_EQ(o.height, 1024);
    EXPECT_EQ(o.backend, cube::Backend::OSMesa);
    EXPECT_EQ(o.fx, cube::FxPath::Plugin);
    EXPECT_FALSE(o.prepassEqual);
    EXPECT_FALSE(o.quarterRes);
}

TEST(Options, GoodValuesParse) {
    Options o;
    std::string err;
    ASSERT_TRUE(parse({"--frames", "12", "--size", "640x480", "--fixed-dt", "0.02", "--seed", "99", "--fx",
                       "legacy", "--mode", "spherical", "--prepass-equal", "--quarter-res", "--backend", "egl",
                       "--screenshot-every", "5", "/tmp", "--stats-json", "s.json"},
                      &o, &err))
        << err;
    EXPECT_EQ(o.frames, 12);
    EXPECT_EQ(o.width, 640);
    EXPECT_EQ(o.height, 480);
    EXPECT_DOUBLE_EQ(o.fixedDt, 0.02);
    EXPECT_EQ(o.seed, 99u);
    EXPECT_EQ(o.fx, cube::FxPath::Legacy);
    EXPECT_EQ(o.mode, "spherical");
    EXPECT_TRUE(o.prepassEqual && o.quarterRes);
    EXPECT_EQ(o.backend, cube::Backend::EGL);
    EXPECT_EQ(o.screenshotEvery, 5);
    EXPECT_EQ(o.screenshotDir, "/tmp");
}

TEST(Options, ModeMegaParses) {
    Options o;
    std::string err;
    ASSERT_TRUE(parse({"--mode", "mega"}, &o, &err)) << err;
    EXPECT_EQ(o.mode, "mega");
    Options bad;
    EXPECT_FALSE(parse({"--mode", "megaa"}, &bad, &err));
    EXPECT_NE(err.find("mega"), std::string::npos) << err;  // the message lists it
}

TEST(Options, BadValuesAreRejectedNamingTheFlag) {
    const std::vector<std::vector<const char*>> bad = {
        {"--frames", "-1"},      {"--frames", "ten"},        {"--size", "0x10"},      {"--size", "640"},
        {"--size", "99999x10"},  {"--fixed-dt", "nan"},      {"--fixed-dt", "-0.1"},  {"--fixed-dt", "inf"},
        {"--seed", "-3"},        {"--fx", "shiny"},          {"--mode", "fuzzy"},     {"--backend", "vulkan"},
        {"--bogus"},             {"--frames"},               {"--screenshot-every", "0", "d"},
        {"--near", "10", "--far", "1"}, {"--window", "--backend", "osmesa"},
    };
    for (const auto& args : bad) {
        Options o;
        std::string err;
        EXPECT_FALSE(parse(args, &o, &err)) << args[0];
        EXPECT_FALSE(err.empty());
        const std::string flag = args[0];
        if (flag != "--bogus" && flag != "--window" && flag != "--near") {
            EXPECT_NE(err.find(flag), std::string::npos) << err;
        }
    }
}

// Issue 15: values that parse but cannot make a sensible run are refused before it starts.
TEST(Options, RunsThatCannotWorkAreRefusedBeforeTheyStart) {
    const std::vector<std::pair<std::vector<const char*>, std::string>> bad = {
        {{"--frames", "0"}, "--window"},
        {{"--scene", ""}, "--scene"},
        {{"--reactions", ""}, "--reactions"},
        {{"--legacy-reactions", ""}, "--legacy-reactions"},
        {{"--screenshot", ""}, "--screenshot"},
        {{"--stats-json", ""}, "--stats-json"},
        {{"--screenshot-every", "3", ""}, "--screenshot-every"},
        {{"--car-node", ""}, "--car-node"},
        {{"--screenshot", "/nonexistent-folder-for-cube-test/x.png"}, "does not exist"},
        {{"--stats-json", "/proc/cube_test/s.json"}, "--stats-json"},
        {{"--camera", "4,4,4,4,4,4"}, "eye is on the target"},
        {{"--camera", "0,10,0,0,-5,0"}, "parallel to the up axis"},
        {{"--camera", "0,1,0,inf,0,0"}, "--camera"},
    };
    for (const auto& [args, mention] : bad) {
        Options o;
        std::string err;
        EXPECT_FALSE(parse(args, &o, &err)) << args[0];
        EXPECT_NE(err.find(mention), std::string::npos) << args[0] << ": " << err;
    }
    Options o;
    std::string err;
    EXPECT_TRUE(parse({"--frames", "0", "--window"}, &o, &err)) << err;
    EXPECT_TRUE(parse({"--camera", "0,10,0.5,0,0,0", "--car-node", "truck"}, &o, &err)) << err;
    EXPECT_EQ(o.carNode, "truck");
}
