#include "fxbench_measure.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <memory>

#include <unistd.h>

#include "fxbench_depth.h"
#include "fxbench_options.h"
#include "render/FillRateProbe.h"
#include "fxbench_stats.h"
#include "game/Game.h"
#include "game/JobSystem.h"
#include "gl/Gl.h"

namespace fxbench {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// Progress on stderr: an updating line on a terminal, a line every 10 s otherwise.
class Progress {
public:
    Progress(std::string label, int total) : label_(std::move(label)), total_(total), tty_(isatty(2) != 0) {}
    void update(int done, const char* phase) {
        const double s = msSince(start_) / 1000.0;
        if (s - last_ < (tty_ ? 0.25 : 10.0)) return;
        last_ = s;
        const double left = done > 0 ? s * double(total_ - done) / double(done) : 0.0;
        std::fprintf(stderr, "%sfxbench %s: %s frame %d/%d, %.0f s, ~%.0f s left%s", tty_ ? "\r" : "",
                     label_.c_str(), phase, done, total_, s, left, tty_ ? "   " : "\n");
        shown_ = true;
    }
    ~Progress() {
        if (shown_ && tty_) std::fprintf(stderr, "\n");
    }

private:
    std::string label_;
    int total_;
    bool tty_;
    bool shown_ = false;
    double last_ = -1e9;
    Clock::time_point start_ = Clock::now();
};

// The plugin's passes: the billboards' ("particles", the quarter-res ones), mega-particles'
// ("mega_...") and lit smoke's opacity map ("smoke_opacity"); with the immediate path the engine's
// one pass around Plugin::renderView ("fx_immediate": the depth copy, its linearisation and every
// plugin pass inside).
bool isParticlePass(const std::string& name) {
    return name.find("particles") != std::string::npos || name.find("mega_") != std::string::npos ||
           name.find("smoke_opacity") != std::string::npos || name.find("fx_immediate") != std::string::npos;
}

/// The rows top-down the mirror inset covers in the chase frame (cubeView's HUD pass), plus its
/// 3-pixel frame; empty when the mirror is off.
void maskOutInset(const cube::Options& o, int w, int h, std::vector<uint8_t>* mask) {
    if (!o.mirror) return;
    const int iw = std::max(1, int(float(w) * 0.30f)), ih = std::max(1, int(float(h) * 0.13f));
    const int x0 = (w - iw) / 2 - 3, x1 = (w - iw) / 2 + iw + 3;
    const int glY0 = h - ih - 12 - 3, glY1 = h - 12 + 3;  // GL rows, bottom-up
    for (int gy = std::max(0, glY0); gy < std::min(h, glY1); ++gy) {
        const int row = h - 1 - gy;
        for (int x = std::max(0, x0); x < std::min(w, x1); ++x) (*mask)[size_t(row) * size_t(w) + size_t(x)] = 0;
    }
}

std::string fileSafe(std::string s) {
    std::replace(s.begin(), s.end(), '+', '-');
    return s;
}

class Runner {
public:
    Runner(const RunConfig& config, RunResult* out) : config_(config), out_(out) {}

