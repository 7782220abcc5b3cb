#include "fxbench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "fxbench_image_error.h"

namespace fxbench {

std::string num(double v, int precision) {
    if (!std::isfinite(v)) v = 0.0;
    char b[64];
    std::snprintf(b, sizeof b, "%.*g", precision, v);
    return b;
}

std::string jsonQuote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char b[8];
            std::snprintf(b, sizeof b, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
            out += b;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

namespace {

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, std::isfinite(v) ? v : 0.0);
    return b;
}

std::string psnrText(double db) { return db >= kPsnrCapDb ? "cap (identical)" : fmt("%.1f", db); }

using PassFigures = std::vector<std::pair<std::string, double>>;

// {"pass": figure, ...} in the passes' order.
std::string jsonObject(const PassFigures& figures) {
    std::string o = "{";
    for (size_t k = 0; k < figures.size(); ++k) o += (k ? ", " : "") + jsonQuote(figures[k].first) + ": " + num(figures[k].second);
    return o + "}";
}

// A table of one figure per pass (rows) and mode (columns), each printed with `format`; nothing
// when no mode has one.
void perPassTable(const Report& r, PassFigures ModeSummary::*figures, const std::string& title, const char* format,
                  std::string* out) {
    std::vector<std::string> passes;
    for (const ModeSummary& m : r.modes)
        for (const auto& p : m.*figures)
            if (std::find(passes.begin(), passes.end(), p.first) == passes.end()) passes.push_back(p.first);
    if (passes.empty()) return;
    std::string& o = *out;
    o += "\n" + title + "\n\n| pass |";
    for (const ModeSummary& m : r.modes) o += " " + m.name + " |";
    o += "\n|---|";
    for (size_t i = 0; i < r.modes.size(); ++i) o += "---:|";
    o += "\n";
    for (const std::string& p : passes) {
        o += "| " + p + " |";
        for (const ModeSummary& m : r.modes) {
            std::string cell = " - |";
            for (const auto& q : m.*figures)
                if (q.first == p) cell = " " + fmt(format, q.second) + " |";
            o += cell;
        }
        o += "\n";
    }
}

}  // namespace

