// fxbench: the thesis's Table 1 (hard / soft / soft + prepass-EQUAL / soft + quarter-res, min /
// max / average FPS) measured fairly: every simulated frame rendered in every mode, interleaved,
// with frame-time percentiles, per-pass times, the fill limit and image error against a
// reference mode. See --help; the pieces live in fxbench_*.cpp, one concept each.
#include <cstdio>
#include <filesystem>
#include <string>

#include "fxbench_chart.h"
#include "fxbench_integrators.h"
#include "fxbench_measure.h"
#include "fxbench_options.h"
#include "fxbench_report.h"
#include "fxbench_summary.h"
#include "fxbench_sweep.h"

#include "apps/CommandLine.h"

namespace {

int runSingle(const fxbench::BenchOptions& o) {
    const fxbench::Scenario* sc = fxbench::findScenario(o.scenario);
    fxbench::RunConfig cfg = fxbench::runConfig(*sc, o);
    cfg.imagesDir = o.imagesDir;
    cfg.progressLabel = o.scenario;
    std::string err;
    if (!o.imagesDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(o.imagesDir, ec);
        if (ec) {
            std::fprintf(stderr, "fxbench: --images %s: %s\n", o.imagesDir.c_str(), ec.message().c_str());
            return 1;
        }
    }
    fxbench::RunResult result;
    if (!fxbench::runBench(cfg, &result, &err)) {
        std::fprintf(stderr, "fxbench: %s\n", err.c_str());
        return 1;
    }
    const fxbench::Report report = fxbench::makeReport(cfg, result, o.seed);
    std::printf("%s", fxbench::markdownReport(report).c_str());
    int status = result.glErrors > 0 ? 3 : 0;
    auto write = [&](const std::string& path, const std::string& text) {
        if (path.empty()) return;
        if (!fxbench::writeText(path, text, &err)) {
            std::fprintf(stderr, "fxbench: %s\n", err.c_str());
            status = 1;
        }
    };
    write(o.json, fxbench::jsonReport(report) + "\n");
    write(o.csv, fxbench::csvRows(report, "", true));
    write(o.chart, fxbench::chartSvg(report));
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    fxbench::BenchOptions options;
    const int exitNow = cube::parseCommandLine("fxbench", argc, argv, &fxbench::parseBenchOptions,
                                               &fxbench::benchUsage, &options);
    if (exitNow >= 0) return exitNow;
    if (options.integrators) {
        std::printf("%s", fxbench::integratorReport().c_str());
        return 0;
    }
    if (options.sweep.kind != fxbench::Sweep::Kind::None) return fxbench::runSweep(options);
    return runSingle(options);
}
