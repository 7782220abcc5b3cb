#pragma once
// A virtual (or imported) render target declared in one FrameGraph frame. The id maps 1:1 onto
// fx::Target::id (0 = invalid), so a host adapter can pass it through unchanged.
#include <cstdint>

namespace cube::rtt {

/// Defaults: invalid. Valid from FrameGraph::create/import until the next FrameGraph::reset.
struct FrameGraphResource {
    uint32_t id = 0;
    bool valid() const { return id != 0; }
    friend bool operator==(FrameGraphResource a, FrameGraphResource b) { return a.id == b.id; }
    friend bool operator!=(FrameGraphResource a, FrameGraphResource b) { return a.id != b.id; }
};

}  // namespace cube::rtt
