#pragma once
// Quarter-resolution particles (RenderOptions::quarterRes; the thesis's fourth row of Table 1):
// particles are drawn into a half-width x half-height RGBA16F target (premultiplied), then
// composited onto sceneColor. Three passes, each declared through FrameBuilder (declare()):
//   particles_depth_downsample  reads sceneDepth                   writes particles_half_depth
//   particles_quarter           reads particles_half_depth         writes particles_half_color
//   particles_composite         reads half colour + half depth + sceneDepth, writes sceneColor
//
// Downsampled depth: MINIMUM (nearest) of each 2x2 block. With min, thin foreground geometry
// (poles, barrier tops, a car's roof line) survives in the low-res depth, so the half-res pass
// hides the smoke behind it; the cost is that a block straddling an edge holds no smoke for its
// background pixels, which the composite repairs by borrowing a neighbour. Max (farthest) would
// lose thin foreground geometry altogether and paint smoke over it, an error no upsample can
// undo because no low-res texel holds the right answer.
//
// Upsample: depth-aware, after nearest-depth upsampling (Bavoil, NVIDIA "Opacity Mapping"
// 2011). Per full-res pixel, the 4 low-res texels of the bilinear footprint; if all their depths
// are within kDepthThreshold * depth of the pixel's own depth, bilinear. Otherwise (a depth
// edge) the bilinear weights of the texels within the threshold, renormalised, and when no texel
// is within it the one with the closest depth. (Taking the closest texel alone on every edge
// pixel measured 1.37/255 instead of 1.04/255 below: it turns edges that smoke merely crosses
// blocky.) Plain bilinear stays selectable (RenderOptions::bilinearUpsample) to measure the effect.
//
// Measured (tests/fx_host/QuarterResTest.cpp, Mesa llvmpipe, 256x192; error against the same
// frame drawn at full res, mean |difference| per 8-bit RGB channel):
//   scene: bright soft smoke behind a wall whose top edge crosses it, a 6 cm pole in front;
//   2552 pixels within 2 px of a depth edge:
//     plain bilinear   mean 9.56/255, max 143/255 (a dark band above the wall top where the
//                      straddling texels hold no smoke, smoke smeared over the pole)
//     depth-aware      mean 1.04/255, max  29/255
//   the other 46600 pixels: mean 0.22/255 for both (the upsample only differs at edges);
//   whole frame PSNR: bilinear 32.3 dB, depth-aware 46.9 dB.
//   End-to-end burnout frame (repo reactions, 1.5 s of wheelspin, smoke crossing no depth edge
//   of its own): 43.9 dB with either upsample.
//
// Mixed resolution (Plugin::setQuarterResEdges(MixedResolution); GPU Gems 3 ch. 23, Cantlay,
// "High-Speed, Off-Screen Particles"): the pixels the upsample cannot get right are redrawn at
// full resolution. A fourth pass, between the quarter pass and the composite:
//   particles_edges   reads half depth + sceneDepth (+ the opacity map)   writes particles_edge_color
// Edge pixel: one whose bilinear footprint holds a low-res depth farther than kDepthThreshold *
// depth from its own (particles_mixed_edge.glsl, the depth-aware test; included by the mask
// shader and the composite, so both agree pixel for pixel), inside the screen rect. The mask is
// written as DEPTH into the z-buffer of particles_edge_color (full size, RGBA16F, created through
// FrameBuilder with depth = true): edge pixels get a depth every fragment passes, the rest one
// none passes; the particles are then drawn there with depth writes off, so the rasteriser drops
// the non-edge fragments before shading (the quarter-res programs: HardLinearDepth's in-shader
// test stands in for the full-res z-buffer test, soft and spherical are the full-res programs).
// The composite takes edge pixels from that target and gives every other pixel plain bilinear,
// which is what depth-aware gives a pixel whose footprint does not straddle an edge.
// Why not the stencil of sceneColor's framebuffer: no host we run has one (engine_stub's
// z-buffers are DEPTH24 or DEPTH32F, fx_host's too, the example host's DEPTH24), and the plugin
// may neither add one nor write the host's z-buffer. The target of our own works on any host, with
// no stencil state to save, at the cost of a full-size RGBA16F target + z-buffer and one more
// texture fetch in the composite.
//   Measured (tests/fx_host/MixedResTest.cpp, the scene above, standard and reversed-Z alike): on
//   the 2552 edge-band pixels mean 1.04/255 -> 0.38/255, max 29 -> 13 (the rest of that band is
//   not an edge by the footprint test and keeps the bilinear value); on the 376 pixels the redraw
//   changed 4.76/255 -> 0.28/255, max 29 -> 2 (full res blends every particle into RGBA8, the
//   redraw accumulates in RGBA16F and blends once); away from edges equal to depth-aware (max 0);
//   whole frame 46.9 -> 48.0 dB.
//   fxbench, one interleaved run per scenario (1280x1024, llvmpipe, reversed-Z; `fxbench --modes
//   soft,soft+quarter,soft+mixed --size 1280x1024 --frames 12 --rounds 2 --error-frames 3
//   [--scenario fill]`), frame p50 vs soft / particle fragments / vs soft: PSNR, max abs, edge %:
//     standard  soft 154.4 ms, 6.76 M; quarter 0.78x, 3.23 M, 52.0 dB, 154, 0.14 %;
//               mixed 1.09x, 4.38 M, 52.2 dB, 90, 0.03 %
//     fill      soft 848.3 ms, 48.9 M; quarter 0.40x, 14.3 M, 48.1 dB, 163, 0.15 %;
//               mixed 0.66x, 16.8 M, 48.2 dB, 84, 0.12 %
//   On llvmpipe the edge pass is not cheap (49 ms standard, 211 ms fill): a CPU rasteriser has
//   no hierarchical z, so each of the full-res particles' fragments is still rasterised and
//   depth-rejected (about 28 of the 49 ms), and the mask is a full-res pass over the rect like
//   the composite (about 21 ms). A GPU's early/hierarchical z rejects the masked fragments in
//   blocks, where the redraw costs about the edge pixels' share. What mixed leaves: depth steps
//   below kDepthThreshold (a wheel against the road a few per cent behind it) where the soft
//   fade still changes within a half-res texel.
//
// Fixed costs. The downsample, the half-res z-fill, the edge mask and the
// composite are drawn on ScreenTiles (16 px tiles a particle's bound touches, as runs) instead
// of one triangle over the rect, with billboards bounded by their view-plane square rather than
// a cube; and the composite is three builds (depth-aware, bilinear, mixed) instead of one with
// uniform branches, which llvmpipe ran all of (19 fetches a pixel instead of 9). Images are
// bit-identical (golden hashes of every quarter-res frame unchanged). fxbench standard, 1280x1024,
// llvmpipe, per-pass p50 (before: one run of the previous build; after: one run of this one):
//   covered pixels   rect 920 k  ->  tiles 680 k  (of 1311 k; the smoke changes 24 % = 315 k)
//   composite        22.1 ms -> 10.2 ms;  downsample 2.4 -> 1.9 ms
//   soft + quarter frame / soft frame   0.78 -> 0.63;  fill scenario 0.42 -> 0.39
// What remains is the half-res particle pass itself (32 ms against 82 ms at full res for a
// quarter of the fragments): smaller triangles fill more partial 4x4 blocks, and blending into
// RGBA16F is dearer than RGBA8 on a CPU rasteriser (RGBA8 measured 15 % faster, 52.0 -> 51.7 dB;
// not taken, the 8-bit accumulation costs precision where many puffs overlap).
#include <memory>
#include <string>
#include <vector>

