// fxbench end to end: tiny runs of the real binary (64x64, a few frames, two rounds) and checks
// of its JSON, exit codes and messages. Figures here are correctness, not speed: timings are
// only checked to be present and finite.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "RunCommand.h"
#include "fxbench_sweep.h"

namespace {

// exit code (-1 when a signal ended it) and stdout + stderr
using RunOutput = cubetest::CommandResult;

RunOutput runFxbench(const std::string& args) {
    return cubetest::runCommand(std::string(CUBE_TEST_BIN_DIR) + "/fxbench " + args + " 2>&1", -1);
}

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("fxbench_test_" + std::to_string(getpid()) + "_" + name)).string();
}

using cubetest::readFile;

/// One tiny run per scenario, shared by the tests that look at it (the runs are the slow part).
const YAML::Node& tinyRun(const std::string& scenario) {
    static std::map<std::string, YAML::Node> cache;
    auto it = cache.find(scenario);
    if (it != cache.end()) return it->second;
    const std::string json = tempPath(scenario + ".json");
    const RunOutput r = runFxbench("--scenario " + scenario +
                                   " --size 64x64 --frames 3 --rounds 2 --warmup 1 --error-frames 1 --json " + json);
    EXPECT_EQ(r.status, 0) << r.output;
    YAML::Node node;
    try {
        node = YAML::Load(readFile(json));  // JSON is YAML
    } catch (const std::exception& e) {
        ADD_FAILURE() << json << ": " << e.what();
    }
    std::filesystem::remove(json);
    return cache.emplace(scenario, node).first->second;
}

double finite(const YAML::Node& n, const std::string& what) {
    EXPECT_TRUE(n.IsDefined() && n.IsScalar()) << what << " missing";
    if (!n.IsDefined() || !n.IsScalar()) return 0.0;
    const double v = n.as<double>();
    EXPECT_TRUE(std::isfinite(v)) << what << " = " << n.as<std::string>();
    return v;
}

const YAML::Node modeNode(const YAML::Node& run, const std::string& name) {
    for (const YAML::Node& m : run["modes"])
        if (m["name"].as<std::string>() == name) return m;
    ADD_FAILURE() << "mode " << name << " not in the JSON";
    return YAML::Node();
}

// fxbench with `args` and --json into a file of its own named `name`, which is read and removed: the
// run, or a null node (and a failure with fxbench's output) where it failed; its output in *out.
YAML::Node runToJson(const std::string& name, const std::string& args, RunOutput* out) {
    const std::string json = tempPath(name);
    *out = runFxbench(args + " --json " + json);
    if (out->status != 0 || !std::filesystem::exists(json)) {
        ADD_FAILURE() << "fxbench " << args << ": status " << out->status << "\n" << out->output;
        return YAML::Node();
    }
    const YAML::Node run = YAML::Load(readFile(json));
    std::filesystem::remove(json);
    return run;
}

// runToJson of `modes` in the standard scene at 320x180, `frames` timed frames, one round, one
// warm-up frame, two error frames.
YAML::Node smallStandardRun(const std::string& name, const std::string& modes, int frames, RunOutput* out) {
    return runToJson(name, "--scenario standard --modes " + modes + " --size 320x180 --frames " + std::to_string(frames) +
                               " --rounds 1 --warmup 1 --error-frames 2", out);
}

bool hasParticlePass(const YAML::Node& mode) {
    for (const auto& kv : mode["passes_ms"])
        if (kv.first.as<std::string>().find("particles") != std::string::npos) return true;
    return false;
}

class FxbenchScenario : public ::testing::TestWithParam<const char*> {};

