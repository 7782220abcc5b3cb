#pragma once
// A fixed-capacity particle pool, structure of arrays. Storage is allocated once, in the
// constructor; spawn/kill never allocate. Live particles are always the dense range
// [0, alive()): kill() moves the last live particle into the freed slot (swap-remove), so the
// order of particles changes when one dies (renderers must not keep indices across steps).
//
// What a renderer reads per particle i < alive():
//   posX/posY/posZ (world, m), size (billboard edge now, m), life (age / lifetime, [0, 1)),
//   rotation (rad), frame (atlas frame 0..3), fade (alpha factor [0, 1]: fade in/out over life).
// The rest is simulation state.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fx {

class ParticlePool {
public:
    /// The float streams, in storage order. Each is capacity() floats.
    enum Stream : int {
        PosX = 0, PosY, PosZ,
        VelX, VelY, VelZ,
        Age,         ///< seconds since birth
        Lifetime,    ///< seconds this particle lives
        StartSize,   ///< m
        EndSize,     ///< m
        Rotation,    ///< rad, wrapped to [-pi, pi]
        Spin,        ///< rad/s
        Size,        ///< m, derived: size at the current life fraction
        Life,        ///< derived: age / lifetime
        Fade,        ///< derived: alpha factor
        OriginX,     ///< m, the emitter's position at birth (the vortex axis passes through it)
        OriginZ,
        StreamCount
    };

    /// Defaults: an empty pool (capacity 0). `capacity` must be >= 0 (the loader bounds it).
    explicit ParticlePool(int capacity = 0);

    int capacity() const { return capacity_; }
    int alive() const { return alive_; }
    bool full() const { return alive_ >= capacity_; }

    /// Claims the slot alive() and returns its index, or -1 when full. Its fields hold whatever
    /// the slot held before: the caller sets every stream and frame.
    int spawn() { return alive_ < capacity_ ? alive_++ : -1; }
    /// Swap-remove: the last live particle moves into slot i. i must be < alive().
    void kill(int i);
    void clear() { alive_ = 0; }

    float* stream(Stream s) { return data_.data() + static_cast<size_t>(s) * capacity_; }
    const float* stream(Stream s) const { return data_.data() + static_cast<size_t>(s) * capacity_; }
    uint8_t* frame() { return frame_.data(); }
    const uint8_t* frame() const { return frame_.data(); }

    const float* posX() const { return stream(PosX); }
    const float* posY() const { return stream(PosY); }
    const float* posZ() const { return stream(PosZ); }
    const float* size() const { return stream(Size); }
    const float* life() const { return stream(Life); }
    const float* rotation() const { return stream(Rotation); }
    const float* fade() const { return stream(Fade); }

    /// Bytes of pool storage (for stats and tests).
    size_t bytes() const { return data_.size() * sizeof(float) + frame_.size(); }

private:
    int capacity_ = 0;
    int alive_ = 0;
    std::vector<float> data_;     ///< StreamCount blocks of capacity_ floats
    std::vector<uint8_t> frame_;  ///< atlas frame per particle
};

}  // namespace fx
