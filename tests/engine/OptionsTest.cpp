#include <gtest/gtest.h>

#include <cmath>

#include "game/Options.h"
#include "game/TechniqueModes.h"

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

// Each value-less switch flips its own option from the default and nothing else of these.
TEST(Options, EverySwitchSetsItsOptionAlone) {
    const struct {
        const char* flag;
        bool Options::*option;
    } switches[] = {{"--prepass-equal", &Options::prepassEqual}, {"--quarter-res", &Options::quarterRes},
                    {"--quarter-res-always", &Options::quarterResAlways},
                    {"--bilinear-upsample", &Options::bilinearUpsample}, {"--watch", &Options::watch},
                    {"--no-mirror", &Options::mirror},          {"--no-hud", &Options::hud},
                    {"--unlit-smoke", &Options::litSmoke},       {"--panel", &Options::panel}};
    const Options defaults;
    for (const auto& s : switches) {
        Options o;
        std::string err;
        ASSERT_TRUE(parse({s.flag}, &o, &err)) << s.flag << ": " << err;
        for (const auto& other : switches) {
            if (other.option == s.option) {
                EXPECT_NE(o.*other.option, defaults.*other.option) << s.flag;
            } else {
                EXPECT_EQ(o.*other.option, defaults.*other.option) << s.flag << " changed " << other.flag;
            }
        }
    }
}

TEST(Options, UnlitSmokeIsASwitchAndLitIsTheDefault) {
    Options o;
    std::string err;
    ASSERT_TRUE(parse({}, &o, &err)) << err;
    EXPECT_TRUE(o.litSmoke);
    ASSERT_TRUE(parse({"--unlit-smoke"}, &o, &err)) << err;
    EXPECT_FALSE(o.litSmoke);
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

// Every override word of the table parses to its technique, and --help and the refusal list it.
TEST(Options, EveryTechniqueModeWordParsesAndIsListed) {
    std::string err;
    Options bad;
    EXPECT_FALSE(parse({"--mode", "not_a_mode"}, &bad, &err));
    for (const cube::TechniqueMode& m : cube::kTechniqueModes) {
        Options o;
        std::string e;
        ASSERT_TRUE(parse({"--mode", m.word}, &o, &e)) << m.word << ": " << e;
        EXPECT_EQ(o.mode, m.word);
        ASSERT_NE(cube::findTechniqueMode(o.mode), nullptr);
        EXPECT_EQ(cube::findTechniqueMode(o.mode)->technique, m.technique);
        EXPECT_EQ(&cube::techniqueMode(m.technique), &m) << m.word << ": row i is fx::Technique(i)";
        EXPECT_NE(err.find(m.word), std::string::npos) << err;
        EXPECT_NE(cube::usage().find(m.word), std::string::npos) << m.word << " is missing from --help";
    }
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

// Values that parse but cannot make a sensible run are refused before it starts.
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

// --sun AZIMUTH,ELEVATION in degrees. The default is the sun the race scene had as a
// shader constant, normalize(-0.35, 0.85, 0.40), within 1e-3 per component.
TEST(Options, SunDefaultsToTheFormerConstantSun) {
    Options o;
    std::string err;
    ASSERT_TRUE(parse({}, &o, &err)) << err;
    const glm::vec3 formerSun = glm::normalize(glm::vec3(-0.35f, 0.85f, 0.40f));
    const cube::SunLight sun = cube::sunFromAngles(o.sunAzimuth, o.sunElevation);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sun.toSun[k], formerSun[k], 1e-3f) << k;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(cube::SunLight{}.toSun[k], formerSun[k], 1e-6f) << k;
    // Above 20 degrees the colours are the former constants too.
    EXPECT_EQ(sun.color, cube::SunLight{}.color);
    EXPECT_EQ(sun.ambientSky, cube::SunLight{}.ambientSky);
    EXPECT_EQ(sun.ambientGround, cube::SunLight{}.ambientGround);
}

TEST(Options, SunAnglesParseWrapAndPointWhereTheySay) {
    Options o;
    std::string err;
    ASSERT_TRUE(parse({"--sun", "200,10"}, &o, &err)) << err;
    EXPECT_DOUBLE_EQ(o.sunAzimuth, 200.0);
    EXPECT_DOUBLE_EQ(o.sunElevation, 10.0);
    ASSERT_TRUE(parse({"--sun", "-1e5,90"}, &o, &err)) << err;  // any azimuth, the zenith
    EXPECT_DOUBLE_EQ(o.sunAzimuth, -1e5);
    const float kTol = 1e-5f;
    // Azimuth from +X toward +Z in the ground plane, elevation above it.
    const glm::vec3 along = cube::sunFromAngles(0.0, 1.0).toSun, right = cube::sunFromAngles(90.0, 45.0).toSun;
    EXPECT_NEAR(along.x, std::cos(glm::radians(1.0f)), kTol);
    EXPECT_NEAR(along.y, std::sin(glm::radians(1.0f)), kTol);
    EXPECT_NEAR(along.z, 0.0f, kTol);
    EXPECT_NEAR(right.x, 0.0f, kTol);
    EXPECT_NEAR(right.y, std::sqrt(0.5f), kTol);
    EXPECT_NEAR(right.z, std::sqrt(0.5f), kTol);
    EXPECT_NEAR(cube::sunFromAngles(123.0, 90.0).toSun.y, 1.0f, kTol);
    // Wrapping: 725 = 5 and -355 = 5 degrees.
    for (double az : {725.0, -355.0}) {
        const glm::vec3 d = cube::sunFromAngles(az, 30.0).toSun - cube::sunFromAngles(5.0, 30.0).toSun;
        EXPECT_LT(glm::length(d), 1e-5f) << az;
    }
    // A low sun is warmer: less blue than red.
    const cube::SunLight low = cube::sunFromAngles(200.0, 1.0);
    EXPECT_LT(low.color.b, 0.5f * low.color.r);
}

TEST(Options, BadSunValuesAreRejectedNamingTheFlagAndTheExpectation) {
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"200", "AZIMUTH,ELEVATION"}, {"200,10,3", "AZIMUTH,ELEVATION"}, {"nan,10", "AZIMUTH,ELEVATION"},
        {"10,inf", "AZIMUTH,ELEVATION"}, {"north,up", "AZIMUTH,ELEVATION"}, {",", "AZIMUTH,ELEVATION"},
        {"200,0", "1..90"},           {"200,0.99", "1..90"},          {"200,90.5", "1..90"},
        {"200,-10", "1..90"},
    };
    for (const auto& [value, mention] : bad) {
        Options o;
        std::string err;
        EXPECT_FALSE(parse({"--sun", value.c_str()}, &o, &err)) << value;
        EXPECT_EQ(err.rfind("--sun: ", 0), 0u) << value << ": " << err;
        EXPECT_NE(err.find(mention), std::string::npos) << value << ": " << err;
    }
    Options o;
    std::string err;
    EXPECT_FALSE(parse({"--sun"}, &o, &err));
    EXPECT_NE(err.find("--sun"), std::string::npos) << err;
    EXPECT_NE(cube::usage().find("--sun AZ,EL"), std::string::npos);
}

