#pragma once
// What one view draws, recorded while passes are declared (no GL): the visible particles of every
// reaction packed into one instance array in draw order, one DrawBatch per reaction that has any,
// and whether any of them needs the scene depth. DrawListBuilder fills it from the pools:
//  - culling: each particle's bounding sphere (radius = half the quad diagonal, size / sqrt 2,
//    which also holds the spherical technique's sphere) against the view frustum;
//  - slice: only particles whose view distance lies in ViewInfo::slice (default: all);
//  - order: back to front (sim/ParticleSorter, over the particles left after culling) for
//    reactions that need it (ReactionRuntime::needsSorting: sorted alpha blending), pool order
//    otherwise (additive); with deferOrder the back-to-front sort is left out (DrawList::orderPending)
//    for the tiled path to do on the GPU (TileSort.h), or order() to do later, and with deferGather
//    the writing of the particles too (DrawList::gatherPending), for the tiled path's first pass to
//    do straight into its storage buffer, or settle() to do later;
//    reactions are drawn in reaction order (no sorting across reactions);
//  - technique: RenderOptions::techniqueOverride, else the reaction's render.technique;
//    batches whose technique is not in the caller's usable mask are left out (each renderer
//    passes the techniques the technique table gives it, TechniqueRow::drawnBy, less those
//    without a working program: each batch is drawn by one of them).
#include <cstdint>
#include <vector>

#include "InstanceStream.h"
#include "base/NoInitVector.h"
#include "base/ParallelFor.h"
#include "fx/Plugin.h"
#include "reactions/ReactionDesc.h"
#include "fx/Types.h"
#include "../sim/ParticlePool.h"
#include "../sim/ParticleSorter.h"

namespace fx {

/// One reaction's particles as the renderer takes them (Renderers collects one per runtime for each view).
struct ParticleBatch {
    const ParticlePool* pool = nullptr;
    const ReactionDesc* desc = nullptr;  ///< render settings and particle.colorRamp
    bool sortBackToFront = true;         ///< ReactionRuntime::needsSorting()
    float time = 0.0f;                   ///< the reaction's simulation clock (ReactionRuntime::time), s
};

/// One draw call: a reaction's visible particles and how to draw them.
struct DrawBatch {
    int first = 0;         ///< first instance in DrawList::instances
    int count = 0;
    int rampRow = 0;       ///< row in the colour-ramp texture (= index of the ParticleBatch)
    Technique technique = Technique::Soft;  ///< resolved: Hard, Soft, Spherical or Mega
    BlendMode blend = BlendMode::Alpha;
    float softScale = 2.0f;      ///< 1 / render.softness
    float contrastPower = 1.0f;
    float nearFade = 0.5f;
    LightingDesc lighting;       ///< the reaction's `lighting:` keys (lit when a scene light is set)
    bool backToFront = false;    ///< drawn back to front (ParticleBatch::sortBackToFront)
};

struct DrawList {
    NoInitVector<ParticleInstance> instances;
    std::vector<DrawBatch> batches;
    bool needsSceneDepth = false;  ///< a soft or spherical batch is visible
    /// Built with deferOrder: the batches drawn back to front hold their particles in pool order
    /// (culled), not yet sorted. DrawListBuilder::order sorts them; the tiled path can instead
    /// sort them on the GPU (TileSort.h). Every other consumer needs the order in place.
    bool orderPending = false;

    /// Built with deferGather: the particles are culled, counted and placed in the list (each
    /// batch's first and count are final) but not yet written: `instances` stays empty until
    /// settle() writes them there, and gatherInto() writes them anywhere else (the tiled path:
    /// straight into its mapped storage buffer, saving the list the copy on the way). Both read
    /// the pools the list was built from, unchanged since: the plugin settles every list a pass
    /// still holds before it steps, fires or reloads a reaction (Renderers::settleLists), so a
    /// pass draws the particles as they were declared.
    bool gatherPending() const { return !pending.empty(); }
    /// Writes the pending particles into `instances` (nothing where none are pending): the list
    /// build() without deferGather gives, bit for bit.
    void settle(const Jobs& jobs = Jobs());
    /// The pending particles into `to` (particleCount() of them), as settle() writes them.
    void gatherInto(ParticleInstance* to, const Jobs& jobs = Jobs()) const;

    void clear() {
        instances.clear();
        batches.clear();
        needsSceneDepth = false;
        orderPending = false;
        pending.clear();
        pendingKeep.clear();
        pendingPieceFirst.clear();
        pendingCount = 0;
    }
    int particleCount() const { return gatherPending() ? pendingCount : static_cast<int>(instances.size()); }

    /// A batch whose visible particles are not yet written (gatherPending): the pool's particles
    /// [0, alive) in the pieces build() culled them in (splitWork(alive)), each piece's answers in
    /// pendingKeep from keepAt on (per four particles, bits at the first, where `grouped`), its
    /// visible ones going to list position first + pendingPieceFirst[pieceAt + piece].
    struct PendingBatch {
        const ParticlePool* pool = nullptr;
        uint32_t alive = 0, first = 0, keepAt = 0, pieceAt = 0;
        bool grouped = false;
    };
    std::vector<PendingBatch> pending;
    NoInitVector<uint8_t> pendingKeep;
    std::vector<uint32_t> pendingPieceFirst;
    int pendingCount = 0;
};

/// The technique a reaction is drawn with under `override`.
Technique resolveTechnique(Technique override, Technique fromReaction);
inline uint32_t techniqueBit(Technique t) { return 1u << static_cast<uint32_t>(t); }
/// The camera's forward axis in world space (minus the third row of the view rotation): a
/// particle's sort depth is dot(p - eye, viewForward) on the CPU and on the GPU alike.
inline glm::vec3 viewForward(const ViewInfo& view) {
    return glm::vec3(-view.view[0][2], -view.view[1][2], -view.view[2][2]);
}

class DrawListBuilder {
public:
    /// Fills `out` for one view. `usableTechniques`: techniqueBit() mask of techniques whose
    /// programs built. Keeps its scratch between calls; after warm-up it allocates nothing.
    /// `jobs`: the host's job system for pools of tens of thousands of particles (culled, sorted
    /// and gathered in pieces); the list is the same bit for bit with or without it.
    /// `deferOrder`: leave the back-to-front sort out (DrawList::orderPending).
    /// `deferGather` (with deferOrder only): leave the writing of the particles out too
    /// (DrawList::gatherPending); the list is then only counted.
    void build(const ViewInfo& view, const ParticleBatch* batches, int batchCount,
               Technique techniqueOverride, uint32_t usableTechniques, DrawList* out,
               const Jobs& jobs = Jobs(), bool deferOrder = false, bool deferGather = false);
    /// Puts a deferred order in place: `list` as build() without deferOrder gives it, bit for
    /// bit (a pending gather settled first). Nothing where no order is pending. `view`: the view
    /// it was built for.
    void order(const ViewInfo& view, DrawList* list, const Jobs& jobs = Jobs());

private:
    ParticleSorter sorter_;                   // the batch being built's order
    NoInitVector<ParticleInstance> culled_;   // a sorted batch's visible particles, each piece's at its pool offset
    NoInitVector<uint8_t> keep_;              // an unsorted batch's answers per particle (per four: bits)
    NoInitVector<float> depth_;               // their depths along the view axis, likewise
    NoInitVector<float> packedDepth_;         // the depths without the gaps between pieces
    NoInitVector<uint32_t> packedAt_;         // where each of those lies in culled_
    std::vector<uint32_t> pieceDrawn_, pieceFirst_;  // per piece: visible particles, first packed slot
};

}  // namespace fx