TEST_P(FxbenchScenario, TinyRunWritesEveryKeyWithFiniteValues) {
    const YAML::Node& run = tinyRun(GetParam());
    ASSERT_TRUE(run.IsMap());
    EXPECT_EQ(run["scenario"].as<std::string>(), GetParam());
    ASSERT_TRUE(run["size"].IsSequence());
    EXPECT_EQ(run["size"][0].as<int>(), 64);
    EXPECT_EQ(run["size"][1].as<int>(), 64);
    EXPECT_EQ(run["frames"].as<int>(), 3);
    EXPECT_EQ(run["rounds"].as<int>(), 2);
    EXPECT_FALSE(run["renderer"].as<std::string>().empty());
    EXPECT_GE(run["threads"].as<int>(), 1);  // --threads 0: one per hardware thread
    ASSERT_TRUE(run["modes"].IsSequence());
    EXPECT_EQ(run["modes"].size(), 25u);  // every mode by default (lit, mega, *-zbuffer, *-linear, *+tiled, *-lit+tiled included)
    for (const YAML::Node& m : run["modes"]) {
        const std::string name = m["name"].as<std::string>();
        SCOPED_TRACE(name);
        for (const char* k : {"min", "avg", "max"}) EXPECT_GT(finite(m["fps"][k], std::string("fps.") + k), 0.0);
        EXPECT_LE(m["fps"]["min"].as<double>(), m["fps"]["max"].as<double>());
        for (const char* k : {"p50", "p95", "p99"}) EXPECT_GT(finite(m["frame_ms"][k], std::string("frame_ms.") + k), 0.0);
        EXPECT_LE(m["frame_ms"]["p50"].as<double>(), m["frame_ms"]["p99"].as<double>());
        EXPECT_GT(finite(m["ratio_vs_hard"], "ratio_vs_hard"), 0.0);
        ASSERT_TRUE(m["passes_ms"].IsMap());
        EXPECT_GT(m["passes_ms"].size(), 0u);
        for (const auto& kv : m["passes_ms"]) finite(kv.second, "passes_ms." + kv.first.as<std::string>());
        EXPECT_GE(finite(m["particles"], "particles"), 0.0);
        // Frame ms less its passes' ms: the passes run inside the frame's clock.
        EXPECT_GE(finite(m["outside_passes_ms"], "outside_passes_ms"), 0.0);
        EXPECT_GE(finite(m["particle_fragments"], "particle_fragments"), 0.0);
        EXPECT_GE(finite(m["fill_limit_ratio"], "fill_limit_ratio"), 0.0);
        const YAML::Node e = m["error"];
        ASSERT_TRUE(e.IsMap());
        EXPECT_FALSE(e["reference"].as<std::string>().empty());
        for (const char* k : {"rmse", "psnr_db", "max_abs", "edge_pct"})
            EXPECT_GE(finite(e[k], std::string("error.") + k), 0.0);
    }
    EXPECT_DOUBLE_EQ(modeNode(run, "hard")["ratio_vs_hard"].as<double>(), 1.0);
    // The bare engine never declares a particle pass.
    EXPECT_FALSE(hasParticlePass(modeNode(run, "nofx")));
}

INSTANTIATE_TEST_SUITE_P(All, FxbenchScenario, ::testing::Values("standard", "fill", "overdraw", "empty"));

// Soft discards a fragment whose atlas texel is empty before its scene-depth fetch, so trimmed
// polygons and full quads write the same samples: the texels with smoke. What the polygon saves
// is rasterised fragments, counted here with a copy of the shaders whose soft program has no such
// discard (read through CUBE_SHADER_DIR; every rasterised fragment then writes its sample).
TEST(Fxbench, TrimmedSoftRasterisesFewerFragmentsThanQuadsForTheSameImage) {
    namespace fs = std::filesystem;
    const YAML::Node& run = tinyRun("standard");
    const YAML::Node soft = modeNode(run, "soft"), quads = modeNode(run, "soft-quads");
    EXPECT_EQ(quads["error"]["reference"].as<std::string>(), "soft");
    // 8-bit levels. At 64x64 the particles are a few pixels across and read coarse mip levels,
    // whose steeper bilinear slopes turn the two triangulations' rounding into up to 2 (1 from
    // 160x120 up).
    EXPECT_LE(quads["error"]["max_abs"].as<double>(), 2.0);
    const double written = soft["particle_fragments"].as<double>();
    ASSERT_GT(written, 0.0);
    // A trimmed polygon holds every texel with smoke: the same samples within 1 % (at 64x64 a
    // fragment on the rim can sample exactly 0 through one triangulation and a trace through the
    // other: 0.7 % seen; at 1920x1080 the counts are equal).
    EXPECT_NEAR(written, quads["particle_fragments"].as<double>(), 0.01 * written);

    const fs::path shaders = tempPath("shaders");
    fs::remove_all(shaders);
    fs::copy(fs::path(CUBE_SOURCE_DIR) / "shaders", shaders);
    const fs::path softShader = shaders / "fs_particles_soft.glsl";
    std::string text = readFile(softShader.string());
    const std::string earlyOut = "    if (texel.a == 0.0) discard;\n";
    const size_t at = text.find(earlyOut);
    ASSERT_NE(at, std::string::npos) << softShader << ": the early out this test removes is not there";
    text.erase(at, earlyOut.size());
    std::ofstream(softShader, std::ios::binary) << text;
    const std::string json = tempPath("rasterised.json");
    const RunOutput r = cubetest::runCommand("CUBE_SHADER_DIR=" + shaders.string() + " " + CUBE_TEST_BIN_DIR +
                                                 "/fxbench --scenario standard --modes soft,soft-quads --size 64x64"
                                                 " --frames 3 --rounds 2 --warmup 1 --error-frames 1 --json " +
                                                 json + " 2>&1",
                                             -1);
    fs::remove_all(shaders);
    ASSERT_EQ(r.status, 0) << r.output;
    const YAML::Node rasterised = YAML::Load(readFile(json));
    fs::remove(json);
    const double trimmed = modeNode(rasterised, "soft")["particle_fragments"].as<double>();
    const double full = modeNode(rasterised, "soft-quads")["particle_fragments"].as<double>();
    // The polygons hold 60-97 % of the quad depending on the LOD bucket (TrimmedShapes test).
    EXPECT_LT(trimmed, 0.98 * full);
    // Every sample the shipped program writes is among those rasterised.
    EXPECT_GE(trimmed, written);
    EXPECT_GT(trimmed, 1.05 * written);  // and the early out discards some: the empty rim
}