    bool run(std::string* error) {
        if (!game_.Init(config_.game, error)) return false;
        game_.setCameraQuads(config_.cameraQuads);
        if (!probe_.init(error)) return false;
        out_->renderer = game_.platform().rendererName();
        out_->backend = std::string(cube::backendName(game_.platform().backend())) +
                        (game_.scene().renderer().reversedZ() ? ", reversed-Z float depth" : ", standard 24-bit depth");
        out_->timingMethod = game_.graph().timingMethod();
        out_->threads = game_.jobs()->threads();
        for (const Mode* m : measuredModes(config_.selected)) {
            ModeRun r;
            r.mode = m;
            r.selected = config_.selected.empty() ||
                         std::find(config_.selected.begin(), config_.selected.end(), m->name) != config_.selected.end();
            out_->modes.push_back(std::move(r));
        }
        const float dt = float(config_.game.fixedDt);
        const int preroll = int(config_.scenario->prerollSeconds / double(dt) + 0.5);
        for (int i = 0; i < preroll; ++i) game_.Update(dt);

        Progress progress(config_.progressLabel, config_.warmup + config_.frames);
        for (int i = 0; i < config_.warmup; ++i) {
            game_.Update(dt);
            for (ModeRun& m : out_->modes) renderOnce(m, false);
            progress.update(i + 1, "warm-up");
        }
        const std::vector<int> errorAt = errorFrames();
        std::vector<double> alive, simMs;
        const int modeCount = int(out_->modes.size());
        for (int f = 0; f < config_.frames; ++f) {
            const auto t0 = Clock::now();
            game_.Update(dt);
            simMs.push_back(msSince(t0));
            alive.push_back(game_.specialFX().particlesAlive());
            for (ModeRun& m : out_->modes) m.frameParticleMs.clear();
            for (int r = 0; r < config_.rounds; ++r) {
                // Rotate the start each round and reverse every other round, so each mode sits in
                // each position, and after different modes, about equally often.
                const int turn = f * config_.rounds + r;
                for (int k = 0; k < modeCount; ++k) {
                    const int slot = (turn % 2) ? modeCount - 1 - k : k;
                    renderOnce(out_->modes[size_t((slot + turn) % modeCount)], true);
                }
            }
            if (std::find(errorAt.begin(), errorAt.end(), f) != errorAt.end())
                errorPass(f == errorAt.back());
            progress.update(config_.warmup + f + 1, "timed");
        }
        out_->particlesAlive = median(alive);
        out_->simMsPerFrame = median(simMs);
        if (const fx::Plugin* plugin = game_.specialFX().plugin()) {
            out_->particleCapacity = plugin->stats().particleCapacity;
            for (int i = 0; i < plugin->reactionCount(); ++i) {
                const fx::ReactionStats rs = plugin->reactionStats(i);
                out_->particlesEmitted += double(rs.emitted);
                out_->particlesDropped += double(rs.dropped);
            }
        }
        out_->edgePixelPct = edgeSamples_ ? 100.0 * double(edgeCount_) / double(edgeSamples_) : 0.0;
        out_->glErrors = cube::gl::errorCount();
        return true;
    }

private:
    std::vector<int> errorFrames() const {
        std::vector<int> v;
        const int n = std::min(config_.errorFrames, config_.frames);
        for (int k = 0; k < n; ++k) v.push_back(int((long long)(k + 1) * config_.frames / (n + 1)));
        v.erase(std::unique(v.begin(), v.end()), v.end());
        return v;
    }

    /// True when the last render created or destroyed pool targets.
    bool poolChurned(const cube::rtt::RenderTargetPoolStats& before) {
        const cube::rtt::RenderTargetPoolStats now = game_.pool().stats();
        return now.totalAllocations != before.totalAllocations ||
               now.liveFramebuffers != before.liveFramebuffers + int(now.totalAllocations - before.totalAllocations);
    }

    void renderOnce(ModeRun& m, bool timed) {
        applyMode(game_, *m.mode);
        // Targets of every mode stay pooled across a round (Options::poolFramesUntilFree is set
        // in gameOptions), so a timed render normally allocates nothing; the warm-up frames
        // created them. A render that still allocated is repeated below.
        cube::rtt::RenderTargetPoolStats before = game_.pool().stats();
        double ms = game_.RenderFrame();
        if (!timed) return;
        for (int retry = 0; retry < 3 && poolChurned(before); ++retry) {
            // Rare: this render's frame-end still freed another mode's stale target. Time a repeat.
            ++m.allocatingRenders;
            before = game_.pool().stats();
            ms = game_.RenderFrame();
        }
        m.frameMs.push_back(ms);
        // Game::RenderFrame resolved this render's pass timings after its glFinish (GPU timer
        // results included), so every lastMs below is this render's, in this mode.
        double particles = 0.0, passes = 0.0;
        for (const cube::rtt::PassTiming& t : game_.graph().report().timings) {
            if (t.lastMs < 0.0) continue;
            passes += t.lastMs;
            auto it = m.passMs.find(t.name);
            if (it == m.passMs.end()) {
                m.passOrder.push_back(t.name);
                it = m.passMs.emplace(t.name, std::vector<double>{}).first;
            }
            it->second.push_back(t.lastMs);
            if (isParticlePass(t.name)) particles += t.lastMs;
        }
        m.particleMs.push_back(particles);
        m.outsidePassesMs.push_back(ms - passes);
        m.declareMs.push_back(game_.lastFrameCpu().declareMs);
        m.executeMs.push_back(game_.lastFrameCpu().executeMs);
        m.finishMs.push_back(game_.lastFrameCpu().finishMs);
        m.frameParticleMs.push_back(particles);
        const fx::Plugin* plugin = game_.specialFX().plugin();
        m.particlesDrawn.push_back(m.mode->effects && plugin ? plugin->stats().particlesDrawn : 0);
    }

