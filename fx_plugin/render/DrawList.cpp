#include "DrawList.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "ViewFrustum.h"
#include "reactions/TechniqueTable.h"

namespace fx {
namespace {

// Particles per piece of the cull and the gather: enough that handing a piece to another thread
// costs far less than the piece (about 10 ns a particle four at a time: 20-40 us a piece, against
// a few us to hand it over), few enough that a view of 16,000 particles is seven pieces, not one
// (bench_draw BM_DrawListBuildJobs/16000/2/1: 0.73 x the time of 8,192-particle pieces on two threads).
constexpr size_t kCullGrain = 2048;

// A pool's streams, as the cull and the gather read them.
struct Streams {
    const float *x, *y, *z, *size, *life, *rotation, *fade;
    const uint8_t* frame;
    explicit Streams(const ParticlePool& p)
        : x(p.posX()), y(p.posY()), z(p.posZ()), size(p.size()), life(p.life()), rotation(p.rotation()),
          fade(p.fade()), frame(p.frame()) {}
};

// Particle i's instance.
inline void writeOne(const Streams& s, size_t i, ParticleInstance* to) {
    ParticleInstance& p = *to;
    p.x = s.x[i];
    p.y = s.y[i];
    p.z = s.z[i];
    p.size = s.size[i];
    p.life = s.life[i];
    p.rotation = s.rotation[i];
    p.fade = s.fade[i] < 1.0f ? s.fade[i] : 1.0f;
    p.frame = float(s.frame[i] & 3u);
}

#if FX_SSE2
// The instances of those of particles i .. i + 3 whose bits `keep` has, to `to` one after
// another, each as two vectors (the same values as writeOne); returns how many.
inline int writeFour(const Streams& s, size_t i, int keep, ParticleInstance* to) {
    uint32_t frames4;
    std::memcpy(&frames4, s.frame + i, 4);
    const __m128i bytes = _mm_cvtsi32_si128(int(frames4));
    const __m128i frameInts =
        _mm_and_si128(_mm_unpacklo_epi16(_mm_unpacklo_epi8(bytes, _mm_setzero_si128()), _mm_setzero_si128()),
                      _mm_set1_epi32(3));
    __m128 a0 = _mm_loadu_ps(s.x + i), a1 = _mm_loadu_ps(s.y + i), a2 = _mm_loadu_ps(s.z + i),
           a3 = _mm_loadu_ps(s.size + i);
    __m128 b0 = _mm_loadu_ps(s.life + i), b1 = _mm_loadu_ps(s.rotation + i),
           b2 = _mm_min_ps(_mm_loadu_ps(s.fade + i), _mm_set1_ps(1.0f)), b3 = _mm_cvtepi32_ps(frameInts);
    _MM_TRANSPOSE4_PS(a0, a1, a2, a3);  // x, y, z, size of each
    _MM_TRANSPOSE4_PS(b0, b1, b2, b3);  // life, rotation, fade, frame of each
    const __m128 firstHalf[4] = {a0, a1, a2, a3}, secondHalf[4] = {b0, b1, b2, b3};
    int k = 0;
    for (int lane = 0; lane < 4; ++lane) {
        if (!(keep >> lane & 1)) continue;
        _mm_storeu_ps(&to[k].x, firstHalf[lane]);
        _mm_storeu_ps(&to[k].life, secondHalf[lane]);
        ++k;
    }
    return k;
}
#endif

// The visible particles of [i, e) as a cull answered them in `keep` (four to a byte, as bits at
// the first, where `grouped`; else a byte each), to `to` one after another.
void gatherKept(const Streams& s, size_t i, size_t e, [[maybe_unused]] bool grouped, const uint8_t* keep,
                ParticleInstance* to) {
    size_t k = 0;
#if FX_SSE2
    if (grouped) {
        for (; i + 4 <= e; i += 4) {
            if (keep[i]) k += size_t(writeFour(s, i, keep[i], to + k));
        }
    }
#endif
    for (; i < e; ++i) {
        if (keep[i]) writeOne(s, i, to + k++);
    }
}

}  // namespace

void DrawList::gatherInto(ParticleInstance* to, const Jobs& jobs) const {
    for (const PendingBatch& b : pending) {
        const Streams streams(*b.pool);
        const Pieces pieces = splitWork(b.alive, kCullGrain, HostAdapter::kMaxTasks);
        jobs.run(pieces, [&](uint32_t piece) {
            gatherKept(streams, pieces.begin(piece), pieces.end(piece), b.grouped, pendingKeep.data() + b.keepAt,
                       to + b.first + pendingPieceFirst[b.pieceAt + piece]);
        });
    }
}

void DrawList::settle(const Jobs& jobs) {
    if (!gatherPending()) return;
    instances.resize(size_t(pendingCount));
    gatherInto(instances.data(), jobs);
    pending.clear();
    pendingCount = 0;
}

Technique resolveTechnique(Technique override, Technique fromReaction) {
    const Technique t = override != Technique::FromReaction ? override : fromReaction;
    return t == Technique::FromReaction ? Technique::Soft : t;
}

void DrawListBuilder::build(const ViewInfo& view, const ParticleBatch* batches, int batchCount,
                            Technique techniqueOverride, uint32_t usableTechniques,
                            DrawList* out, const Jobs& jobs, bool deferOrder, bool deferGather) {
    out->clear();
    if (batchCount <= 0) return;
    const ViewFrustum frustum(view.view, view.proj, view.nearPlane, view.farPlane);
    const glm::vec3 forward = viewForward(view);
    constexpr float kHalfDiagonal = 0.70710678f;
    // The distance slice (ViewInfo::slice): the centre's distance along the view axis, -z_view,
    // which orders particles as the back-to-front sort does; a particle lies wholly in one slice.
    const bool sliced = !view.slice.everything();
    [[maybe_unused]] const bool lanes = fourLanes();
    const glm::vec4 viewZRow(view.view[0][2], view.view[1][2], view.view[2][2], view.view[3][2]);
    auto viewDistance = [&](float px, float py, float pz) {
        return -(viewZRow.x * px + viewZRow.y * py + viewZRow.z * pz + viewZRow.w);
    };
    int listed = 0;  // the list's particles so far (written, or pending)

    for (int b = 0; b < batchCount; ++b) {
        const ParticleBatch& in = batches[b];
        if (!in.pool || !in.desc || in.pool->alive() == 0) continue;
        const RenderDesc& render = in.desc->render;
        const Technique technique = resolveTechnique(techniqueOverride, render.technique);
        if (!(usableTechniques & techniqueBit(technique))) continue;

        const ParticlePool& pool = *in.pool;
        const Streams streams(pool);

        // Cull first, in pool order (each stream read front to back), then sort what is drawn:
        // sorting the whole pool and gathering through its order read every stream at random.
        // The radix sort is stable, so the order is the one sorting the pool would give. Each
        // piece of the pool writes its visible particles at its own offset in culled_ (no piece
        // waits for another); the pieces' counts then place them in the list, in pool order. A
        // batch drawn unsorted (or whose order the GPU works out) goes into the list directly:
        // each piece tests its particles first, then writes the visible ones at its place there
        // (bench_draw BM_DrawListBuildJobs/N/T/1: the copy through culled_ was a third of it),
        // or, with deferGather, leaves that to whoever takes the list (DrawList::gatherPending).
        DrawBatch batch;
        batch.first = listed;
        const bool sort = in.sortBackToFront && !deferOrder;
        const bool pend = deferOrder && deferGather;
        const int alive = pool.alive();
        // Sized for the whole pool once: a frame that sees more of it than any before does not
        // allocate.
        const size_t capacity = size_t(std::max(pool.capacity(), alive));
        if (culled_.size() < capacity) {
            culled_.resize(capacity);
            depth_.resize(capacity);
            packedDepth_.resize(capacity);
            packedAt_.resize(capacity);
            sorter_.reserve(int(capacity));
        }
        const Pieces pieces = splitWork(size_t(alive), kCullGrain, HostAdapter::kMaxTasks);
        pieceDrawn_.assign(pieces.count, 0u);
        pieceFirst_.assign(pieces.count, 0u);
        const bool grouped = FX_SSE2 && !sliced && lanes;
        // One piece of the pool: tests each particle, keeps the answers in keepOut (where given;
        // four to a byte where `grouped`: gatherKept reads them) and writes each visible
        // particle's instance to `to` (and its depth to `depthTo`) one after another. Returns how
        // many are visible.
        auto cullPiece = [&](uint32_t piece, uint8_t* keepOut, ParticleInstance* to, float* depthTo) {
            // The streams as locals: the instances' stores (__m128, which may alias anything)
            // would otherwise have the pointers read from the closure again every four particles.
            const float *const xs = streams.x, *const ys = streams.y, *const zs = streams.z,
                        *const sizes = streams.size, *const fades = streams.fade;
            size_t k = 0, i = pieces.begin(piece);
            const size_t e = pieces.end(piece);
#if FX_SSE2
            // Four particles a lane each (an unsliced view): the tests and the instances in
            // registers, each visible one stored as two vectors; the same list as the loop below
            // (ViewFrustum::intersectsSpheres4, DrawListOrderTest).
            if (grouped) {
                const __m128 zero = _mm_setzero_ps(), halfDiagonal = _mm_set1_ps(kHalfDiagonal);
                const __m128 eye[3] = {_mm_set1_ps(view.eye.x), _mm_set1_ps(view.eye.y), _mm_set1_ps(view.eye.z)};
                const __m128 ahead[3] = {_mm_set1_ps(forward.x), _mm_set1_ps(forward.y), _mm_set1_ps(forward.z)};
                static constexpr uint8_t kBits[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
                for (; i + 4 <= e; i += 4) {
                    int keep = _mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(_mm_loadu_ps(sizes + i), zero),
                                                          _mm_cmpgt_ps(_mm_loadu_ps(fades + i), zero)));
                    if (keep) {
                        keep &= frustum.intersectsSpheres4(_mm_loadu_ps(xs + i), _mm_loadu_ps(ys + i), _mm_loadu_ps(zs + i),
                                                           _mm_mul_ps(_mm_loadu_ps(sizes + i), halfDiagonal));
                    }
                    if (keepOut) keepOut[i] = uint8_t(keep);
                    if (!keep) continue;
                    if (!to) {
                        k += kBits[keep];
                        continue;
                    }
                    if (depthTo) {
                        // ((x - eye.x) forward.x + (y - eye.y) forward.y) + (z - eye.z) forward.z
                        const __m128 d = _mm_add_ps(
                            _mm_add_ps(_mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(xs + i), eye[0]), ahead[0]),
                                       _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(ys + i), eye[1]), ahead[1])),
                            _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(zs + i), eye[2]), ahead[2]));
                        alignas(16) float depth4[4];
                        _mm_store_ps(depth4, d);
                        size_t at = k;
                        for (int lane = 0; lane < 4; ++lane) {
                            if (keep >> lane & 1) depthTo[at++] = depth4[lane];
                        }
                    }
                    k += size_t(writeFour(streams, i, keep, to + k));
                }
            }
