#pragma once
// The birth records of a stateless reaction (technique: stateless): one record per particle,
// written once at emission and never updated; the vertex shader evaluates the particle from it
// and the current time (sim/StatelessParticle.h). A ring of `capacity` records: a new particle
// takes the slot of the oldest, which is dead when capacity >= rate x longest life (the loader's
// sizing rule in reactions/README.md); a live particle overwritten early is counted.
//
// The renderer uploads only what changed: written() counts every record ever written, so a
// reader that uploaded up to count n copies slots n .. written() - 1 (mod capacity), or all of
// them when more than capacity were written since.
#include <cstdint>
#include <vector>

namespace fx {

/// One particle's birth, 16 floats = 4 vec4 attributes (the GPU layout as is).
struct StatelessRecord {
    float p0[3];        ///< world position at birth, m
    float birth;        ///< reaction clock at birth, s
    float v0[3];        ///< velocity at birth, m/s
    float lifetime;     ///< s
    float startSize;    ///< m
    float endSize;      ///< m
    float rotation;     ///< rad at birth
    float spin;         ///< rad/s
    float frame;        ///< atlas frame
    float pad[3];
};
static_assert(sizeof(StatelessRecord) == 16 * sizeof(float), "4 vec4 attributes");

class StatelessRing {
public:
    explicit StatelessRing(int capacity = 0) : records_(static_cast<size_t>(capacity > 0 ? capacity : 0)) {}

    int capacity() const { return static_cast<int>(records_.size()); }
    uint64_t written() const { return written_; }
    const StatelessRecord* data() const { return records_.data(); }

    /// Writes `r` over the oldest slot. Returns false when that slot held a particle still alive
    /// at `now` (recycled early: the caller counts it as dropped).
    bool write(const StatelessRecord& r, double now) {
        if (records_.empty()) return false;
        StatelessRecord& slot = records_[static_cast<size_t>(written_ % records_.size())];
        const bool evicted = written_ >= records_.size() && aliveAt(slot, now);
        slot = r;
        ++written_;
        const float death = r.birth + r.lifetime;
        if (death > liveUntil_) liveUntil_ = death;
        return !evicted;
    }

    /// Records alive at `now` (0 <= now - birth < lifetime). O(capacity): for stats, not per frame.
    int alive(double now) const {
        const uint64_t n = written_ < records_.size() ? written_ : records_.size();
        int count = 0;
        for (uint64_t i = 0; i < n; ++i) count += aliveAt(records_[static_cast<size_t>(i)], now) ? 1 : 0;
        return count;
    }

    /// The clock time when the last record written dies: nothing is alive after it. O(1), so a
    /// renderer can skip a reaction with no live record without reading the records.
    float liveUntil() const { return liveUntil_; }

    void clear() {
        written_ = 0;
        liveUntil_ = 0.0f;
    }

    /// In float, as the vertex shader sees it (uTime and birth are floats): a record written
    /// this step is alive at once, whatever the rounding of the double clock.
    static bool aliveAt(const StatelessRecord& r, double now) {
        const float age = static_cast<float>(now) - r.birth;
        return age >= 0.0f && age < r.lifetime;
    }

private:
    std::vector<StatelessRecord> records_;
    uint64_t written_ = 0;
    float liveUntil_ = 0.0f;
};

}  // namespace fx