    // Untimed: one render of the current simulated frame in mode `m`. With `fragments`, each pass
    // also counts the samples it writes (GL_SAMPLES_PASSED; the read-back waits, so never in a
    // timed render) and, where the context can, its fragment shader invocations; the particle
    // passes' sum of samples goes to m.particleFragments.
    cube::ImageRGBA8 capture(ModeRun& m, bool fragments = false) {
        applyMode(game_, *m.mode);
        game_.captureNextFrame();
        game_.graph().setCountFragments(fragments);
        game_.RenderFrame();
        game_.graph().setCountFragments(false);
        if (fragments) {
            long long sum = 0;
            for (const cube::rtt::PassTiming& t : game_.graph().report().timings) {
                if (!isParticlePass(t.name) || t.fragments < 0) continue;
                sum += t.fragments;
                m.passFragments[t.name].push_back(double(t.fragments));
                if (t.shaded >= 0) m.passShaded[t.name].push_back(double(t.shaded));
            }
            m.particleFragments.push_back(double(sum));
        }
        return game_.lastFrame();
    }

    ModeRun* find(const char* name) {
        for (ModeRun& m : out_->modes)
            if (std::string(m.mode->name) == name) return &m;
        return nullptr;
    }

    // Untimed: every mode's image of this simulated frame, errors against each reference,
    // coverage against nofx and the fill limit over that coverage.
    void errorPass(bool last) {
        std::map<std::string, cube::ImageRGBA8> images;
        for (ModeRun& m : out_->modes) images[m.mode->name] = capture(m, true);
        const int w = images.begin()->second.width, h = images.begin()->second.height;

        std::vector<float> depth;
        std::vector<uint8_t> edges;
        std::string err;
        if (renderChaseDepth(game_, &depth, &err)) {
            edges = depthEdgeMask(depth, w, h);
            maskOutInset(game_.options(), w, h, &edges);
            for (uint8_t e : edges) edgeCount_ += e ? 1 : 0;
            edgeSamples_ += edges.size();
        } else {
            std::fprintf(stderr, "%s\n", err.c_str());
        }

        const ModeRun* bare = find("nofx");
        std::vector<uint8_t> mask;
        for (ModeRun& m : out_->modes) {
            if (!m.mode->effects || !bare) {
                m.fillMs.push_back(0.0);
                m.fillRatio.push_back(0.0);
                m.coveragePct.push_back(0.0);
                continue;
            }
            const size_t covered = coverageMask(images[m.mode->name], images["nofx"], &mask);
            const double fill = median(probe_.drawTimesMs(game_.pool(), mask, w, h, 3));
            const double particle = median(m.frameParticleMs);
            m.fillMs.push_back(fill);
            m.fillRatio.push_back(fill > 0.0 ? particle / fill : 0.0);
            m.coveragePct.push_back(100.0 * double(covered) / double(size_t(w) * size_t(h)));
        }

        // Self-referenced modes render the frame a second time after every other mode and both
        // probes ran: their error is then between two renders of one frame, 0 unless rendering
        // is not deterministic or some GL state leaked (from a mode or from fxbench's probes).
        for (ModeRun& m : out_->modes) {
            const std::string ref = m.mode->reference;
            if (ref == m.mode->name) m.error.add(capture(m), images[ref], edges);
            else if (images.count(ref)) m.error.add(images[m.mode->name], images[ref], edges);
        }

        if (last && !config_.imagesDir.empty()) writeImages(images, edges, w, h);
    }