#endif
            for (; i < e; ++i) {
                const bool visible =
                    sizes[i] > 0.0f && fades[i] > 0.0f &&  // also drops NaN
                    frustum.intersectsSphere(glm::vec3(xs[i], ys[i], zs[i]), sizes[i] * kHalfDiagonal) &&
                    (!sliced || view.slice.contains(viewDistance(xs[i], ys[i], zs[i])));
                if (keepOut) keepOut[i] = uint8_t(visible);
                if (!visible) continue;
                if (to) {
                    writeOne(streams, i, to + k);
                    if (depthTo) {
                        depthTo[k] = (xs[i] - view.eye.x) * forward.x + (ys[i] - view.eye.y) * forward.y +
                                     (zs[i] - view.eye.z) * forward.z;
                    }
                }
                ++k;
            }
            return uint32_t(k);
        };
        ParticleInstance* at = nullptr;  // a sorted batch's place in the list, where its gather writes
        uint32_t drawnCount = 0;
        auto place = [&]() {
            for (uint32_t s = 0; s < pieces.count; ++s) {
                pieceFirst_[s] = drawnCount;
                drawnCount += pieceDrawn_[s];
            }
        };
        if (sort) {
            // Each piece's visible particles at its pool offset in culled_, with their depths.
            jobs.run(pieces, [&](uint32_t piece) {
                const size_t from = pieces.begin(piece);
                pieceDrawn_[piece] = cullPiece(piece, nullptr, culled_.data() + from, depth_.data() + from);
            });
            place();
            out->instances.resize(size_t(listed) + drawnCount);
            at = out->instances.data() + listed;
        } else if (pieces.count <= 1 && !pend) {
            // One piece: straight into the list, sized for the whole pool and cut to what is
            // visible (a NoInitVector: neither writes the elements).
            out->instances.resize(size_t(listed) + size_t(alive));
            if (pieces.count == 1) pieceDrawn_[0] = cullPiece(0, nullptr, out->instances.data() + listed, nullptr);
            place();
            out->instances.resize(size_t(listed) + drawnCount);
        } else {
            // Several pieces: each piece's answers first, then, with every piece's place in the
            // list known, each writes its visible particles there: no copy through culled_. With
            // deferGather the answers are kept with the list, and the writing is left to whoever
            // takes it (DrawList::settle, gatherInto), from the same pool.
            size_t keepAt = 0;
            uint8_t* keep = nullptr;
            if (pend) {
                keepAt = out->pendingKeep.size();
                out->pendingKeep.resize(keepAt + size_t(alive));
                keep = out->pendingKeep.data() + keepAt;
            } else {
                if (keep_.size() < capacity) keep_.resize(capacity);
                keep = keep_.data();
            }
            jobs.run(pieces, [&](uint32_t piece) { pieceDrawn_[piece] = cullPiece(piece, keep, nullptr, nullptr); });
            place();
            if (pend) {
                if (drawnCount > 0) {
                    DrawList::PendingBatch p;
                    p.pool = &pool;
                    p.alive = uint32_t(alive);
                    p.first = uint32_t(listed);
                    p.keepAt = uint32_t(keepAt);
                    p.pieceAt = uint32_t(out->pendingPieceFirst.size());
                    p.grouped = grouped;
                    out->pendingPieceFirst.insert(out->pendingPieceFirst.end(), pieceFirst_.begin(), pieceFirst_.end());
                    out->pending.push_back(p);
                }
            } else {
                out->instances.resize(size_t(listed) + drawnCount);
                ParticleInstance* const to = out->instances.data() + listed;
                jobs.run(pieces, [&](uint32_t piece) {
                    if (pieceDrawn_[piece] > 0) {
                        gatherKept(streams, pieces.begin(piece), pieces.end(piece), grouped, keep, to + pieceFirst_[piece]);
                    }
                });
            }
        }
        if (sort && drawnCount > 0) {
            // The depths without the gaps (and where each came from), sorted; then gathered.
            jobs.run(pieces, [&](uint32_t piece) {
                const size_t from = pieces.begin(piece), n = pieceDrawn_[piece], to = pieceFirst_[piece];
                if (n == 0) return;
                std::memcpy(packedDepth_.data() + to, depth_.data() + from, n * sizeof(float));
                for (size_t j = 0; j < n; ++j) packedAt_[to + j] = uint32_t(from + j);
            });
            const ParticleSorter::Order order =
                sorter_.sortDescending(packedDepth_.data(), packedAt_.data(), int(drawnCount), jobs);
            const Pieces gather = splitWork(drawnCount, kCullGrain, HostAdapter::kMaxTasks);
            jobs.run(gather, [&](uint32_t piece) {
                for (size_t k = gather.begin(piece), e = gather.end(piece); k < e; ++k) {
                    at[k] = culled_[order.indices[k]];
                }
            });
        }
        batch.count = int(drawnCount);
        listed += int(drawnCount);
        if (pend) out->pendingCount = listed;
        if (batch.count == 0) continue;
        batch.rampRow = b;
        batch.technique = technique;
        batch.blend = render.blend;
        batch.softScale = 1.0f / std::fmax(render.softness, 1e-6f);  // the loader allows [1e-6, 1e6] m
        batch.contrastPower = render.contrastPower;
        batch.nearFade = render.nearFade;
        batch.lighting = in.desc->lighting;
        batch.backToFront = in.sortBackToFront;
        if (in.sortBackToFront && deferOrder && batch.count > 1) out->orderPending = true;
        out->batches.push_back(batch);
        if (techniqueRow(technique, false).needsSceneDepth) out->needsSceneDepth = true;
    }
}

