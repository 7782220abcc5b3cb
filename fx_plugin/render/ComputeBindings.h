#pragma once
// What the tiled path's compute passes (TiledPath.h, TileSort.h) change that GlStateGuard has no
// rows for, and how they fill their storage buffers.
//
// GL state: ComputeBindingsScope reads the shader storage buffer bindings 0 .. kBindings - 1 (with
// their ranges), the generic one and image unit kImage on entry and puts them back on exit.
// Context current, GL 4.3 (TiledPath::available()).
#include <cstddef>
#include <cstdint>

#include "base/ParallelFor.h"

namespace fx {

class ComputeBindingsScope {
public:
    /// The sort's 0-4 (TileSort::kBindings) hold the pass's 0-4; the lit pass's shapes take 5.
    static constexpr int kBindings = 6;
    static constexpr int kImage = 0;  ///< the accumulation image's unit

    ComputeBindingsScope();
    ~ComputeBindingsScope();
    ComputeBindingsScope(const ComputeBindingsScope&) = delete;
    ComputeBindingsScope& operator=(const ComputeBindingsScope&) = delete;

private:
    int32_t generic_ = 0;
    int32_t buffer_[kBindings] = {};
    int64_t start_[kBindings] = {}, size_[kBindings] = {};
    int32_t image_[6] = {};  // name, level, layered, layer, access, format
};

/// Fills `*buffer` (a grow-only shader storage buffer, TileSort::ensureBuffer) with `bytes`: mapped
/// and copied on the host's threads where that applies, else glBufferSubData. Leaves it bound to
/// GL_SHADER_STORAGE_BUFFER.
void fillStorage(uint32_t* buffer, size_t* capacity, const void* data, size_t bytes, const Jobs& jobs);

struct DrawList;
/// Fills `*buffer` as fillStorage does with the list's instances. A pending gather
/// (DrawList::gatherPending) is written from the pools straight into the mapped store, in the
/// pieces the cull made, on the host's threads: true. Else, or where the map fails or loses its
/// store (the list then settled), a copy of the written list: false.
bool fillInstances(uint32_t* buffer, size_t* capacity, DrawList& list, const Jobs& jobs);

}  // namespace fx
