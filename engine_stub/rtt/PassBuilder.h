#pragma once
// What a pass's setup callback uses to declare its reads and writes (Filament-style).
#include <cstdint>

#include "rtt/FrameGraphResource.h"

namespace cube::rtt {

class FrameGraph;

class PassBuilder {
public:
    /// The pass samples (or blits from, or reads back) the target's colour attachments.
    FrameGraphResource read(FrameGraphResource target);
    /// The pass samples the target's depth (its own or the one it shares): the depth owner is
    /// then allocated with a depth texture instead of a renderbuffer.
    FrameGraphResource readDepth(FrameGraphResource target);
    /// The pass draws into (or clears) the target. Drawing into a target that shares another's
    /// depth also reads and writes that other target (depth test and depth writes).
    FrameGraphResource write(FrameGraphResource target);
    /// The pass offers to write the target (the opaque pass writing the linear scene depth as a
    /// second render target; a depth prepass): taken only when a later kept pass reads it, no
    /// earlier kept pass wrote it outright, and the pass does not draw into it already through
    /// a shared z-buffer. Untaken, the target is neither allocated nor bound for this pass. An
    /// offer keeps no pass, except one whose writes are all offers. The pass asks
    /// PassContext::isNeeded(target) when it runs.
    FrameGraphResource writeIfRead(FrameGraphResource target);
    /// Keep the pass even if nobody reads what it writes (presenting, read-back, statistics).
    void sideEffect();

private:
    friend class FrameGraph;
    PassBuilder(FrameGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    /// Records one access (FrameGraph::kRead, ...) of the target by this pass; returns the target.
    FrameGraphResource declare(FrameGraphResource target, uint8_t access);
    FrameGraph& graph_;
    uint32_t pass_;
};

}  // namespace cube::rtt
