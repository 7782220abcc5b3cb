// cube_game: the stand-in racing game. Runs the scripted drive headless (OSMesa) by default,
// in a window with --window, or on a GPU with --backend egl. See --help.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>

#include "apps/CommandLine.h"
#include "game/Game.h"
#include "gl/Gl.h"
#include "gl/Image.h"
#include "panel/TweakPanel.h"

namespace {

// SIGINT/SIGTERM only set this; the frame loop notices it between frames, so the current frame
// finishes and the screenshot and stats are still written. SA_RESETHAND: a second signal
// during that clean-up ends the process the default way.
volatile std::sig_atomic_t g_stopSignal = 0;

void onStopSignal(int signo) { g_stopSignal = signo; }

void installStopHandlers() {
    struct sigaction sa {};
    sa.sa_handler = &onStopSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
    cube::Options options;
    const int exitNow = cube::parseCommandLine("cube_game", argc, argv, &cube::parseOptions, &cube::usage, &options);
    if (exitNow >= 0) return exitNow;
    std::string error;
    installStopHandlers();
    cube::Game game;
    if (!game.Init(options, &error)) {
        std::fprintf(stderr, "cube_game: %s\n", error.c_str());
        return 1;
    }
    // A flag that needs the loaded reactions is checked now, before the first frame; refused as
    // every other flag is (exit 2).
    if (!game.checkExplodeAt(&error)) {
        std::fprintf(stderr, "cube_game: %s\n", error.c_str());
        return 2;
    }
    for (const std::string& w : game.warnings()) std::fprintf(stderr, "cube_game: warning: %s\n", w.c_str());
    // Declared after the game: destroyed first, while the game's GL context still exists.
    cube::TweakPanel panel;
    if (options.panel) {
        if (!panel.init(game, &error)) {
            std::fprintf(stderr, "cube_game: %s\n", error.c_str());
            return 1;
        }
        game.setOverlay(&panel);
    }
    std::printf("cube_game: %s on %s, %dx%d, fx %s\n", cube::backendName(game.platform().backend()),
                game.platform().rendererName().c_str(), options.width, options.height,
                options.fx == cube::FxPath::Legacy ? "legacy" : "plugin");

    auto last = std::chrono::steady_clock::now();
    int status = 0;
    bool capturedLast = false;
    for (long long f = 0; options.frames == 0 || f < options.frames; ++f) {
        if (g_stopSignal || !game.platform().pollEvents()) break;
        float dt = float(options.fixedDt);
        if (options.fixedDt <= 0.0) {
            const auto now = std::chrono::steady_clock::now();
            dt = f == 0 ? 1.0f / 60.0f : std::chrono::duration<float>(now - last).count();
            last = now;
        }
        const bool lastFrame = options.frames > 0 && f + 1 == options.frames;
        const bool every = options.screenshotEvery > 0 && (f + 1) % options.screenshotEvery == 0;
        if ((lastFrame && !options.screenshot.empty()) || every) game.captureNextFrame();
        game.Dyn(dt);
        capturedLast = lastFrame;
        if (every) {
            char name[64];
            std::snprintf(name, sizeof name, "/frame_%06lld.png", f + 1);
            if (!cube::writePng(options.screenshotDir + name, game.lastFrame(), &error)) {
                std::fprintf(stderr, "cube_game: %s\n", error.c_str());
                status = 1;
                break;
            }
        }
    }
    if (g_stopSignal) {
        std::fprintf(stderr, "cube_game: %s after frame %lld: writing the results and stopping\n",
                     g_stopSignal == SIGINT ? "SIGINT" : "SIGTERM", game.frame());
    }
    if (!options.screenshot.empty() && status == 0 && !capturedLast) {
        // Stopped early (signal, window closed): draw the current state once more to capture it.
        game.captureNextFrame();
        game.RenderFrame();
    }
    if (!options.screenshot.empty() && status == 0) {
        if (!cube::writePng(options.screenshot, game.lastFrame(), &error)) {
            std::fprintf(stderr, "cube_game: %s\n", error.c_str());
            status = 1;
        } else {
            std::printf("cube_game: wrote %s\n", options.screenshot.c_str());
        }
    }
    if (!options.statsJson.empty()) {
        if (!game.writeStatsJson(options.statsJson, &error)) {
            std::fprintf(stderr, "cube_game: %s\n", error.c_str());
            status = 1;
        } else {
            std::printf("cube_game: wrote %s\n", options.statsJson.c_str());
        }
    }
    if (cube::gl::errorCount() > 0) {
        std::fprintf(stderr, "cube_game: %d GL error(s), last: %s\n", cube::gl::errorCount(),
                     cube::gl::lastError().c_str());
        status = status ? status : 3;
    }
    std::printf("cube_game: %lld frames, %d particles alive\n", game.frame(), game.specialFX().particlesAlive());
    if (g_stopSignal && status == 0) status = 128 + int(g_stopSignal);  // 130 SIGINT, 143 SIGTERM
    return status;
}