// The tiled modes draw their reference's picture up to the blend's rounding (measured at 320x180:
// max 3-6/255 at 50-60 dB) in a pass of their own, and blend each covered pixel once: far fewer
// samples than the rasterised pass writes (overdraw 5 and more in the standard scene).
TEST(Fxbench, TiledModesDrawTheirReferencesPictureWithOneBlendAPixel) {
    RunOutput r;
    const YAML::Node run = smallStandardRun("tiled.json", "hard,soft,spherical,hard+tiled,soft+tiled,spherical+tiled", 3, &r);
    ASSERT_TRUE(run.IsMap());
    for (const char* name : {"hard+tiled", "soft+tiled", "spherical+tiled"}) {
        SCOPED_TRACE(name);
        const YAML::Node m = modeNode(run, name);
        const std::string reference = name[0] == 'h' ? "hard" : name[1] == 'o' ? "soft" : "spherical";
        EXPECT_EQ(m["error"]["reference"].as<std::string>(), reference);
        EXPECT_LE(m["error"]["max_abs"].as<double>(), 8.0);
        EXPECT_GE(m["error"]["psnr_db"].as<double>(), 45.0);
        ASSERT_TRUE(m["passes_fragments"]["chase.particles_tiled"]);
        EXPECT_FALSE(m["passes_fragments"]["chase.particles"]) << "the rasterised pass ran too";
        const double tiled = m["passes_fragments"]["chase.particles_tiled"].as<double>();
        const double raster = modeNode(run, reference.c_str())["passes_fragments"]["chase.particles"].as<double>();
        EXPECT_GT(tiled, 0.0);
        EXPECT_LT(tiled * 4.0, raster) << "one blend a covered pixel, against one a fragment";
    }
    EXPECT_EQ(r.output.find("built while declaring a frame"), std::string::npos) << r.output;
}

// Lit smoke tiled: the tiled pass draws it (no rasterised particle pass), reading the frame's
// opacity map, lit across the trimmed polygons' fans as the raster path lights them (measured at
// 320x180: soft 57.8 dB / max 7, spheres 57.7 dB / 6; with the light at the quads' corners, before
// session 28, soft was 39.9 dB / 26).
TEST(Fxbench, LitTiledModesDrawTheLitPictureInTheTiledPass) {
    RunOutput out;
    const YAML::Node run =
        smallStandardRun("lit_tiled.json", "soft-lit,soft-lit+tiled,spherical-lit,spherical-lit+tiled", 2, &out);
    ASSERT_TRUE(run.IsMap());
    for (const char* name : {"soft-lit+tiled", "spherical-lit+tiled"}) {
        const YAML::Node m = modeNode(run, name);
        SCOPED_TRACE(name);
        const bool soft = name[1] == 'o';
        EXPECT_EQ(m["error"]["reference"].as<std::string>(), soft ? "soft-lit" : "spherical-lit");
        EXPECT_GE(m["error"]["psnr_db"].as<double>(), 50.0);
        EXPECT_LE(m["error"]["max_abs"].as<double>(), soft ? 12.0 : 10.0);
        EXPECT_TRUE(m["passes_fragments"]["chase.particles_tiled"]);
        EXPECT_TRUE(m["passes_fragments"]["chase.smoke_opacity"]) << "lit smoke reads this frame's opacity map";
        EXPECT_FALSE(m["passes_fragments"]["chase.particles"]) << "the rasterised pass ran too";
    }
    EXPECT_EQ(out.output.find("built while declaring a frame"), std::string::npos) << out.output;
}