void DrawListBuilder::order(const ViewInfo& view, DrawList* list, const Jobs& jobs) {
    list->settle(jobs);
    if (!list->orderPending) return;
    list->orderPending = false;
    const glm::vec3 forward = viewForward(view);
    for (const DrawBatch& batch : list->batches) {
        if (!batch.backToFront || batch.count < 2) continue;
        // What build() sorts: the batch's visible particles in pool order, their depths worked out
        // as it does; the same stable sort, so the same order.
        const size_t n = size_t(batch.count);
        if (culled_.size() < n) {
            culled_.resize(n);
            packedDepth_.resize(n);
            sorter_.reserve(int(n));
        }
        ParticleInstance* const drawn = list->instances.data() + batch.first;
        const Pieces pieces = splitWork(n, kCullGrain, HostAdapter::kMaxTasks);
        jobs.run(pieces, [&](uint32_t piece) {
            for (size_t k = pieces.begin(piece), e = pieces.end(piece); k < e; ++k) {
                const ParticleInstance& p = drawn[k];
                packedDepth_[k] = (p.x - view.eye.x) * forward.x + (p.y - view.eye.y) * forward.y +
                                  (p.z - view.eye.z) * forward.z;
            }
        });
        const ParticleSorter::Order order = sorter_.sortDescending(packedDepth_.data(), nullptr, int(n), jobs);
        jobs.run(pieces, [&](uint32_t piece) {
            for (size_t k = pieces.begin(piece), e = pieces.end(piece); k < e; ++k) culled_[k] = drawn[order.indices[k]];
        });
        std::memcpy(drawn, culled_.data(), n * sizeof(ParticleInstance));
    }
}

}  // namespace fx