#include "ParticleDraw.h"
#include "QuarterResPrograms.h"
#include "RendererConfig.h"
#include "ScreenTiles.h"
#include "fx/HostAdapter.h"
#include "fx/Types.h"

namespace fx {

class QuarterResPath {
public:
    static constexpr const char* kDepthTarget = "particles_half_depth";
    static constexpr const char* kColorTarget = "particles_half_color";
    static constexpr const char* kDownsamplePass = "particles_depth_downsample";
    static constexpr const char* kQuarterPass = "particles_quarter";
    static constexpr const char* kCompositePass = "particles_composite";
    /// Mixed resolution only: the full-res redraw of the edge pixels and its target.
    static constexpr const char* kEdgeTarget = "particles_edge_color";
    static constexpr const char* kEdgePass = "particles_edges";
    /// Relative depth difference above which a footprint counts as straddling an edge.
    static constexpr float kDepthThreshold = 0.1f;

    /// Half size, RG32F (min, max of each 2x2 block), nearest filtering.
    static TargetDesc depthTargetDesc();
    /// Half size, RGBA16F, linear filtering; with its own z-buffer when `withDepth` (the
    /// half-res z-test, reversed-Z hosts only).
    static TargetDesc colorTargetDesc(bool withDepth = false);
    /// Mixed resolution: full size, RGBA16F, nearest filtering, with its own z-buffer (the mask).
    static TargetDesc edgeTargetDesc();