// CUBEFX_TILED_CPU_LISTS (TiledPath::cpuListLimit): 0 has the GPU sort the lists of a view the CPU
// lists by default on llvmpipe (a software rasterizer's default; a GPU's is the GPU's sort); the
// picture is the same byte for byte, and the sort's dispatches show in the pass's shader
// invocations. A value that is not a number is reported and ignored. The same for
// CUBEFX_TILED_GPU_ORDER (TileSort::orderLimit): 0, with the GPU's lists, has the GPU sort the
// particles back to front too; such a view is binned in its pass unless CUBEFX_TILED_DEFER_BINS=0
// (TiledPath::deferBins): the same picture either way, and a value other than 0 or 1 is reported
// and ignored. Binned in its pass, the GPU bins it (TiledPath::gpuBins: its bound and list
// dispatches show in the invocations) unless CUBEFX_TILED_GPU_BINS=0, whose dispatches are then
// those of the view binned while declared; the same picture, and a bad value reported and ignored.
// So too CUBEFX_TILED_GATHER_IN_PASS=0 (TiledPath::gatherInPass: such a view's particles written
// while declared, not in its first pass): the same picture and dispatches.
TEST(Fxbench, TiledListsFromTheCpuOrTheGpuSortGiveTheSamePicture) {
    std::map<std::string, std::string> png;
    std::map<std::string, double> shaded;
    const std::string gpuOrder = "CUBEFX_TILED_CPU_LISTS=0 CUBEFX_TILED_GPU_ORDER=0 ", badOrder = "CUBEFX_TILED_GPU_ORDER=1e5 ";
    const std::string binnedEarly = gpuOrder + "CUBEFX_TILED_DEFER_BINS=0 ", badDefer = gpuOrder + "CUBEFX_TILED_DEFER_BINS=yes ";
    const std::string cpuBinned = gpuOrder + "CUBEFX_TILED_GPU_BINS=0 ", badGpuBins = gpuOrder + "CUBEFX_TILED_GPU_BINS=2 ";
    const std::string listCopied = gpuOrder + "CUBEFX_TILED_GATHER_IN_PASS=0 ",
                      badGather = gpuOrder + "CUBEFX_TILED_GATHER_IN_PASS=on ";
    for (const std::string& env : {std::string(), std::string("CUBEFX_TILED_CPU_LISTS=0 "),
                                  std::string("CUBEFX_TILED_CPU_LISTS=12x "), gpuOrder, badOrder, binnedEarly, badDefer,
                                  cpuBinned, badGpuBins, listCopied, badGather}) {
        SCOPED_TRACE(env);
        const std::string json = tempPath("lists.json"), images = tempPath("lists_images");
        const RunOutput r = cubetest::runCommand(env + std::string(CUBE_TEST_BIN_DIR) +
                                                     "/fxbench --scenario standard --modes soft,soft+tiled --size 160x96 "
                                                     "--frames 2 --rounds 1 --warmup 1 --error-frames 1 --json " +
                                                     json + " --images " + images + " 2>&1",
                                                 -1);
        ASSERT_EQ(r.status, 0) << r.output;
        const bool bad = env.find("12x") != std::string::npos;
        EXPECT_EQ(r.output.find("CUBEFX_TILED_CPU_LISTS is not a whole number") != std::string::npos, bad) << r.output;
        EXPECT_EQ(r.output.find("CUBEFX_TILED_GPU_ORDER is not a whole number") != std::string::npos, env == badOrder)
            << r.output;
        EXPECT_EQ(r.output.find("CUBEFX_TILED_DEFER_BINS is neither 0 nor 1") != std::string::npos, env == badDefer)
            << r.output;
        EXPECT_EQ(r.output.find("CUBEFX_TILED_GPU_BINS is neither 0 nor 1") != std::string::npos, env == badGpuBins)
            << r.output;
        EXPECT_EQ(r.output.find("CUBEFX_TILED_GATHER_IN_PASS is neither 0 nor 1") != std::string::npos, env == badGather)
            << r.output;
        const YAML::Node run = YAML::Load(readFile(json));
        const YAML::Node m = modeNode(run, "soft+tiled");
        ASSERT_TRUE(m["passes_shaded"]["chase.particles_tiled"]) << "the context counts compute invocations";
        // A view binned in its pass has two (TiledPath::kSetupPass first): their invocations together.
        const bool deferred = env == gpuOrder || env == badDefer || env == cpuBinned || env == badGpuBins ||
                              env == listCopied || env == badGather;
        EXPECT_EQ(bool(m["passes_shaded"]["chase.particles_tiled_setup"]), deferred);
        shaded[env] = 0.0;
        for (const char* pass : {"chase.particles_tiled", "chase.particles_tiled_setup"}) {
            if (m["passes_shaded"][pass]) shaded[env] += m["passes_shaded"][pass].as<double>();
        }
        if (deferred) {
            // The setup pass ran the particles' order and records: more than its scans of 1,024.
            EXPECT_GT(m["passes_shaded"]["chase.particles_tiled_setup"].as<double>(), 8 * 1024.0);
        }
        png[env] = readFile(images + "/standard_soft-tiled.png");
        EXPECT_GT(png[env].size(), 1000u);
        std::filesystem::remove(json);
        std::filesystem::remove_all(images);
    }
    const std::string byDefault = "", sorted = "CUBEFX_TILED_CPU_LISTS=0 ", bad = "CUBEFX_TILED_CPU_LISTS=12x ";
    EXPECT_EQ(png[byDefault], png[sorted]) << "the same lists, the same picture";
    EXPECT_EQ(png[byDefault], png[bad]);
    EXPECT_GT(shaded[sorted], shaded[byDefault] + 1024.0) << "the sort's passes (a scan of 1,024 each) did not run";
    EXPECT_EQ(shaded[bad], shaded[byDefault]) << "an unreadable value keeps the default";
    // The particles sorted back to front on the GPU (TileSort::DepthOrder): the same picture, and
    // the order's passes ran (eight radix passes over the particles, each with a scan of 1,024).
    EXPECT_EQ(png[byDefault], png[gpuOrder]) << "the same order, the same picture";
    EXPECT_GT(shaded[gpuOrder], shaded[sorted] + 8 * 1024.0) << "the order's passes did not run";
    EXPECT_EQ(png[byDefault], png[badOrder]);
    EXPECT_EQ(shaded[badOrder], shaded[byDefault]);
    for (const std::string& env : {binnedEarly, badDefer, cpuBinned, badGpuBins, listCopied, badGather}) {
        EXPECT_EQ(png[gpuOrder], png[env]) << env;
    }
    EXPECT_EQ(shaded[gpuOrder], shaded[badDefer]);
    EXPECT_EQ(shaded[gpuOrder], shaded[badGpuBins]);
    EXPECT_EQ(shaded[gpuOrder], shaded[listCopied]) << "where the particles are written changes no dispatch";
    EXPECT_EQ(shaded[gpuOrder], shaded[badGather]);
    // Binned on the host's threads, in the pass or while declared: the same dispatches; the GPU's
    // bins add a bound per particle and one list group of 1,024.
    EXPECT_EQ(shaded[cpuBinned], shaded[binnedEarly]);
    EXPECT_GT(shaded[gpuOrder], shaded[cpuBinned] + 1024.0) << "the GPU's bins did not run";
}

