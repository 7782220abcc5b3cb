#pragma once
// Helpers for tests that run the whole game headless.
#include <cmath>
#include <memory>
#include <string>

#include "game/Game.h"

namespace cubetest {

/// Options for a small deterministic headless run. Defaults: 320x256, dt 1/60, seed 7.
inline cube::Options smallOptions(int w = 320, int h = 256) {
    cube::Options o;
    o.width = w;
    o.height = h;
    o.fixedDt = 1.0 / 60.0;
    o.seed = 7;
    o.hud = false;
    return o;
}

/// smallOptions for a look at the scene alone: no mirror view, no reactions (none.yaml).
inline cube::Options sceneOnlyOptions(int w, int h) {
    cube::Options o = smallOptions(w, h);
    o.mirror = false;
    o.reactions = std::string(CUBE_SOURCE_DIR) + "/reactions/none.yaml";
    return o;
}

/// Runs `frames` frames and captures the last one.
inline bool runFrames(cube::Game& game, int frames) {
    for (int i = 0; i < frames; ++i) {
        if (i + 1 == frames) game.captureNextFrame();
        game.Dyn(float(game.options().fixedDt));
    }
    return !game.lastFrame().pixels.empty();
}

/// Points the chase view from `eye` at `target` (world space) and keeps it there.
inline void fixCamera(cube::Options& o, const glm::vec3& eye, const glm::vec3& target) {
    o.fixedCamera = true;
    for (int k = 0; k < 3; ++k) {
        o.cameraEye[k] = eye[k];
        o.cameraTarget[k] = target[k];
    }
}

/// Projects a world point with the chase camera into top-down pixel coordinates.
inline glm::ivec2 project(cube::Game& g, glm::vec3 p) {
    const cube::cubeView& v = g.chaseView();
    const glm::mat4 vp = v.camera().proj(float(v.width()) / float(v.height())) * v.camera().view();
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    const glm::vec3 ndc = glm::vec3(c) / c.w;
    return {int((ndc.x * 0.5f + 0.5f) * float(v.width())), int((0.5f - ndc.y * 0.5f) * float(v.height()))};
}

struct Rgb {
    int r, g, b;
};
inline Rgb pixel(const cube::ImageRGBA8& img, int x, int y) {
    const size_t i = (size_t(y) * size_t(img.width) + size_t(x)) * 4u;
    return {img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]};
}

/// PSNR in dB of b against a over RGB (inf when identical).
inline double psnr(const cube::ImageRGBA8& a, const cube::ImageRGBA8& b) {
    double se = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = double(a.pixels[i]) - double(b.pixels[i]);
        se += d * d;
        ++n;
    }
    if (se == 0.0) return INFINITY;
    return 10.0 * std::log10(255.0 * 255.0 / (se / double(n)));
}

}  // namespace cubetest
