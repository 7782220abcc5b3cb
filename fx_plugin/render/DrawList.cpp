#include "DrawList.h"

#include <cmath>

#include "ViewFrustum.h"
#include "reactions/TechniqueTable.h"

namespace fx {

Technique resolveTechnique(Technique override, Technique fromReaction) {
    const Technique t = override != Technique::FromReaction ? override : fromReaction;
    return t == Technique::FromReaction ? Technique::Soft : t;
}

void DrawListBuilder::build(const ViewInfo& view, const ParticleBatch* batches, int batchCount,
                            Technique techniqueOverride, uint32_t usableTechniques,
                            DrawList* out) {
    out->clear();
    if (batchCount <= 0) return;
    const ViewFrustum frustum(view.view, view.proj, view.nearPlane, view.farPlane);
    // Camera forward in world space: minus the third row of the view rotation.
    const glm::vec3 forward(-view.view[0][2], -view.view[1][2], -view.view[2][2]);
    constexpr float kHalfDiagonal = 0.70710678f;
    // The distance slice (ViewInfo::slice): the centre's distance along the view axis, -z_view,
    // which orders particles as the back-to-front sort does; a particle lies wholly in one slice.
    const bool sliced = !view.slice.everything();
    const glm::vec4 viewZRow(view.view[0][2], view.view[1][2], view.view[2][2], view.view[3][2]);
    auto viewDistance = [&](float px, float py, float pz) {
        return -(viewZRow.x * px + viewZRow.y * py + viewZRow.z * pz + viewZRow.w);
    };

    for (int b = 0; b < batchCount; ++b) {
        const ParticleBatch& in = batches[b];
        if (!in.pool || !in.desc || in.pool->alive() == 0) continue;
        const RenderDesc& render = in.desc->render;
        const Technique technique = resolveTechnique(techniqueOverride, render.technique);
        if (!(usableTechniques & techniqueBit(technique))) continue;

        const ParticlePool& pool = *in.pool;
        const float* x = pool.posX();
        const float* y = pool.posY();
        const float* z = pool.posZ();
        const float* size = pool.size();
        const float* life = pool.life();
        const float* rotation = pool.rotation();
        const float* fade = pool.fade();
        const uint8_t* frame = pool.frame();

        // Cull first, in pool order (each stream read front to back), then sort what is drawn:
        // sorting the whole pool and gathering through its order read every stream at random.
        // The radix sort is stable, so the order is the one sorting the pool would give.
        DrawBatch batch;
        batch.first = static_cast<int>(out->instances.size());
        const bool sort = in.sortBackToFront;
        std::vector<ParticleInstance>& drawn = sort ? culled_ : out->instances;
        if (sort) {
            // Sized for the whole pool once, as the sorter is: a frame that sees more of it than
            // any before does not allocate.
            culled_.clear();
            depth_.clear();
            culled_.reserve(size_t(pool.capacity()));
            depth_.reserve(size_t(pool.capacity()));
            sorter_.reserve(pool.capacity());
        }
        const int alive = pool.alive();
        for (int i = 0; i < alive; ++i) {
            if (!(size[i] > 0.0f) || !(fade[i] > 0.0f)) continue;  // also drops NaN
            if (!frustum.intersectsSphere(glm::vec3(x[i], y[i], z[i]), size[i] * kHalfDiagonal)) {
                continue;
            }
            if (sliced && !view.slice.contains(viewDistance(x[i], y[i], z[i]))) continue;
            ParticleInstance p;
            p.x = x[i];
            p.y = y[i];
            p.z = z[i];
            p.size = size[i];
            p.life = life[i];
            p.rotation = rotation[i];
            p.fade = fade[i] < 1.0f ? fade[i] : 1.0f;
            p.frame = float(frame[i] & 3u);
            drawn.push_back(p);
            if (sort) {
                depth_.push_back((x[i] - view.eye.x) * forward.x + (y[i] - view.eye.y) * forward.y +
                                 (z[i] - view.eye.z) * forward.z);
            }
        }
        if (sort) {
            const ParticleSorter::Order order = sorter_.sortDescending(depth_.data(), int(depth_.size()));
            for (int k = 0; k < order.count; ++k) out->instances.push_back(culled_[order.indices[k]]);
        }
        batch.count = static_cast<int>(out->instances.size()) - batch.first;
        if (batch.count == 0) continue;
        batch.rampRow = b;
        batch.technique = technique;
        batch.blend = render.blend;
        batch.softScale = 1.0f / std::fmax(render.softness, 1e-6f);  // the loader allows [1e-6, 1e6] m
        batch.contrastPower = render.contrastPower;
        batch.nearFade = render.nearFade;
        batch.lighting = in.desc->lighting;
        out->batches.push_back(batch);
        if (techniqueRow(technique, false).needsSceneDepth) out->needsSceneDepth = true;
    }
}

}  // namespace fx
