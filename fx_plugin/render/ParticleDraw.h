#pragma once
// The billboard particles' draw, shared by every path that draws them (full res and the half-res
// pass of quarter res): one view's batches into the bound target, each with its technique's
// program (lit or not, its contrast power's own build), blend mode, depth test and uniforms,
// trimmed polygons or full quads. It
// owns what those draws read but the programs (Renderers' ProgramCache): the atlas and its
// trimmed shapes, the colour ramps, the instance stream and the scene depth's sampler.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ColorRampTexture.h"
#include "DrawList.h"
#include "FrameSettings.h"
#include "GlStateGuard.h"
#include "InstanceStream.h"
#include "ProgramCache.h"
#include "ScreenTiles.h"
#include "SmokeAtlas.h"
#include "TileBins.h"
#include "fx/HostAdapter.h"

namespace fx {

/// One view's recorded draw, shared with the pass bodies of every path until the host has run
/// them.
struct ParticleView {
    ViewInfo view;
    DrawList list;
    FrameSettings settings;    ///< the frame's settings, read once when the view was declared
    bool reversedZ = false;    ///< view.depth is ReversedZ
    ScreenRect rect;           ///< quarter res: where the particles can be
    ScreenTiles tiles;         ///< quarter res: the same, as screen tiles
    /// Whether quarter res draws the view. Pending: chosen by the first of its passes to run
    /// (QuarterResPath::settle), where a host's frame graph draws a view quarter res may draw.
    enum class Quarter : uint8_t { No, Yes, Pending } quarter = Quarter::No;
    TileBins bins;             ///< the tiled path: the particles per tile (TiledPath.h)
    bool tiledSetUp = false;   ///< the tiled path: its first pass of this frame ran (TiledPath::kSetupPass)
    /// The view's last pass ran (the tiled path's particles_tiled, the one that may leave the list's
    /// gather pending): ParticleRenderer::settleLists drops a pending gather then, not writes it.
    bool drawn = false;
    Target opacity;            ///< the opacity map of this frame (invalid: unshadowed)
    glm::mat4 worldToShadow{1.0f};
    bool lit() const { return settings.light.on; }
};

/// What one pass hands the draw: its textures (0: none) and how its target is tested.
struct DrawInputs {
    uint32_t sceneDepth = 0;  ///< scene depth of the bound target's size (0 when no batch needs it)
    SceneDepthDecode depthDecode;  ///< how to read it (SceneDepthSource.h; default: linear)
    bool quarterRes = false;  ///< the quarter-res programs (HardLinearDepth for hard)
    /// The bound target's own z-buffer was filled (the half-res z-test, reversed-Z only): every
    /// batch is z-tested (GEQUAL).
    bool zTested = false;
    uint32_t opacity = 0;     ///< the opacity map (lit smoke)
    HostClip clip;  ///< drawing into sceneColor: the scissor its bindForDraw left (HostClip::current)
};

class ParticleDraw {
public:
    /// Texture units of the particle draws (all below GlStateGuard::kTextureUnits).
    static constexpr int kAtlasUnit = 0, kRampUnit = 1, kSceneDepthUnit = 2, kOpacityUnit = 3;

    /// Draws with the programs of `programs`, which must outlive this.
    explicit ParticleDraw(ProgramCache& programs) : programs_(&programs) {}
    /// The host's job system for the instance upload's copy (none: one thread).
    void setJobs(const Jobs& jobs) { jobs_ = jobs; }
    const Jobs& jobs() const { return jobs_; }

    /// Loads the atlas (inside a guard): false with "path: reason" in *error.
    bool loadAtlas(const std::string& dataDir, std::string* error) { return atlas_.load(dataDir, error); }
    /// Once the programs built: the stream, the sampler, the ramp texture and the shape tables.
    void create();

    /// Draws every batch of `view` into the bound target (inside the pass's GlStateGuard).
    void draw(const ParticleView& view, const DrawInputs& in);
    /// How far `view`'s billboards reach when drawn on its full-resolution target, or with
    /// `halfRes` on the quarter-res path's half-size one (screenRect's `reach`): their trimmed
    /// polygons' reach when they are drawn trimmed, else none (lodScale 0).
    BillboardReach billboardReach(const ParticleView& view, bool halfRes) const;

    /// The running program cache (ProgramCache.h: filled by prepare and reloads, never by a
    /// draw; a shader reload swaps its contents).
    ProgramCache& programs() { return *programs_; }
    const SmokeAtlas& atlas() const { return atlas_; }
    ColorRampTexture& ramp() { return ramp_; }
    InstanceStream& stream() { return stream_; }
    const InstanceStream& stream() const { return stream_; }
    /// The samplers draw() reads the atlas and the scene depth through (the tiled path's too).
    const ClampSampler& atlasSampler() const { return atlasSampler_; }
    const NearestSampler& depthSampler() const { return depthSampler_; }
    /// The billboards' trimmed polygons as vs_particles.glsl's uShapes takes them (empty: no table,
    /// quads are drawn), and its uLodScale for a target `height` pixels high under `proj`.
    const std::vector<glm::vec4>& shapeTable() const { return shapeTable_; }
    float lodScaleFor(const glm::mat4& proj, float height) const;

private:
    /// Sets the FX_LIT uniforms of `p` for `batch` (the program is in use).
    void setLightUniforms(const ParticleProgram& p, const DrawBatch& batch, const ParticleView& view,
                          uint32_t opacity) const;

    ProgramCache* programs_;
    Jobs jobs_;
    SmokeAtlas atlas_;
    ColorRampTexture ramp_;
    InstanceStream stream_;
    NearestSampler depthSampler_;        ///< the scene depth's unit, whatever sampling the host set
    /// The particles' atlas, billboards' and spheres': one mip level per read, the nearest (draw()
    /// says what that costs the picture).
    ClampSampler atlasSampler_{ClampSampler::Filter::LinearNearestMip};
    std::vector<glm::vec4> shapeTable_;  ///< atlas_.shapes().packed(), uploaded per draw
    std::vector<glm::vec4> discTable_;   ///< the same for spheres (TrimmedShapes::Clip::Disc)
    std::vector<glm::vec4> discInfo_;    ///< and their (inradius, area share)
    BillboardReach reach_;               ///< the billboards' reach table (its lodScale is the view's)
};

}  // namespace fx