// Per particle pass, the samples it wrote: their sum is particle_fragments; quarter res's
// downsample writes its half-res texels and its composite blends fewer pixels than the
// downsample's tiles hold at full res (a pixel without smoke is discarded).
TEST(Fxbench, PerPassFragmentsAddUpAndShowTheCompositesDiscards) {
    const YAML::Node& run = tinyRun("standard");
    for (const char* name : {"soft", "soft+quarter-always", "spherical+quarter"}) {
        SCOPED_TRACE(name);
        const YAML::Node m = modeNode(run, name);
        ASSERT_TRUE(m["passes_fragments"].IsMap());
        double sum = 0.0;
        for (const auto& kv : m["passes_fragments"]) {
            EXPECT_NE(kv.first.as<std::string>().find("particles"), std::string::npos);
            sum += finite(kv.second, "passes_fragments." + kv.first.as<std::string>());
        }
        // Medians of each pass against the median of their sums: equal with one error frame.
        EXPECT_DOUBLE_EQ(sum, m["particle_fragments"].as<double>());
    }
    const YAML::Node q = modeNode(run, "soft+quarter-always")["passes_fragments"];
    const double downsample = q["chase.particles_depth_downsample"].as<double>();
    const double composite = q["chase.particles_composite"].as<double>();
    ASSERT_GT(downsample, 0.0);
    EXPECT_GT(composite, 0.0);
    EXPECT_LT(composite, 4.0 * downsample);
    EXPECT_EQ(modeNode(run, "soft")["passes_fragments"].size(), 1u);  // chase.particles alone
}

// Where the context counts fragment shader invocations (llvmpipe does), every particle pass has
// them, never fewer than the samples it wrote, and the composite's show its early outs: it shades
// every pixel of its tiles and writes only those with smoke.
TEST(Fxbench, PerPassShadedFragmentsHoldEveryWrittenSampleAndTheCompositesDiscards) {
    const YAML::Node& run = tinyRun("standard");
    const bool llvmpipe = run["renderer"].as<std::string>().find("llvmpipe") != std::string::npos;
    for (const char* name : {"hard", "soft", "spherical", "soft+quarter-always", "spherical+quarter"}) {
        SCOPED_TRACE(name);
        const YAML::Node m = modeNode(run, name);
        const YAML::Node shaded = m["passes_shaded"];
        ASSERT_TRUE(shaded.IsMap());
        if (shaded.size() == 0) {
            EXPECT_FALSE(llvmpipe) << "llvmpipe lists ARB_pipeline_statistics_query";
            continue;
        }
        EXPECT_EQ(shaded.size(), m["passes_fragments"].size());
        for (const auto& kv : m["passes_fragments"]) {
            const std::string pass = kv.first.as<std::string>();
            ASSERT_TRUE(shaded[pass]) << pass;
            EXPECT_GE(finite(shaded[pass], "passes_shaded." + pass), kv.second.as<double>()) << pass;
        }
    }
    const YAML::Node q = modeNode(run, "soft+quarter-always");
    if (q["passes_shaded"].size() == 0) return;
    EXPECT_GT(q["passes_shaded"]["chase.particles_composite"].as<double>(),
              1.5 * q["passes_fragments"]["chase.particles_composite"].as<double>());
}

TEST(Fxbench, ParticleModesDrawParticlesInTheStandardScenario) {
    // The positive control for the "no particle pass" checks.
    const YAML::Node& run = tinyRun("standard");
    for (const char* name : {"hard", "soft", "soft+quarter", "spherical"}) {
        SCOPED_TRACE(name);
        const YAML::Node m = modeNode(run, name);
        EXPECT_TRUE(hasParticlePass(m));
        EXPECT_GT(m["particles"].as<double>(), 0.0);
        EXPECT_GT(m["fill_limit_ratio"].as<double>(), 0.0);
        EXPECT_GT(m["particle_fragments"].as<double>(), 0.0);
    }
    EXPECT_EQ(modeNode(run, "nofx")["particles"].as<double>(), 0.0);
    EXPECT_EQ(modeNode(run, "nofx")["particle_fragments"].as<double>(), 0.0);
    // Fragments are counted, not timed: prepass-EQUAL changes the opaque pass only, so the
    // particle passes write exactly the same samples with and without it.
    EXPECT_EQ(modeNode(run, "soft")["particle_fragments"].as<double>(),
              modeNode(run, "soft+equal")["particle_fragments"].as<double>());
}

