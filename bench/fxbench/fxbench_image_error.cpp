#include "fxbench_image_error.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>

namespace fxbench {

void ErrorAccum::add(const cube::ImageRGBA8& image, const cube::ImageRGBA8& reference,
                     const std::vector<uint8_t>& edges) {
    assert(image.width == reference.width && image.height == reference.height);
    assert(image.pixels.size() == reference.pixels.size());
    const size_t pixels = size_t(image.width) * size_t(image.height);
    const bool useEdges = edges.size() == pixels;
    const uint8_t* a = image.pixels.data();
    const uint8_t* b = reference.pixels.data();
    uint64_t sq = 0;  // exact: at most 3 * 255^2 per pixel
    for (size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(a[4 * p + size_t(c)]) - int(b[4 * p + size_t(c)]));
            sq += uint64_t(d * d);
            worst = std::max(worst, d);
        }
        maxAbs = std::max(maxAbs, worst);
        if (useEdges && edges[p]) {
            ++edgePixels;
            if (worst > kEdgeErrorThreshold) ++edgeOver;
        }
    }
    sumSq += double(sq);
    channels += 3 * uint64_t(pixels);
    ++frames;
}

double ErrorAccum::rmse() const { return channels ? std::sqrt(sumSq / double(channels)) : 0.0; }

double ErrorAccum::psnrDb() const {
    const double e = rmse();
    if (e <= 0.0) return kPsnrCapDb;
    return std::min(kPsnrCapDb, 20.0 * std::log10(255.0 / e));
}

double ErrorAccum::edgePct() const { return edgePixels ? 100.0 * double(edgeOver) / double(edgePixels) : 0.0; }

std::vector<uint8_t> depthEdgeMask(const std::vector<float>& depth, int w, int h) {
    std::vector<uint8_t> edge(size_t(w) * size_t(h), 0), out(edge.size(), 0);
    if (depth.size() < edge.size()) return out;
    // Inverse depth is affine in screen space across any plane, so its second difference is ~0
    // on a plane seen at any angle (the far ground too) and large where surfaces meet or jump.
    std::vector<float> inv(edge.size());
    for (size_t i = 0; i < inv.size(); ++i) inv[i] = depth[i] > 1e-6f ? 1.0f / depth[i] : 1e6f;
    auto bent = [&](size_t prev, size_t i, size_t next) {
        return std::fabs(inv[prev] - 2.0f * inv[i] + inv[next]) > kDepthEdgeRelJump * inv[i];
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if ((x > 0 && x + 1 < w && bent(i - 1, i, i + 1)) ||
                (y > 0 && y + 1 < h && bent(i - size_t(w), i, i + size_t(w))))
                edge[i] = 1;
        }
    }
    const int r = kDepthEdgeRadius;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!edge[size_t(y) * size_t(w) + size_t(x)]) continue;
            for (int yy = std::max(0, y - r); yy <= std::min(h - 1, y + r); ++yy)
                for (int xx = std::max(0, x - r); xx <= std::min(w - 1, x + r); ++xx)
                    out[size_t(yy) * size_t(w) + size_t(xx)] = 1;
        }
    }
    return out;
}

size_t coverageMask(const cube::ImageRGBA8& frame, const cube::ImageRGBA8& bare, std::vector<uint8_t>* mask) {
    const size_t pixels = size_t(frame.width) * size_t(frame.height);
    mask->assign(pixels, 0);
    if (bare.pixels.size() != frame.pixels.size()) return 0;
    size_t covered = 0;
    for (size_t p = 0; p < pixels; ++p) {
        const uint8_t* a = &frame.pixels[4 * p];
        const uint8_t* b = &bare.pixels[4 * p];
        if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) {
            (*mask)[p] = 1;
            ++covered;
        }
    }
    return covered;
}

}  // namespace fxbench
