#pragma once
// Where a view's particles can be on screen (no GL but the scissor): the rect and the 16 px tiles
// their projected footprints touch. The quarter-res passes (QuarterResPath.h) and the
// mega-particles (MegaRenderer.h) keep their fixed full-screen costs inside them, and the
// immediate path reads the scene depth only there.
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "InstanceStream.h"
#include "TrimmedShapes.h"
#include "fx/Types.h"
#include "base/ParallelFor.h"

namespace fx {

/// The part of the view the particles can touch, in full-resolution pixels ([x0, x1) x
/// [y0, y1), GL's bottom-up rows); `whole` when it is the whole view (a particle reaches the
/// near plane, or the bound covers it anyway).
struct ScreenRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool whole = true;
    /// The pixels of every particle's bound (each clipped to the view) added up: an upper bound
    /// of the fragments a full-resolution draw rasterises, overdraw included.
    double footprintPixels = 0.0;
};

/// Finer than the rect: the screen tiles (kTileSize pixels square) that some particle's bound,
/// grown by kTileBorder pixels, touches, as horizontal runs. The downsample, the half-res
/// z-fill, the edge mask and the composite draw these runs instead of one triangle over the
/// rect, so their per-pixel cost follows the smoke's footprint: in fxbench's standard scene
/// the rect spans about 70 % of the view while the smoke covers about 24 %.
/// The border: the composite's bilinear footprint reaches 2 pixels, the half-res texels it reads
/// hold depth from 2 more; 6 keeps every pixel whose result can differ from "no smoke" inside.
struct ScreenTiles {
    static constexpr int kTileSize = 16;
    static constexpr int kTileBorder = 6;
    std::vector<float> vertices;  ///< x, y in full-resolution pixels, 6 per run (2 triangles)
    /// Scratch (kept for its capacity): per particle +-1 at the corners of its tile range, summed
    /// into coverage once per frame, so a large particle costs no more than a small one.
    std::vector<int32_t> grid;
    std::vector<int32_t> pieceGrids;  ///< scratch: the grids of the second and later pieces (ParallelFor.h)
    /// `grid` is all zero: the last bound zeroed the tiles its particles reached after summing
    /// them, so this one need not clear all of it (8,349 cells at 1080p, however small the smoke).
    bool gridClean = false;
    int64_t pixels = 0;           ///< pixels the runs cover
    int viewWidth = 0, viewHeight = 0;
    int runs() const { return int(vertices.size() / 12); }
};

/// What a particle's footprint is bounded by. Box: the view-space cube of half-size 0.71 size
/// around its centre (holds a rotated billboard's corners and a sphere of diameter size,
/// which a spherical particle's quad at the sphere's front covers). Billboard: the square of
/// half-size 0.71 size in the view plane through the centre, exactly where vs_particles.glsl
/// puts a billboard's corners; much tighter for large particles near the camera.
enum class Footprint { Box, Billboard };

/// How far a trimmed billboard reaches from its centre, in units of its size, by atlas frame and
/// LOD bucket (TrimmedShapes::reach / 2): a Footprint::Billboard bound from it is the polygon the
/// vertex shader draws (0.50-0.67 of the size with the repo's atlas) instead of the quad's corners
/// (0.71). The shader (vs_particles.glsl: shapeVertex) takes bucket ceil(log2(t) + 0.5), t the
/// texels per pixel of the target it draws into, lodScale * depth / size (the centre's depth, at
/// least the near plane). Each entry holds the largest reach of that bucket and its two
/// neighbours: where t lies on a bucket's edge, the GPU's rounding of it may pick either side.
struct BillboardReach {
    static constexpr int kEntries = TrimmedShapes::kMaxBuckets;  ///< per row
    static constexpr int kRows = TrimmedShapes::kFrames + 1;    ///< the frames', then any frame's
    /// Texels per pixel = lodScale * depth / size on the target the bound is for (ParticleDraw's
    /// uLodScale: full or half resolution); 0: no table, every billboard reaches 0.71 of its size.
    float lodScale = 0.0f;
    int buckets = 0;
    std::array<float, kRows * kEntries> table{};

