#pragma once
// The smoke's opacity seen from the sun (lit smoke's self-shadowing; API 1.2 SmokeShadow).
//
// Choice: an opacity shadow map with four slices in one RGBA16F target (Kim and Neumann's
// opacity shadow maps, with the slices as colour channels) rather than half-angle slicing.
// Half-angle slicing sorts the particles along the half vector and alternates between the eye
// buffer and a light buffer once per slice: a pass pair per slice inside the particle draw,
// which cannot share the soft, spherical and quarter-res passes this renderer already has and
// multiplies their fixed costs. The opacity map is one extra draw of the shadow casters into
// a target of at most 128 x 128 (sizeFor: smaller for small views), independent of the
// screen's size above that, that every technique samples once per vertex, and the host samples the same texture to darken the ground under the cloud. (Smoke
// shadows are soft: 128 texels across a 10 m cloud are 8 cm; 256 cost four times the fill for
// no visible difference.)
// Four slices resolve a burnout cloud's near and far side; smoke within one slice shadows
// itself linearly (the particles are spread over their quarter-slice), so nothing pops.
//
// The light's box is fitted to the casters every frame, snapped so it does not shimmer: its
// side is rounded up to a power of 2^(1/4), its centre to whole texels of a world-fixed grid,
// and its depth range likewise, so a cloud that drifts moves its shadow by whole texels.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "DrawList.h"
#include "InstanceStream.h"
#include "LightState.h"
#include "ProgramCache.h"

namespace fx {

class SmokeOpacityMap {
public:
    static constexpr const char* kPass = "smoke_opacity";
    static constexpr const char* kTarget = "smoke_opacity";
    static constexpr int kMaxSize = 128;
    static constexpr int kMinSize = 32;
    /// The map's side for a view: a fifth of its larger side, as a power of two in
    /// [kMinSize, kMaxSize] (128 from 640 pixels up; a 160 x 128 mirror gets 32). A shadow finer
    /// than the view can show costs fill for nothing: at 160 x 128 the 128^2 map cost more than
    /// the lit particles themselves (cube_game, 1000 frames with the mirror: 32.5 s lit against
    /// 19.1 s unlit before this).
    static int sizeFor(int viewWidth, int viewHeight);

    SmokeOpacityMap() = default;
    SmokeOpacityMap(const SmokeOpacityMap&) = delete;
    SmokeOpacityMap& operator=(const SmokeOpacityMap&) = delete;

    /// Takes the opacity program of `programs` (ProgramCache::OpacityMap; 0 where it failed: lit
    /// smoke then goes without self-shadowing) and looks its uniforms up. Compiles nothing; the
    /// program stays the cache's, which must outlive its use (until the next bind).
    void bind(const ProgramCache& programs);
    bool ok() const { return program_ != 0; }

    struct Range {
        int first = 0, count = 0, batch = 0;
    };
    /// What one record() collected: the casters and the light's box. Each declared map keeps its
    /// own until its pass has run, so the maps of several views declared before any of them runs
    /// (a host's frame graph, then renderView's own frame) each draw what was recorded for them.
    struct Casters {
        std::vector<ParticleInstance> instances;
        std::vector<Range> ranges;
        glm::mat4 lightView{1.0f}, lightProj{1.0f}, worldToShadow{1.0f};
        glm::vec2 depthRange{0.0f, 1.0f};
        float side = 0.0f;
    };

    /// Collects the shadow casters (lit, casts_shadow, not additive) of `batches` and fits the
    /// light's box to them, into `*out` (its storage reused). False when there is none (then no
    /// pass is needed). No GL. `size`: the map's side (sizeFor), for snapping the box to its texels.
    bool record(const LightState& light, const ParticleBatch* batches, int batchCount, int size, Casters* out);
    /// The same into the map's own record (what worldToShadow(), side() and casterCount() read).
    bool record(const LightState& light, const ParticleBatch* batches, int batchCount, int size = kMaxSize) {
        return record(light, batches, batchCount, size, &last_);
    }
    /// World position -> (u, v, light depth, 1) of the last record(): what SmokeShadow hands out.
    const glm::mat4& worldToShadow() const { return last_.worldToShadow; }
    /// Side of the light's box in metres (for tests and the docs).
    float side() const { return last_.side; }
    int casterCount() const { return int(last_.instances.size()); }

    /// Draws `casters` into the bound size x size RGBA16F target (cleared here). Inside a
    /// GlStateGuard; `atlas` and `ramp` are textures, `rampRows` the ramp's row v per batch index.
    void draw(const Casters& casters, uint32_t atlas, uint32_t ramp, const std::vector<float>& rampRows);
    /// The same with the map's own record.
    void draw(uint32_t atlas, uint32_t ramp, const std::vector<float>& rampRows) {
        draw(last_, atlas, ramp, rampRows);
    }

private:
    uint32_t program_ = 0;
    int locView_ = -1, locProj_ = -1, locRampRow_ = -1, locAtlas_ = -1, locRamp_ = -1, locDepthRange_ = -1,
        locTrimmed_ = -1, locNear_ = -1;
    InstanceStream stream_;
    Casters last_;
};

}  // namespace fx
