#pragma once
// Quarter-resolution particles (RenderOptions::quarterRes; the thesis's fourth row of Table 1):
// particles are drawn into a half-width x half-height RGBA8 target (premultiplied), then
// composited onto sceneColor. Three passes, each declared through FrameBuilder (declare()):
//   particles_depth_downsample  reads sceneDepth                   writes particles_half_depth
//   particles_quarter           reads particles_half_depth         writes particles_half_color
//   particles_composite         reads half colour + half depth + sceneDepth, writes sceneColor
// Whether quarter res draws the view at all (quarterResPays) may wait for these passes: then the
// first of them to run, or of the full-res pass the caller declares after them, chooses (settle)
// while the GPU runs what the host queued before, and the passes not chosen do nothing.
//
// Downsampled depth: MINIMUM (nearest) of each 2x2 block. With min, thin foreground geometry
// (poles, barrier tops, a car's roof line) survives in the low-res depth, so the half-res pass
// hides the smoke behind it; the cost is that a block straddling an edge holds no smoke for its
// background pixels, which the composite repairs by borrowing a neighbour. Max (farthest) would
// lose thin foreground geometry altogether and paint smoke over it, an error no upsample can
// undo because no low-res texel holds the right answer. (The block's max is kept too, in the
// green channel: the half-res z-test's depth under reversed-Z.)
//
// Upsample: depth-aware, after nearest-depth upsampling (Bavoil, NVIDIA "Opacity Mapping"
// 2011). Per full-res pixel, the 4 low-res texels of the bilinear footprint; if all their depths
// are within kDepthThreshold * depth of the pixel's own depth, bilinear. Otherwise (a depth
// edge) the bilinear weights of the texels within the threshold, renormalised, and when no texel
// is within it the one with the closest depth: taking the closest texel alone on every edge
// pixel turns edges that smoke merely crosses blocky. Plain bilinear stays selectable
// (RenderOptions::bilinearUpsample) to measure the effect (tests/fx_host/QuarterResTest.cpp
// measures both against the full-res frame; figures in docs/results.md).
//
// Fixed costs follow the smoke's footprint: the downsample, the half-res z-fill and the
// composite are drawn on ScreenTiles (16 px tiles a particle's bound touches, as runs) instead
// of one triangle over the view, with billboards bounded by their trimmed polygon's reach
// (BillboardReach) rather than a cube; and the composite is two builds (depth-aware, bilinear)
// instead of one with a uniform branch, which a CPU rasteriser runs both sides of. Its fetches:
// the bilinear colour through the half-res colour's linear sampler (one fetch, after which a
// pixel without smoke is discarded), the four low-res depths' nearest and farthest in two
// textureGathers (ARB_gpu_shader5), and the pixel's full-resolution depth only where those span
// more than the edge threshold (in fxbench's standard frame 3.9 % of the smoky pixels; the rest
// blend bilinearly, as the edge test would have had them); on a depth edge the kept texels' blend
// in two more filtered fetches, one per row. The downsample gathers its block too (four texelFetch each where the context has no
// ARB_texture_gather). The half-res colour is RGBA8 for
// billboards: blending there costs a GPU about a fifth less than RGBA16F for a few tenths of a dB
// (figures in docs/results.md); it gives up accumulation finer than 1/255 where many faint puffs
// overlap, and additive smoke brighter than 1 in an HDR host's scene (clamped at quarter res).
// A view with spherical particles keeps RGBA16F: their pass is bound by its arithmetic, not the
// blend, so 8 bits would save nothing and cost most of a dB.
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
    /// Relative depth difference above which a footprint counts as straddling an edge.
    static constexpr float kDepthThreshold = 0.1f;

    /// Half size, RG32F (min, max of each 2x2 block), nearest filtering.
    static TargetDesc depthTargetDesc();
    /// Half size, linear filtering, RGBA8 (RGBA16F with `spheres`: a spherical batch in the view);
    /// with its own z-buffer when `withDepth` (the half-res z-test, reversed-Z hosts only).
    static TargetDesc colorTargetDesc(bool withDepth = false, bool spheres = false);

    QuarterResPath(ParticleDraw& draw, SizeMismatchReport sizeMismatch);
    QuarterResPath(const QuarterResPath&) = delete;
    QuarterResPath& operator=(const QuarterResPath&) = delete;

    /// The passes' programs, taken from the running ProgramCache (QuarterResPrograms::bind, again
    /// after each shader reload); swapPrograms hands the set back (its stream buffer is deleted
    /// with it).
    QuarterResPrograms& programs() { return *programs_; }
    std::unique_ptr<QuarterResPrograms> swapPrograms(std::unique_ptr<QuarterResPrograms> next) {
        programs_.swap(next);
        return next;
    }
    /// The programs quarter res needs built (else the particles are drawn at full res).
    bool ok() const { return programs_ && programs_->ok(); }

    /// Declares the view's quarter-res passes inside the view's rect and tiles (ParticleView::rect,
    /// ::tiles: the caller's screenRect). Where the choice is pending (ParticleView::quarter), each
    /// pass settles it first and does nothing where full res was chosen.
    void declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& view);
    /// True where quarter res draws `view`. A pending choice is made here, once: what the host
    /// queued goes to the GPU (glFlush), so it runs while the CPU works out the view's rect and
    /// tiles (screenRect, on the host's threads) and weighs them (quarterResPays).
    bool settle(ParticleView& view);
    /// Works out `view`'s rect and tiles (ParticleView::rect, ::tiles) for its quarter-res passes.
    void bound(ParticleView& view) const;

    /// Whether a host's frame graph may leave the choice to the passes (settle). On unless
    /// CUBEFX_QUARTER_CHOICE_IN_PASS=0 or setChoiceInPass(false): then every view chooses while
    /// declared, as before 2026-11-28, for A/B runs on a GPU.
    static bool choiceInPass();
    static void setChoiceInPass(bool on);
    static void resetChoiceInPass();           ///< back to the environment's, or on
    static const char* choiceInPassProblem();  ///< what was wrong with CUBEFX_QUARTER_CHOICE_IN_PASS, or null

private:
    // Pass bodies; each runs inside the caller's GlStateGuard and sets the state it needs. All
    // work inside the view's rect only (scissor, with a 2-texel border at half resolution): the
    // clears cover the rect, the full-screen work (downsample, half-res z-fill, composite) only
    // its tiles, so the fixed costs follow the smoke's footprint.
    void downsampleDepth(PassContext& ctx, const ParticleView& v, Target sceneDepth, const SceneDepthDecode& decode,
                         Target halfDepth);
    /// Binds the half-res colour target and clears it (within the rect) to transparent black.
    /// With `halfDepth` (a reversed-Z view; halfColor made with a z-buffer, halfDepth downsampled):
    /// also fills that z-buffer with the farthest scene depth of each 2x2 block (halfDepth's
    /// green, fs_particles_half_z.glsl) and leaves the depth test on, GEQUAL without writes, so
    /// the half-res particles skip what is hidden behind all four pixels. True when that was done.
    bool beginQuarter(PassContext& ctx, const ParticleView& v, Target halfColor, Target halfDepth);
    /// Blends the half-res colour onto sceneColor, depth-aware or bilinear (the view's options).
    void composite(PassContext& ctx, const ParticleView& v, Target sceneColor, Target halfColor, Target halfDepth,
                   Target sceneDepth, const SceneDepthDecode& decode);

    ParticleDraw& draw_;
    SizeMismatchReport sizeMismatch_;
    std::unique_ptr<QuarterResPrograms> programs_ = std::make_unique<QuarterResPrograms>();
};

}  // namespace fx