    /// The table of `shapes` (empty shapes: lodScale stays 0).
    static BillboardReach of(const TrimmedShapes& shapes, float lodScale);
    /// The reach of a particle of atlas frame `frame` (the shader's clamp(int(frame + 0.5), 0, 3);
    /// out of range or not a number: the largest of any frame) at `texelsPerPixel`.
    float at(float frame, float texelsPerPixel) const;
};

inline float BillboardReach::at(float frame, float texelsPerPixel) const {
    const float f = frame + 0.5f;
    const int row = f >= 0.0f && f < float(TrimmedShapes::kFrames) ? int(f) : TrimmedShapes::kFrames;
    // ceil(log2 t + 0.5): t = m 2^e with m in [1, 2) gives e + 1, or e + 2 where m > sqrt(2)
    // (0x3504F3 is the mantissa of sqrt(2), rounded down). Not a number or infinite: the last.
    uint32_t bits;
    std::memcpy(&bits, &texelsPerPixel, sizeof bits);
    const int e = int((bits >> 23) & 0xFFu) - 127;
    const int bucket = e + 1 + ((bits & 0x7FFFFFu) > 0x3504F3u ? 1 : 0);
    return table[size_t(row * kEntries + std::min(std::max(bucket, 0), buckets - 1))];
}

/// Conservative bound of `instances` on screen, each particle's footprint projected. Empty
/// rect (x0 == x1) when none is in front of the camera (one wholly behind the near plane is
/// clipped away and counts for nothing); the whole view when one straddles the near plane or
/// has a non-finite position or size. With `tiles`, also their tile runs (one run over the whole
/// view for a whole-view rect, none for an empty one); the vectors keep their capacity, so a
/// steady frame allocates nothing.
/// `jobs`: the host's job system; the particles are bounded in pieces fixed by `count`, and the
/// result is the same bit for bit however they run.
/// `reach`: for Footprint::Billboard under a perspective projection, the rect and the tiles bound
/// each particle's trimmed polygon instead of its quad (BillboardReach); footprintPixels still
/// counts the quads' boxes (the overdraw estimate quarterResPays was set for).
ScreenRect screenRect(const ViewInfo& view, const ParticleInstance* instances, int count,
                      ScreenTiles* tiles = nullptr, Footprint footprint = Footprint::Box,
                      const Jobs& jobs = Jobs(), const BillboardReach* reach = nullptr);

/// Whether drawing this view's particles at quarter resolution costs less than drawing them at
/// full resolution. Quarter res trades the particles' fragments (three in four saved) for fixed
/// work over the tiles (the depth downsample and the composite, each a full-screen-like pass
/// there); it pays only where the smoke overlaps itself enough. The rule compares the particles'
/// summed bounds with the tiles' pixels: quarter res when that overdraw estimate reaches
/// kQuarterResMinOverdraw. The estimate counts each particle's screen box (about four times the
/// fragments a trimmed billboard rasterises), so 16 means about four layers of smoke; the figures
/// behind it are in docs/results.md. An unbounded footprint (a particle at the near plane) always
/// takes quarter res.
constexpr double kQuarterResMinOverdraw = 16.0;
bool quarterResPays(const ScreenRect& rect, const ScreenTiles& tiles);

/// Scissor to `rect` on a target of w x h whose pixels are the view's times `scale` (0.5: half
/// resolution), grown by `border` texels; no scissor for a whole-view rect.
void scissorTo(const ScreenRect& rect, float scale, int border, int w, int h);

/// The scissor the host's PassContext::bindForDraw(sceneColor) left (renderView: the one the host
/// had enabled at the call): read right after binding, before plainDrawState() turns it off.
struct HostClip {
    bool on = false;
    int box[4] = {0, 0, 0, 0};
    static HostClip current();
    /// Turns the scissor on at the box again when `on` (after plainDrawState turned it off).
    void apply() const;
};

/// Scissor to `rect` (grown by `border` pixels) of the view, which lies at (view.x, view.y) of
/// sceneColor, inside `clip` when it is on. A whole-view rect without a host clip: no scissor,
/// as scissorTo (the viewport bounds the draws).
void scissorToView(const ScreenRect& rect, int border, const ViewInfo& view, const HostClip& clip);

}  // namespace fx
