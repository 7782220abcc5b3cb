#pragma once
// The simulation's own random numbers: PCG32 (O'Neill, pcg-random.org, "XSH RR" output),
// seeded through splitmix64. Deterministic across platforms and runs; no std::rand, no clocks.
#include <cstdint>
#include <string>

namespace fx {

/// One splitmix64 step: a well-mixed 64-bit value from a counter (used for seeding).
inline uint64_t splitmix64(uint64_t& state) {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// lowbias32 (Chris Wellons' 32-bit integer finalizer): every input bit reaches every output
/// bit. Lattice noise hashes its mixed-in coordinates with it (CurlNoise here, the smoke atlas in
/// tools/make_assets_smoke.cpp); changing it changes the noise and the committed atlas bytes.
inline uint32_t lowbias32(uint32_t h) {
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

/// 64-bit FNV-1a of a name (stable across runs, unlike std::hash).
inline uint64_t nameHash(const std::string& name) {
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : name) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

class Pcg32 {
public:
    /// Defaults: seed 0, stream 0 (still a full-period, well-mixed generator).
    explicit Pcg32(uint64_t seed = 0, uint64_t stream = 0) { reseed(seed, stream); }

    void reseed(uint64_t seed, uint64_t stream = 0) {
        uint64_t mix = seed;
        state_ = 0;
        inc_ = (splitmix64(mix) ^ stream) << 1u | 1u;
        next();
        state_ += splitmix64(mix);
        next();
    }

    uint32_t next() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    /// Uniform in [0, 1) with 24 random bits (every value exactly representable as float).
    float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
    /// Uniform in [lo, hi).
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; bias < n / 2^32).
    uint32_t below(uint32_t n) {
        return static_cast<uint32_t>((static_cast<uint64_t>(next()) * n) >> 32);
    }

    bool operator==(const Pcg32& o) const { return state_ == o.state_ && inc_ == o.inc_; }
    bool operator!=(const Pcg32& o) const { return !(*this == o); }

private:
    uint64_t state_ = 0;
    uint64_t inc_ = 1;
};

/// The generator of one reaction: the global seed and the reaction's name pick the stream,
/// so adding or reordering reactions does not change what the others emit.
inline Pcg32 reactionRng(uint64_t globalSeed, const std::string& reactionName) {
    return Pcg32(globalSeed ^ nameHash(reactionName), nameHash(reactionName));
}

}  // namespace fx