std::string markdownReport(const Report& r) {
    std::string o;
    char line[512];
    std::snprintf(line, sizeof line, "## fxbench: %s, %dx%d\n\n", r.scenario.c_str(), r.width, r.height);
    o += line;
    o += "- scenario: " + r.description + "\n";
    o += "- renderer: " + r.renderer + " (" + r.backend + "); job threads: " + std::to_string(r.threads) +
         "; timing: " + r.timingMethod +
         " (frame = Game::RenderFrame wall ms, CPU clock around glFinish)\n";
    o += r.timingMethod == std::string("cpu-glfinish")
             ? "- pass times: CPU clock between glFinish calls around each pass\n"
             : "- pass times: " + r.timingMethod + " results of each render, waited for after its glFinish "
               "(Game::RenderFrame), so every mode's pass times are its own renders'\n";
    std::snprintf(line, sizeof line,
                  "- %d timed simulated frames x %d rounds per mode (dt 1/60 s, seed %u), after %d warm-up "
                  "frames; modes interleaved per frame, order rotated each round; HUD off, mirror %s\n",
                  r.frames, r.rounds, r.seed, r.warmup, r.mirror ? "on" : "off");
    o += line;
    if (r.particlesRequested > 0) {
        std::snprintf(line, sizeof line,
                      "- particles alive (median): %.0f of %.0f requested (%.1f%%; pools %.0f); simulation %.3f "
                      "ms/frame (not in frame times)\n",
                      r.particlesAlive, r.particlesRequested, 100.0 * r.particlesAlive / r.particlesRequested,
                      r.particleCapacity, r.simMsPerFrame);
    } else {
        std::snprintf(line, sizeof line,
                      "- particles alive (median): %.0f; simulation %.3f ms/frame (not in frame times)\n",
                      r.particlesAlive, r.simMsPerFrame);
    }
    o += line;
    std::snprintf(line, sizeof line,
                  "- image error over %d frames per mode against the reference's render of the same simulated "
                  "frame (soft modes vs soft, spherical+quarter vs spherical, the full-res techniques vs a "
                  "second render of themselves: 0 = deterministic); PSNR over RGB 8-bit, capped at %.0f dB\n",
                  r.modes.empty() ? 0 : r.modes[0].errorFrames, kPsnrCapDb);
    o += line;
    o += "\n| Method | Setup | Min FPS | Max FPS | Average FPS | p50 ms | p95 ms | p99 ms | vs hard | "
         "particle ms | outside passes ms | fill-limit x | RMSE | PSNR dB | max abs | edge % |\n";
    o += "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ModeSummary& m : r.modes) {
        std::snprintf(line, sizeof line, "| %s (`%s`) | %dx%d, %s | ", m.setup.c_str(), m.name.c_str(), r.width,
                      r.height, r.scenario.c_str());
        o += line;
        o += fmt("%.1f", m.fpsMin) + " | " + fmt("%.1f", m.fpsMax) + " | " + fmt("%.1f", m.fpsAvg) + " | ";
        o += fmt("%.2f", m.p50) + " | " + fmt("%.2f", m.p95) + " | " + fmt("%.2f", m.p99) + " | ";
        o += fmt("%.3f", m.ratioVsHard) + " | " + fmt("%.2f", m.particleMs) + " | " + fmt("%.2f", m.outsidePassesMs) +
             " | ";
        o += (m.fillLimitRatio > 0 ? fmt("%.1f", m.fillLimitRatio) : std::string("-")) + " | ";
        o += fmt("%.2f", m.rmse) + " | " + psnrText(m.psnrDb) + " | " + fmt("%.0f", m.maxAbs) + " | " +
             fmt("%.2f", m.edgePct) + " |\n";
    }

    // Per-pass medians: one column per mode.
    perPassTable(r, &ModeSummary::passes, "Per-pass median ms (" + r.timingMethod + "); '-' = pass not run in that mode",
                 "%.3f", &o);

    // Per particle pass, the samples it wrote: what a pass's time is paid for (a composite's
    // blended pixels, a downsample's half-res texels); then, where the context counts them, the
    // fragments it shaded (discarded ones included: a bound's waste, a composite's early outs).
    perPassTable(r, &ModeSummary::passFragments,
                 "Per particle pass, samples written (GL_SAMPLES_PASSED, median over error frames); '-' = not run",
                 "%.0f", &o);
    perPassTable(r, &ModeSummary::passShaded,
                 "Per particle pass, fragments shaded (GL_FRAGMENT_SHADER_INVOCATIONS_ARB: discarded ones too; "
                 "a compute pass adds its invocations: the tiled path's one per pixel of its tiles and one per "
                 "particle, and where the GPU writes its lists (over TiledPath::kCpuListEntries) one per list entry "
                 "and per sort pass 512 per block (TileSort::rowsFor: 256 to 4,096 entries) and 1,024; median over error "
                 "frames); "
                 "'-' = not run",
                 "%.0f", &o);

    o += "\nParticle work vs the fill limit (trivial textured quad blended once over the covered pixels)\n\n"
         "| mode | particles drawn | coverage % | particle ms | particle fragments | fill-limit ms | ratio | vs nofx | "
         "allocating renders |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ModeSummary& m : r.modes) {
        o += "| " + m.name + " | " + fmt("%.0f", m.particles) + " | " + fmt("%.1f", m.coveragePct) + " | " +
             fmt("%.2f", m.particleMs) + " | " + fmt("%.0f", m.particleFragments) + " | " +
             fmt("%.3f", m.fillLimitMs) + " | " + (m.fillLimitRatio > 0 ? fmt("%.1f", m.fillLimitRatio) : std::string("-")) + " | " +
             fmt("%.3f", m.ratioVsNofx) + " | " + std::to_string(m.allocatingRenders) + " |\n";
    }
    // Where the frame's wall time went on the CPU's clock: what the GPU waited for before the
    // first pass (declare), the issuing of the passes, and the wait for the GPU.
    o += "\nThe frame on the CPU's clock (medians; declare + execute + finish = the frame)\n\n"
         "| mode | declare ms | execute ms | finish ms | outside passes ms |\n|---|---:|---:|---:|---:|\n";
    for (const ModeSummary& m : r.modes) {
        o += "| " + m.name + " | " + fmt("%.2f", m.declareMs) + " | " + fmt("%.2f", m.executeMs) + " | " +
             fmt("%.2f", m.finishMs) + " | " + fmt("%.2f", m.outsidePassesMs) + " |\n";
    }
    o += std::string("- declare / execute / finish: ") + frameCpuDefinition() + "\n";
    o += "\n- vs hard / vs nofx: median frame ms / that mode's median frame ms (same run)\n";
    o += std::string("- coverage: ") + coverageDefinition() + "; fill-limit x = particle ms / fill-limit ms "
         "(median over error frames; '-' = no particle pass)\n";
    o += std::string("- edge %: ") + edgeDefinition() + "\n";
    o += std::string("- outside passes ms: ") + outsidePassesDefinition() + "\n";
    std::snprintf(line, sizeof line, "- pixels next to depth edges: %.1f%% of the frame\n", r.edgePixelPct);
    o += line;
    for (const std::string& n : r.notes) o += "- note: " + n + "\n";
    return o;
}