// --fx-depth: graph (the default: the frame graph samples the z-buffer), linear (the frame graph
// reads a linear R32F target), zbuffer (the immediate path); anything else names all three.
TEST(Options, FxDepthPicksOneOfThreeScenePaths) {
    const struct {
        const char* word;
        bool linear, immediate;
    } cases[] = {{"graph", false, false}, {"linear", true, false}, {"zbuffer", false, true}};
    const Options defaults;
    EXPECT_FALSE(defaults.pluginLinearDepth || defaults.pluginZBuffer);
    for (const auto& c : cases) {
        Options o;
        std::string err;
        ASSERT_TRUE(parse({"--fx-depth", c.word}, &o, &err)) << c.word << ": " << err;
        EXPECT_EQ(o.pluginLinearDepth, c.linear) << c.word;
        EXPECT_EQ(o.pluginZBuffer, c.immediate) << c.word;
    }
    Options bad;
    std::string err;
    EXPECT_FALSE(parse({"--fx-depth", "zbufer"}, &bad, &err));
    EXPECT_EQ(err, "--fx-depth: expected graph, linear or zbuffer, got 'zbufer'");
}

TEST(Options, ThreadsTakesZeroTo64AndDefaultsToOnePerHardwareThread) {
    Options o;
    std::string err;
    ASSERT_TRUE(parse({}, &o, &err)) << err;
    EXPECT_EQ(o.threads, 0);
    for (const char* n : {"0", "1", "2", "8", "64"}) {
        ASSERT_TRUE(parse({"--threads", n}, &o, &err)) << n << ": " << err;
        EXPECT_EQ(o.threads, std::stoi(n));
    }
    EXPECT_NE(cube::usage().find("--threads N"), std::string::npos);
}

TEST(Options, BadThreadCountsAreRejectedNamingTheFlagAndTheRange) {
    for (const char* bad : {"65", "-1", "junk", "", "2.5", "8x", "99999999999999999999"}) {
        SCOPED_TRACE(bad);
        Options o;
        std::string err;
        EXPECT_FALSE(parse({"--threads", bad}, &o, &err));
        EXPECT_NE(err.find("--threads: expected a whole number 0..64"), std::string::npos) << err;
        EXPECT_NE(err.find(std::string("got '") + bad + "'"), std::string::npos) << err;
    }
    Options o;
    std::string err;
    EXPECT_FALSE(parse({"--threads"}, &o, &err));
    EXPECT_EQ(err, "--threads: missing value");
}
