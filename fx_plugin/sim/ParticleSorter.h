#pragma once
// Draw order for one pool and one view: indices of live particles from far to near, for
// alpha-blended (non-commutative) blending. A renderer keeps one sorter per (reaction, view);
// its buffers grow to the pool's capacity on first use and are reused, so after warm-up a
// sort allocates nothing. LSD radix sort on the view depth (3 passes of 11 bits; 4 of 8 when
// sorted in pieces): O(n), stable (equal depths keep pool order), deterministic.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "ParticlePool.h"
#include "base/ParallelFor.h"

namespace fx {

class ParticleSorter {
public:
    struct Order {
        const uint32_t* indices = nullptr;  ///< into the pool's streams; valid until the next update
        int count = 0;                       ///< = pool.alive() at update time
    };

    /// Allocates for pools of up to `capacity` particles (update() does it when needed).
    void reserve(int capacity);

    /// With `sort` true: particles ordered by decreasing depth dot(p - eye, viewDir) (viewDir
    /// need not be normalised), i.e. back to front. With `sort` false (additive blending, or
    /// render.sort_back_to_front off: see ReactionRuntime::needsSorting) the identity order,
    /// without computing depths.
    Order update(const ParticlePool& pool, glm::vec3 eye, glm::vec3 viewDir, bool sort);

    /// Indices 0..n-1 ordered by decreasing depth[i], equal depths in index order: the order
    /// update() gives for particles whose depths these are, for a caller that has culled the
    /// pool first and sorts only what it draws.
    Order sortDescending(const float* depth, int n);

    /// The same order of depth[0 .. n), each entry given as payload[i] (null: i), sorted in
    /// pieces through `jobs` (base/ParallelFor.h) where n is large enough: each pass counts its
    /// digits piece by piece and scatters the pieces in order, so the order does not depend on
    /// how (or on how many threads) the pieces run.
    Order sortDescending(const float* depth, const uint32_t* payload, int n, const Jobs& jobs);

    Order order() const { return order_; }

private:
    void addKey(int i, uint32_t key);  // keys_[i] and the histograms of its digits
    Order radixSort(int n);            // keys_/indices_ [0, n) with histograms counted
    std::vector<uint32_t> keys_, keysTmp_, indices_, indicesTmp_, histogram_;
    std::vector<uint32_t> pieceCounts_, pieceSlots_;  // [piece][digit] of the pass in hand
    Order order_;
};

}  // namespace fx