TEST(Fxbench, EmptyScenarioHasNoParticlePassInAnyMode) {
    const YAML::Node& run = tinyRun("empty");
    for (const YAML::Node& m : run["modes"]) {
        SCOPED_TRACE(m["name"].as<std::string>());
        EXPECT_FALSE(hasParticlePass(m));
        EXPECT_EQ(m["particles"].as<double>(), 0.0);
        EXPECT_EQ(m["fill_limit_ratio"].as<double>(), 0.0);
        // Nothing to draw: every mode's image equals its reference.
        EXPECT_EQ(m["error"]["rmse"].as<double>(), 0.0);
    }
}

TEST(Fxbench, ErrorOfAModeAgainstItselfIsZero) {
    const YAML::Node& run = tinyRun("standard");
    const double cap = run["psnr_cap_db"].as<double>();
    for (const char* name : {"nofx", "hard", "soft", "spherical"}) {
        SCOPED_TRACE(name);
        const YAML::Node e = modeNode(run, name)["error"];
        EXPECT_EQ(e["reference"].as<std::string>(), name);
        EXPECT_EQ(e["rmse"].as<double>(), 0.0);
        EXPECT_EQ(e["max_abs"].as<double>(), 0.0);
        EXPECT_EQ(e["edge_pct"].as<double>(), 0.0);
        EXPECT_EQ(e["psnr_db"].as<double>(), cap);
    }
}

TEST(Fxbench, QuarterResolutionHasFiniteErrorBelowFullResolution) {
    const YAML::Node& run = tinyRun("standard");
    const double cap = run["psnr_cap_db"].as<double>();
    const double full = modeNode(run, "soft")["error"]["psnr_db"].as<double>();
    EXPECT_EQ(full, cap);
    for (const char* name : {"soft+quarter", "spherical+quarter"}) {
        SCOPED_TRACE(name);
        const YAML::Node e = modeNode(run, name)["error"];
        const double psnr = e["psnr_db"].as<double>();
        EXPECT_TRUE(std::isfinite(psnr));
        EXPECT_GT(psnr, 10.0);  // the same picture, not noise
        EXPECT_LT(psnr, full);
        EXPECT_GT(e["rmse"].as<double>(), 0.0);
    }
    EXPECT_EQ(modeNode(run, "soft+quarter")["error"]["reference"].as<std::string>(), "soft");
    EXPECT_EQ(modeNode(run, "spherical+quarter")["error"]["reference"].as<std::string>(), "spherical");
}

TEST(Fxbench, ModeSubsetKeepsOnlyTheAskedModesAndCsvAndChartAreWritten) {
    const std::string json = tempPath("subset.json"), csv = tempPath("subset.csv"), svg = tempPath("subset.svg");
    const RunOutput r = runFxbench("--modes soft+quarter,soft --size 48x48 --frames 2 --rounds 2 --warmup 0 "
                                   "--error-frames 1 --json " + json + " --csv " + csv + " --chart " + svg);
    ASSERT_EQ(r.status, 0) << r.output;
    const YAML::Node run = YAML::Load(readFile(json));
    ASSERT_EQ(run["modes"].size(), 2u);
    EXPECT_EQ(run["modes"][0]["name"].as<std::string>(), "soft");  // table order, not argument order
    EXPECT_EQ(run["modes"][1]["name"].as<std::string>(), "soft+quarter");
    // hard was measured internally as the ratio base.
    EXPECT_GT(run["modes"][0]["ratio_vs_hard"].as<double>(), 0.0);
    const std::string csvText = readFile(csv);
    EXPECT_EQ(std::count(csvText.begin(), csvText.end(), '\n'), 3);  // header + 2 modes
    const std::string svgText = readFile(svg);
    EXPECT_EQ(svgText.rfind("<svg", 0), 0u);
    EXPECT_NE(svgText.find("soft+quarter"), std::string::npos);
    EXPECT_NE(svgText.find("</svg>"), std::string::npos);
    EXPECT_NE(r.output.find("| Method | Setup | Min FPS | Max FPS | Average FPS |"), std::string::npos);
    for (const std::string& p : {json, csv, svg}) std::filesystem::remove(p);
}

// A sweep point reaches the count it asks for (within kSweepReachTolerance, 5 %, and never above:
// capacity = count), every point from the same drive time, and the counted work grows with the
// count: particles drawn and the fragments the particle passes wrote (counted, not timed).
TEST(Fxbench, ParticleSweepReachesTheAskedCountsAndWorkGrowsWithThem) {
    const std::string json = tempPath("sweep.json");
    const RunOutput r = runFxbench("--sweep particles=1000,4000,16000 --modes soft --size 48x48 --frames 2 "
                                   "--rounds 1 --warmup 0 --error-frames 1 --json " + json);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("Cost curve: live particles"), std::string::npos);
    EXPECT_NE(r.output.find("| particles requested | reached | reached % |"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("every point did"), std::string::npos) << r.output;
    const YAML::Node sweep = YAML::Load(readFile(json));
    EXPECT_EQ(sweep["sweep"].as<std::string>(), "particles");
    ASSERT_EQ(sweep["points"].size(), 3u);
    double lastDrawn = 0.0, lastFragments = 0.0;
    for (size_t i = 0; i < 3; ++i) {
        const YAML::Node p = sweep["points"][i];
        SCOPED_TRACE(p["point"].as<std::string>());
        const double asked = p["requested"].as<double>();
        EXPECT_EQ(asked, p["point"].as<double>());
        const double reached = p["reached"].as<double>();
        EXPECT_GE(reached, 0.95 * asked);
        EXPECT_LE(reached, asked);
        EXPECT_EQ(p["run"]["particles_requested"].as<double>(), asked);
        const YAML::Node soft = p["run"]["modes"][0];
        EXPECT_GE(finite(soft["outside_passes_ms"], "outside_passes_ms"), 0.0);
        const double drawn = soft["particles"].as<double>(), fragments = soft["particle_fragments"].as<double>();
        EXPECT_GT(drawn, lastDrawn);
        EXPECT_GT(fragments, lastFragments);
        lastDrawn = drawn;
        lastFragments = fragments;
    }
    std::filesystem::remove(json);
}

