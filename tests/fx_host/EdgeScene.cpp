// The quarter-res tests' depth-edge scene and their error measures (FxTestHost.h).
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "FxTestHost.h"

namespace fxtest {

Image amplifiedDiff(const Image& a, const Image& b, int gain) {
    Image d = a;
    for (size_t i = 0; i < d.rgba.size(); ++i) {
        d.rgba[i] = (i & 3) == 3 ? 255 : uint8_t(std::min(255, gain * std::abs(int(a.rgba[i]) - int(b.rgba[i]))));
    }
    return d;
}

std::vector<uint8_t> depthEdgeMask(const std::vector<float>& depth, int w, int h, int radius) {
    std::vector<uint8_t> edge(depth.size(), 0), mask(depth.size(), 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float d = depth[size_t(y) * size_t(w) + size_t(x)];
            for (auto [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (x + dx >= w || y + dy >= h) continue;
                const float e = depth[size_t(y + dy) * size_t(w) + size_t(x + dx)];
                if (std::fabs(d - e) > 0.1f * std::min(d, e)) edge[size_t(y) * size_t(w) + size_t(x)] = 1;
            }
        }
    }
    // The discontinuity lies between a pixel and its +x/+y neighbour: the band reaches one
    // further on that side.
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!edge[size_t(y) * size_t(w) + size_t(x)]) continue;
            for (int v = std::max(0, y - radius); v <= std::min(h - 1, y + radius + 1); ++v) {
                for (int u = std::max(0, x - radius); u <= std::min(w - 1, x + radius + 1); ++u) {
                    mask[size_t(v) * size_t(w) + size_t(u)] = 1;
                }
            }
        }
    }
    return mask;
}

MaskError maskedError(const Image& a, const Image& b, const std::vector<uint8_t>& mask) {
    MaskError e;
    double sum = 0.0;
    for (size_t p = 0; p < mask.size(); ++p) {
        if (!mask[p]) continue;
        ++e.pixels;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(a.rgba[p * 4 + size_t(c)]) - int(b.rgba[p * 4 + size_t(c)]));
            sum += d;
            e.max = std::max(e.max, d);
        }
    }
    e.mean = e.pixels ? sum / (3.0 * e.pixels) : 0.0;
    return e;
}

EdgeScene wallAndPoleScene(int width, int height, bool reversedZ) {
    EdgeScene s;
    for (int i = 0; i < 7; ++i) {
        const float x = -3.0f + float(i);
        s.puffs.push_back(HandParticle{glm::vec3(x, 1.2f + 0.35f * float(i % 3), -0.5f * float(i % 2)), 2.6f, 0.5f,
                                       0.7f * float(i), 1.0f, i & 3});
    }
    s.scene.sky = glm::vec3(0.08f, 0.1f, 0.2f);
    s.scene.reversedZ = reversedZ;
    s.scene.quads = {TestScene::ground(60.0f, glm::vec3(0.1f)),
                     TestScene::wallZ(2.0f, -10.0f, 10.0f, 0.0f, 1.37f, glm::vec3(0.4f, 0.08f, 0.08f)),
                     TestScene::wallZ(3.0f, 0.97f, 1.03f, 0.0f, 4.0f, glm::vec3(0.1f, 0.3f, 0.1f))};
    s.view = makeView(glm::vec3(0.0f, 1.4f, 8.0f), glm::vec3(0.0f, 1.4f, 0.0f), width, height);
    if (reversedZ) useReversedZ(&s.view);
    return s;
}

}  // namespace fxtest