    void writeImages(const std::map<std::string, cube::ImageRGBA8>& images, const std::vector<uint8_t>& edges,
                     int w, int h) {
        std::string err;
        const std::string prefix = config_.imagesDir + "/" + config_.scenario->name + "_";
        for (const auto& kv : images)
            if (!cube::writePng(prefix + fileSafe(kv.first) + ".png", kv.second, &err))
                std::fprintf(stderr, "fxbench: %s\n", err.c_str());
        // |mode - reference| x 4 for every mode with another reference: where the error is.
        for (const ModeRun& m : out_->modes) {
            const std::string ref = m.mode->reference;
            if (ref == m.mode->name || !images.count(ref)) continue;
            cube::ImageRGBA8 diff = images.at(m.mode->name);
            const cube::ImageRGBA8& r = images.at(ref);
            for (size_t i = 0; i < diff.pixels.size(); ++i)
                diff.pixels[i] = i % 4 == 3 ? 255 : uint8_t(std::min(255, 4 * std::abs(int(diff.pixels[i]) - int(r.pixels[i]))));
            if (!cube::writePng(prefix + "diff_" + fileSafe(m.mode->name) + ".png", diff, &err))
                std::fprintf(stderr, "fxbench: %s\n", err.c_str());
        }
        if (edges.size() == size_t(w) * size_t(h)) {
            // The edge mask over the soft frame, edges in red.
            cube::ImageRGBA8 img = images.count("soft") ? images.at("soft") : images.begin()->second;
            for (size_t p = 0; p < edges.size(); ++p)
                if (edges[p]) img.pixels[4 * p] = 255, img.pixels[4 * p + 1] /= 3, img.pixels[4 * p + 2] /= 3;
            if (!cube::writePng(prefix + "edges.png", img, &err)) std::fprintf(stderr, "fxbench: %s\n", err.c_str());
        }
    }

    const RunConfig& config_;
    RunResult* out_;
    cube::Game game_;
    cube::FillRateProbe probe_;
    uint64_t edgeCount_ = 0, edgeSamples_ = 0;
};

}  // namespace

RunConfig runConfig(const Scenario& scenario, const BenchOptions& bench) {
    RunConfig cfg;
    cfg.scenario = &scenario;
    cfg.game = gameOptions(scenario, bench);
    cfg.cameraQuads = cameraQuads(scenario);
    cfg.frames = bench.frames;
    cfg.rounds = bench.rounds;
    cfg.warmup = bench.warmup;
    cfg.errorFrames = bench.errorFrames;
    cfg.selected = bench.modes;
    return cfg;
}

std::vector<const Mode*> measuredModes(const std::vector<std::string>& selected) {
    std::vector<const Mode*> out;
    for (const Mode& m : allModes()) {
        bool want = selected.empty() || std::string(m.name) == "nofx" || std::string(m.name) == "hard";
        for (const std::string& s : selected) {
            const Mode* sel = findMode(s);
            if (s == m.name || (sel && std::string(sel->reference) == m.name)) want = true;
        }
        if (want) out.push_back(&m);
    }
    return out;
}

bool runBench(const RunConfig& config, RunResult* out, std::string* error) {
    *out = RunResult{};
    if (!config.scenario) {
        *error = "fxbench: no scenario";
        return false;
    }
    // The Runner owns the game (and its GL context) and the probe; the probe is declared after
    // the game, so its GL objects go first, while the context still exists.
    auto runner = std::make_unique<Runner>(config, out);
    return runner->run(error);
}

}  // namespace fxbench