    QuarterResPath(ParticleDraw& draw, SizeMismatchReport sizeMismatch);
    QuarterResPath(const QuarterResPath&) = delete;
    QuarterResPath& operator=(const QuarterResPath&) = delete;

    /// The running programs (QuarterResPrograms::build); a shader reload swaps in a new set and
    /// gets the old one back.
    QuarterResPrograms& programs() { return *programs_; }
    std::unique_ptr<QuarterResPrograms> swapPrograms(std::unique_ptr<QuarterResPrograms> next) {
        programs_.swap(next);
        return next;
    }
    /// The programs quarter res needs built (else the particles are drawn at full res).
    bool ok() const { return programs_ && programs_->ok(); }

    /// Declares the view's quarter-res passes (and the edge pass under mixed resolution, unless
    /// the bilinear upsample is asked for or the mask did not build); fills the view's rect and
    /// tiles.
    void declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& view);

private:
    // Pass bodies; each runs inside the caller's GlStateGuard and sets the state it needs. All
    // work inside the view's rect only (scissor, with a 2-texel border at half resolution): the
    // clears cover the rect, the full-screen work (downsample, half-res z-fill, edge mask,
    // composite) only its tiles, so the fixed costs follow the smoke's footprint.
    void downsampleDepth(PassContext& ctx, const ParticleView& v, Target sceneDepth, const SceneDepthDecode& decode,
                         Target halfDepth);
    /// Binds the half-res colour target and clears it (within the rect) to transparent black.
    /// With `halfDepth` (a reversed-Z view; halfColor made with a z-buffer, halfDepth downsampled):
    /// also fills that z-buffer with the farthest scene depth of each 2x2 block (halfDepth's
    /// green, fs_particles_half_z.glsl) and leaves the depth test on, GEQUAL without writes, so
    /// the half-res particles skip what is hidden behind all four pixels. True when that was done.
    bool beginQuarter(PassContext& ctx, const ParticleView& v, Target halfColor, Target halfDepth);
    /// Mixed resolution: binds the full-res edge target, clears its colour (within the rect) to
    /// transparent black and writes the edge mask into its z-buffer (fs_particles_edge_mask.glsl),
    /// then leaves the depth test on without writes, in the view's convention (LEQUAL, GEQUAL
    /// under reversed-Z), so particles drawn next pass it on edge pixels only.
    void beginEdges(PassContext& ctx, const ParticleView& v, Target edgeColor, Target halfDepth, Target sceneDepth,
                    const SceneDepthDecode& decode);
    /// `edgeColor` valid: mixed resolution (edge pixels from it, the rest bilinear).
    void composite(PassContext& ctx, const ParticleView& v, Target sceneColor, Target halfColor, Target halfDepth,
                   Target sceneDepth, const SceneDepthDecode& decode, Target edgeColor);

    ParticleDraw& draw_;
    SizeMismatchReport sizeMismatch_;
    std::unique_ptr<QuarterResPrograms> programs_ = std::make_unique<QuarterResPrograms>();
};

}  // namespace fx