std::string jsonReport(const Report& r, const std::string& in) {
    std::string o;
    o += in + "{\n";
    o += in + "  \"scenario\": " + jsonQuote(r.scenario) + ",\n";
    o += in + "  \"description\": " + jsonQuote(r.description) + ",\n";
    o += in + "  \"size\": [" + std::to_string(r.width) + ", " + std::to_string(r.height) + "],\n";
    o += in + "  \"frames\": " + std::to_string(r.frames) + ",\n";
    o += in + "  \"rounds\": " + std::to_string(r.rounds) + ",\n";
    o += in + "  \"warmup\": " + std::to_string(r.warmup) + ",\n";
    o += in + "  \"seed\": " + std::to_string(r.seed) + ",\n";
    o += in + "  \"renderer\": " + jsonQuote(r.renderer) + ",\n";
    o += in + "  \"backend\": " + jsonQuote(r.backend) + ",\n";
    o += in + "  \"threads\": " + std::to_string(r.threads) + ",\n";
    o += in + "  \"timing_method\": " + jsonQuote(r.timingMethod) + ",\n";
    o += in + "  \"mirror\": " + std::string(r.mirror ? "true" : "false") + ",\n";
    o += in + "  \"hud\": false,\n";
    o += in + "  \"ratio_base\": \"hard\",\n";
    o += in + "  \"psnr_cap_db\": " + num(kPsnrCapDb) + ",\n";
    o += in + "  \"particles_alive\": " + num(r.particlesAlive) + ",\n";
    o += in + "  \"sim_ms_per_frame\": " + num(r.simMsPerFrame) + ",\n";
    if (r.particlesRequested > 0) o += in + "  \"particles_requested\": " + num(r.particlesRequested) + ",\n";
    o += in + "  \"particle_capacity\": " + num(r.particleCapacity) + ",\n";
    o += in + "  \"edge_pixel_pct\": " + num(r.edgePixelPct) + ",\n";
    o += in + "  \"edge_definition\": " + jsonQuote(edgeDefinition()) + ",\n";
    o += in + "  \"coverage_definition\": " + jsonQuote(coverageDefinition()) + ",\n";
    o += in + "  \"fill_limit_definition\": " + jsonQuote(std::string(
        "median over error frames of particle-pass ms / ms of one alpha-blended textured quad span per run of covered "
        "pixels; 0 = no particle pass or nothing covered")) + ",\n";
    o += in + "  \"frame_ms_definition\": " + jsonQuote(std::string(
        "Game::RenderFrame wall ms (CPU clock around glFinish) of the timed render; every mode's render targets stay "
        "pooled across a round, and a render that still created or freed targets is repeated and the repeat timed")) + ",\n";
    o += in + "  \"pass_ms_definition\": " + jsonQuote(r.timingMethod == std::string("cpu-glfinish")
        ? std::string("CPU clock between glFinish calls around each pass")
        : r.timingMethod + " results of each render, waited for after its glFinish (Game::RenderFrame)") + ",\n";
    o += in + "  \"outside_passes_definition\": " + jsonQuote(outsidePassesDefinition()) + ",\n";
    o += in + "  \"cpu_frame_definition\": " + jsonQuote(frameCpuDefinition()) + ",\n";
    o += in + "  \"notes\": [";
    for (size_t i = 0; i < r.notes.size(); ++i) o += (i ? ", " : "") + jsonQuote(r.notes[i]);
    o += "],\n";
    o += in + "  \"modes\": [\n";
    for (size_t i = 0; i < r.modes.size(); ++i) {
        const ModeSummary& m = r.modes[i];
        const std::string p = in + "    ";
        o += p + "{\n";
        o += p + "  \"name\": " + jsonQuote(m.name) + ",\n";
        o += p + "  \"setup\": " + jsonQuote(m.setup) + ",\n";
        o += p + "  \"samples\": " + std::to_string(m.samples) + ",\n";
        o += p + "  \"fps\": {\"min\": " + num(m.fpsMin) + ", \"avg\": " + num(m.fpsAvg) + ", \"max\": " + num(m.fpsMax) + "},\n";
        o += p + "  \"frame_ms\": {\"p50\": " + num(m.p50) + ", \"p95\": " + num(m.p95) + ", \"p99\": " + num(m.p99) + "},\n";
        o += p + "  \"ratio_vs_hard\": " + num(m.ratioVsHard) + ",\n";
        o += p + "  \"ratio_vs_nofx\": " + num(m.ratioVsNofx) + ",\n";
        o += p + "  \"passes_ms\": " + jsonObject(m.passes) + ",\n";
        o += p + "  \"particle_pass_ms\": " + num(m.particleMs) + ",\n";
        o += p + "  \"outside_passes_ms\": " + num(m.outsidePassesMs) + ",\n";
        o += p + "  \"cpu_declare_ms\": " + num(m.declareMs) + ",\n";
        o += p + "  \"cpu_execute_ms\": " + num(m.executeMs) + ",\n";
        o += p + "  \"cpu_finish_ms\": " + num(m.finishMs) + ",\n";
        o += p + "  \"particle_fragments\": " + num(m.particleFragments) + ",\n";
        o += p + "  \"passes_fragments\": " + jsonObject(m.passFragments) + ",\n";
        o += p + "  \"passes_shaded\": " + jsonObject(m.passShaded) + ",\n";
        o += p + "  \"particles\": " + num(m.particles) + ",\n";
        o += p + "  \"coverage_pct\": " + num(m.coveragePct) + ",\n";
        o += p + "  \"fill_limit_ms\": " + num(m.fillLimitMs) + ",\n";
        o += p + "  \"fill_limit_ratio\": " + num(m.fillLimitRatio) + ",\n";
        o += p + "  \"allocating_renders\": " + std::to_string(m.allocatingRenders) + ",\n";
        o += p + "  \"error\": {\"reference\": " + jsonQuote(m.reference) + ", \"rmse\": " + num(m.rmse) +
             ", \"psnr_db\": " + num(m.psnrDb) + ", \"max_abs\": " + num(m.maxAbs) + ", \"edge_pct\": " +
             num(m.edgePct) + ", \"frames\": " + std::to_string(m.errorFrames) + "}\n";
        o += p + "}" + (i + 1 < r.modes.size() ? "," : "") + "\n";
    }
    o += in + "  ]\n";
    o += in + "}";
    return o;
}