// Past one reaction's reach (100000 particles, rate = capacity): the file holds several
// reactions whose capacities add up to the count.
TEST(Fxbench, ParticleSweepYamlSplitsLargeCountsOverReactions) {
    EXPECT_EQ(fxbench::sweepReactionCount(1000), 1);
    EXPECT_EQ(fxbench::sweepReactionCount(100000), 1);
    EXPECT_EQ(fxbench::sweepReactionCount(100001), 2);
    EXPECT_EQ(fxbench::sweepReactionCount(1000000), 10);
    for (int n : {1000, 250001, 1000000}) {
        SCOPED_TRACE(n);
        const YAML::Node doc = YAML::Load(fxbench::particleSweepYaml(n));
        const YAML::Node reactions = doc["reactions"];
        ASSERT_EQ(int(reactions.size()), fxbench::sweepReactionCount(n));
        long long capacity = 0;
        for (const YAML::Node& reaction : reactions) {
            const int c = reaction["emission"]["capacity"].as<int>();
            EXPECT_LE(c, fxbench::kSweepParticlesPerReaction);
            EXPECT_EQ(reaction["emission"]["rate"].as<int>(), std::max(c, 10));
            capacity += c;
        }
        EXPECT_EQ(capacity, n);
    }
}

// Switching modes goes through prepareGl (as the engine's key and panel switches do): no program
// is built while a frame is declared. Each mode's per-pass times list only the passes its own
// renders ran.
TEST(Fxbench, ModeSwitchesBuildNoProgramWhileDeclaringAndPassTimesStayWithTheirMode) {
    const std::string json = tempPath("passes.json");
    const RunOutput r = runFxbench("--modes hard,soft+quarter,soft+quarter-always,soft --size 48x48 --frames 2 "
                                   "--rounds 2 --warmup 1 --error-frames 0 --json " + json);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("built while declaring a frame"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("mix modes"), std::string::npos) << r.output;
    const YAML::Node run = YAML::Load(readFile(json));
    std::filesystem::remove(json);
    auto passes = [&](const char* mode) {
        std::vector<std::string> names;
        for (const auto& kv : modeNode(run, mode)["passes_ms"]) names.push_back(kv.first.as<std::string>());
        return names;
    };
    auto has = [](const std::vector<std::string>& names, const std::string& pass) {
        return std::find(names.begin(), names.end(), pass) != names.end();
    };
    const std::vector<std::string> hard = passes("hard"), quarter = passes("soft+quarter"),
                                   always = passes("soft+quarter-always"), soft = passes("soft");
    for (const char* pass : {"chase.particles_quarter", "chase.particles_composite", "chase.particles_depth_downsample"}) {
        SCOPED_TRACE(pass);
        EXPECT_TRUE(has(quarter, pass));
        EXPECT_TRUE(has(always, pass));
        EXPECT_FALSE(has(hard, pass));
        EXPECT_FALSE(has(soft, pass));
    }
    EXPECT_TRUE(has(hard, "chase.particles"));
    EXPECT_TRUE(has(soft, "chase.particles"));
    // soft+quarter chooses per view when its passes run, so it declares the full-res pass too;
    // forced quarter res has no choice to make.
    EXPECT_TRUE(has(quarter, "chase.particles"));
    EXPECT_FALSE(has(always, "chase.particles"));
}

