#pragma once
// The two vertex streams of the instanced particle draw (000 section 3.3.3):
//   stream 0 (static, shared): the 4 quad corners (+-1, +-1) as a triangle strip, attribute 0;
//   stream 1 (per particle, divisor 1): ParticleInstance, attributes 1 and 2.
// The instance buffer is refilled per view with orphaning (glBufferData(null) at the current
// capacity, then glBufferSubData), so the driver never waits for a draw still reading the old
// contents; its capacity only grows (doubling), never shrinks.
//
// All reactions of a view share one upload; each draw points attributes 1 and 2 at its own
// range with bindRange() (GL 3.3 has no base-instance draw).
#include <cstddef>
#include <cstdint>
#include <functional>

#include "base/ParallelFor.h"

namespace fx {

/// One particle as the vertex shader reads it. 32 bytes.
struct ParticleInstance {
    float x = 0.0f, y = 0.0f, z = 0.0f;  ///< centre, world space, m
    float size = 0.0f;                   ///< billboard edge / sphere diameter, m
    float life = 0.0f;                   ///< age / lifetime, [0, 1): colour ramp lookup
    float rotation = 0.0f;               ///< texture rotation, rad
    float fade = 1.0f;                   ///< life fade (alpha factor), [0, 1]
    float frame = 0.0f;                  ///< atlas frame 0..3
};
static_assert(sizeof(ParticleInstance) == 32, "the vertex layout assumes 8 packed floats");

/// Maps the first `bytes` of the buffer bound to `target` for writing (the old contents
/// invalidated), hands `write` the pointer, and unmaps. False where the map fails (its GL error
/// taken back) or the store was lost while mapped: the caller fills the buffer another way.
bool writeMapped(uint32_t target, size_t bytes, const std::function<void(void*)>& write);

/// Fills the start of the buffer bound to `target` with `bytes` of `data`, mapped (the old contents
/// invalidated) and copied in pieces of 512 KB on the host's threads: with a job system and more
/// than one piece. False, and nothing written, where that does not apply or mapping fails (then
/// glBufferSubData is the way). The copy is otherwise the driver's one serial step of an upload.
bool copyMappedInPieces(uint32_t target, const void* data, size_t bytes, const Jobs& jobs);

class InstanceStream {
public:
    InstanceStream() = default;
    ~InstanceStream();
    InstanceStream(const InstanceStream&) = delete;
    InstanceStream& operator=(const InstanceStream&) = delete;

    /// Creates the vertex array and both buffers. Changes the VAO and GL_ARRAY_BUFFER bindings.
    void create();
    bool created() const { return vao_ != 0; }
    /// Orphans and refills the instance buffer; grows it when `count` does not fit.
    /// Leaves GL_ARRAY_BUFFER bound to it. With a job system and tens of thousands of instances
    /// the buffer is mapped and the copy split into pieces on the host's threads (one 32-byte
    /// instance a particle: 8 MB at 256k); otherwise, or where mapping fails, glBufferSubData.
    void upload(const ParticleInstance* data, int count, const Jobs& jobs = Jobs());
    /// Uploads that went through a mapped buffer (the copy in pieces).
    int mappedUploads() const { return mappedUploads_; }
    /// Binds the vertex array with the instance attributes starting at instance `first`.
    void bindRange(int first);
    size_t capacityBytes() const { return capacityBytes_; }
    /// Uploads that had to grow the buffer (a warm stream stops growing).
    int growCount() const { return growCount_; }

private:
    uint32_t vao_ = 0;
    uint32_t cornerBuffer_ = 0;
    uint32_t instanceBuffer_ = 0;
    size_t capacityBytes_ = 0;
    int growCount_ = 0;
    int mappedUploads_ = 0;
};

}  // namespace fx