std::string csvRows(const Report& r, const std::string& point, bool header) {
    std::string o;
    if (header)
        o += "point,scenario,width,height,mode,fps_min,fps_avg,fps_max,p50_ms,p95_ms,p99_ms,ratio_vs_hard,"
             "ratio_vs_nofx,particle_pass_ms,particle_fragments,particles,coverage_pct,fill_limit_ms,fill_limit_ratio,reference,"
             "rmse,psnr_db,max_abs,edge_pct,passes_ms,outside_passes_ms\n";
    for (const ModeSummary& m : r.modes) {
        std::string passes;
        for (const auto& p : m.passes) passes += (passes.empty() ? "" : ";") + p.first + "=" + num(p.second);
        o += point + "," + r.scenario + "," + std::to_string(r.width) + "," + std::to_string(r.height) + "," + m.name +
             "," + num(m.fpsMin) + "," + num(m.fpsAvg) + "," + num(m.fpsMax) + "," + num(m.p50) + "," + num(m.p95) +
             "," + num(m.p99) + "," + num(m.ratioVsHard) + "," + num(m.ratioVsNofx) + "," + num(m.particleMs) + "," +
             num(m.particleFragments) + "," + num(m.particles) + "," + num(m.coveragePct) + "," + num(m.fillLimitMs) + "," + num(m.fillLimitRatio) +
             "," + m.reference + "," + num(m.rmse) + "," + num(m.psnrDb) + "," + num(m.maxAbs) + "," +
             num(m.edgePct) + ",\"" + passes + "\"," + num(m.outsidePassesMs) + "\n";
    }
    return o;
}

bool writeText(const std::string& path, const std::string& text, std::string* error) {
    std::ofstream out(path, std::ios::binary);
    if (!out) {
        *error = path + ": cannot write (folder missing or not writable?)";
        return false;
    }
    out << text;
    if (!out) {
        *error = path + ": write failed";
        return false;
    }
    return true;
}

}  // namespace fxbench
