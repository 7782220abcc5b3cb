#pragma once
// The GL render targets of the immediate path (ImmediateRenderer): a colour texture in one of
// TargetFormat's formats, an optional DEPTH_COMPONENT32F renderbuffer (TargetDesc::depth) and the
// framebuffer joining them, the way engine_stub's frame graph and fx_host's give them to the
// plugin. Kept across frames: a request takes a free slot of the same size, format, filter and
// depth, else allocates one. A slot unused for kKeepFrames frames is freed (a view that changed
// size lets its old targets go); release() frees everything.
#include <cstdint>
#include <vector>

#include "fx/Types.h"

namespace fx {

/// One pooled target. Valid (GL names) while the pool owns it; `inUse` for the frame that took it.
struct PooledTarget {
    TargetDesc desc;
    int width = 0, height = 0;
    uint32_t texture = 0, depth = 0, framebuffer = 0;
    bool inUse = false;
    uint64_t lastFrame = 0;  ///< the pool frame that last took it
};

class ImmediateTargetPool {
public:
    static constexpr uint64_t kKeepFrames = 4;

    ImmediateTargetPool() = default;
    ~ImmediateTargetPool();  ///< frees its GL objects: the context must be current if any exist
    ImmediateTargetPool(const ImmediateTargetPool&) = delete;
    ImmediateTargetPool& operator=(const ImmediateTargetPool&) = delete;

    /// Marks every slot free for a new frame.
    void beginFrame();
    /// Frees the slots no frame took in the last kKeepFrames frames.
    void endFrame();
    /// A slot for `desc` at width x height (already resolved from the view); its index. When it
    /// allocates it changes the active texture unit to 0 and binds GL_TEXTURE_2D there, the
    /// pixel-unpack buffer and GL_FRAMEBUFFER (the caller's GlStateGuard restores them);
    /// GL_RENDERBUFFER, which no guard captures, is put back here.
    size_t acquire(const TargetDesc& desc, int width, int height);
    PooledTarget& at(size_t index) { return slots_[index]; }

    void release();
    int allocatedNow() const { return int(slots_.size()); }
    int allocationsEver() const { return allocations_; }

private:
    std::vector<PooledTarget> slots_;
    uint64_t frame_ = 0;
    int allocations_ = 0;
};

}  // namespace fx