// soft+quarter leaves the choice to the view's passes by default (QuarterResPath::choiceInPass):
// CUBEFX_QUARTER_CHOICE_IN_PASS=0 chooses while declaring, as before, for A/B runs on a GPU. The
// same picture byte for byte; the passes the frame ran show which way it chose; a value other than
// 0 or 1 is reported and ignored.
TEST(Fxbench, QuarterResChoiceInThePassOrWhileDeclaredGivesTheSamePicture) {
    std::map<std::string, std::string> png;
    const std::string declared = "CUBEFX_QUARTER_CHOICE_IN_PASS=0 ", bad = "CUBEFX_QUARTER_CHOICE_IN_PASS=maybe ";
    for (const std::string& env : {std::string(), declared, bad}) {
        SCOPED_TRACE(env);
        const std::string json = tempPath("choice.json"), images = tempPath("choice_images");
        const RunOutput r = cubetest::runCommand(env + std::string(CUBE_TEST_BIN_DIR) +
                                                     "/fxbench --scenario standard --modes soft+quarter --size 160x96 "
                                                     "--frames 2 --rounds 1 --warmup 1 --error-frames 1 --json " +
                                                     json + " --images " + images + " 2>&1",
                                                 -1);
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_EQ(r.output.find("CUBEFX_QUARTER_CHOICE_IN_PASS is neither 0 nor 1") != std::string::npos, env == bad)
            << r.output;
        const YAML::Node passes = modeNode(YAML::Load(readFile(json)), "soft+quarter")["passes_ms"];
        const bool full = bool(passes["chase.particles"]), quarter = bool(passes["chase.particles_quarter"]);
        if (env == declared) {
            EXPECT_NE(full, quarter) << "chosen while declared: one path's passes only";
        } else {
            EXPECT_TRUE(full && quarter) << "chosen in the passes: both paths' passes declared";
        }
        png[env] = readFile(images + "/standard_soft-quarter.png");
        EXPECT_GT(png[env].size(), 1000u);
        std::filesystem::remove(json);
        std::filesystem::remove_all(images);
    }
    EXPECT_EQ(png[declared], png[std::string()]) << "the same picture either way";
    EXPECT_EQ(png[bad], png[std::string()]);
}

// --threads N reaches the game: the report header and the JSON give the job system's real count.
TEST(Fxbench, ThreadsFlagSizesTheJobSystemAndTheReportSaysSo) {
    const std::string json = tempPath("threads.json");
    const RunOutput r = runFxbench("--scenario empty --modes hard --size 64x64 --frames 1 --rounds 1 --warmup 0 "
                                   "--error-frames 0 --threads 3 --json " + json);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("job threads: 3;"), std::string::npos) << r.output;
    const YAML::Node run = YAML::Load(readFile(json));
    std::filesystem::remove(json);
    EXPECT_EQ(run["threads"].as<int>(), 3);
}

// The modes of the removed features are refused by name, with the reason, before anything runs.
TEST(Fxbench, RemovedModesAreRefusedWithTheReason) {
    struct Removed {
        const char* name;
        const char* reason;
    };
    for (const Removed& m : {Removed{"soft+mixed", "mixed resolution was removed in API 2.1"},
                             Removed{"soft+classify", "fade classification was removed in API 2.4"},
                             Removed{"spherical+classify", "fade classification was removed in API 2.4"}}) {
        SCOPED_TRACE(m.name);
        const RunOutput r = runFxbench(std::string("--modes soft,") + m.name);
        EXPECT_EQ(r.status, 2);
        EXPECT_NE(r.output.find(std::string("mode '") + m.name + "' no longer exists"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(m.reason), std::string::npos) << r.output;
    }
}

TEST(Fxbench, UnknownModeIsRejectedWithTheValidNames) {
    const RunOutput r = runFxbench("--modes soft,sofft");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("unknown mode 'sofft'"), std::string::npos) << r.output;
    for (const char* name : {"nofx", "hard", "soft+equal", "soft+equal+quarter", "spherical+quarter"})
        EXPECT_NE(r.output.find(name), std::string::npos) << name;
}

TEST(Fxbench, BadValuesAreRejectedWithTheFlagName) {
    struct Case {
        const char* args;
        const char* mentions;
    };
    for (const Case& c : {Case{"--size 1280", "--size"}, Case{"--size 8x8", "--size"}, Case{"--frames 0", "--frames"},
                          Case{"--rounds x", "--rounds"}, Case{"--scenario fast", "valid scenarios"},
                          Case{"--backend vulkan", "--backend"}, Case{"--depth inverted", "--depth"},
                          Case{"--sweep particles=0", "--sweep"},
                          Case{"--sweep depth=3", "--sweep"}, Case{"--json", "missing value"},
                          Case{"--bogus", "unknown option"}}) {
        SCOPED_TRACE(c.args);
        const RunOutput r = runFxbench(c.args);
        EXPECT_EQ(r.status, 2);
        EXPECT_NE(r.output.find(c.mentions), std::string::npos) << r.output;
    }
    EXPECT_EQ(runFxbench("--help").status, 0);
}

TEST(Fxbench, IntegratorReportShowsEulerDivergingAndExactStable) {
    const RunOutput r = runFxbench("--integrators");
    ASSERT_EQ(r.status, 0) << r.output;
    // Stiff row k*dt = 10000: both Euler variants diverge, the exact step does not.
    const size_t row = r.output.find("| 10000 |");
    ASSERT_NE(row, std::string::npos) << r.output;
    const std::string line = r.output.substr(row, r.output.find('\n', row) - row);
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, '|');) {
        const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
        if (a != std::string::npos) cells.push_back(cell.substr(a, b - a + 1));
    }
    ASSERT_EQ(cells.size(), 5u) << line;  // k*dt, k, explicit, semi-implicit, exact
    EXPECT_EQ(cells[2], "diverged");
    EXPECT_EQ(cells[3], "diverged");
    EXPECT_LT(std::stod(cells[4]), 1e-3) << line;
}

}  // namespace
