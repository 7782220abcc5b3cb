#pragma once
// Image error of a mode's frame against its reference frame (the same simulated frame), the
// depth-edge mask the edge statistic uses, and the particle coverage mask the fill limit draws.
#include <cstdint>
#include <vector>

#include "gl/Image.h"

namespace fxbench {

/// PSNR reported for identical images (MSE 0): a finite cap, so JSON never holds inf.
constexpr double kPsnrCapDb = 99.0;
/// A pixel "differs visibly" when some RGB channel differs by more than this (of 255).
constexpr int kEdgeErrorThreshold = 8;
/// Depth edge: the second difference of inverse depth (horizontal or vertical) exceeds this
/// fraction of the pixel's inverse depth.
constexpr float kDepthEdgeRelJump = 0.10f;
/// Pixels within this many pixels (Chebyshev) of a depth edge count as "next to" it.
constexpr int kDepthEdgeRadius = 1;

/// Error statistics summed over any number of frame pairs (pooled, not averaged per frame).
/// Defaults: nothing compared.
struct ErrorAccum {
    double sumSq = 0.0;         ///< squared 8-bit differences over R, G, B
    uint64_t channels = 0;      ///< samples in sumSq (3 per pixel)
    int maxAbs = 0;             ///< largest absolute channel difference, 0..255
    uint64_t edgePixels = 0;    ///< pixels next to depth edges
    uint64_t edgeOver = 0;      ///< ... of those whose error exceeds kEdgeErrorThreshold
    int frames = 0;

    /// Adds one frame pair; images must have the same size. `edges` is one byte per pixel
    /// (non-zero = next to a depth edge), empty for none.
    void add(const cube::ImageRGBA8& image, const cube::ImageRGBA8& reference, const std::vector<uint8_t>& edges);
    double rmse() const;     ///< in 8-bit units (0..255)
    double psnrDb() const;   ///< 20 log10(255 / rmse), kPsnrCapDb when rmse is 0
    double edgePct() const;  ///< 100 * edgeOver / edgePixels (0 without edge pixels)
};

/// Depth-edge mask (1 byte per pixel, rows top-down) from linear view depth in metres (rows
/// top-down, sky = a huge value): a pixel is an edge when |1/d[-1] - 2/d + 1/d[+1]| (along x
/// or y) exceeds kDepthEdgeRelJump / d. Inverse depth is affine across a plane, so planes at any
/// angle give no edges while silhouettes, jumps and creases do. The mask is that set dilated
/// by kDepthEdgeRadius.
std::vector<uint8_t> depthEdgeMask(const std::vector<float>& linearDepth, int width, int height);

/// Coverage: 1 where any RGB channel of `frame` differs from `bare` (the nofx frame of the same
/// simulated frame). Returns the covered pixel count.
size_t coverageMask(const cube::ImageRGBA8& frame, const cube::ImageRGBA8& bare, std::vector<uint8_t>* mask);

}  // namespace fxbench
