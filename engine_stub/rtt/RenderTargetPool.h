#pragma once
// Owns every render target's GL objects and hands them out as generation-checked handles.
// Acquire reuses a matching free target or creates one; release returns it to the free list;
// endFrame frees what stayed unused for a few frames. Needs the GL context current for every
// call, construction and destruction included. Restores every GL binding it touches.
#include <cstdint>
#include <string>
#include <vector>

#include "rtt/RenderTargetDesc.h"
#include "rtt/RenderTargetHandle.h"
#include "rtt/RttError.h"

namespace cube::rtt {

/// Defaults: a free target is destroyed after 3 frames unused; limits come from the driver.
/// A positive max* value lowers the driver's limit (to emulate a smaller device, or in tests).
struct RenderTargetPoolDesc {
    int framesUntilFree = 3;
    int maxTextureSize = 0;       ///< 0 = GL_MAX_TEXTURE_SIZE
    int maxRenderbufferSize = 0;  ///< 0 = GL_MAX_RENDERBUFFER_SIZE
    int maxColorAttachments = 0;  ///< 0 = min(GL_MAX_COLOR_ATTACHMENTS, GL_MAX_DRAW_BUFFERS, 4)
};

/// GL object counts are exact: the pool is the only owner of what it creates.
struct RenderTargetPoolStats {
    int targetsInUse = 0;
    int targetsFree = 0;
    int liveTextures = 0;
    int liveRenderbuffers = 0;
    int liveFramebuffers = 0;
    uint64_t totalAllocations = 0;  ///< targets created since start (each = 1 FBO + attachments)
    uint64_t reallocations = 0;     ///< in-place storage re-specifications (view resizes)
    int allocationsThisFrame = 0;   ///< targets created since the last beginFrame()
    uint64_t frame = 0;             ///< beginFrame() calls so far
};

class RenderTargetPool {
public:
    explicit RenderTargetPool(const RenderTargetPoolDesc& desc = {});
    ~RenderTargetPool();
    RenderTargetPool(const RenderTargetPool&) = delete;
    RenderTargetPool& operator=(const RenderTargetPool&) = delete;

    /// The size relative targets follow. Every relative target, in use or free, is re-specified
    /// in place: handles and GL object names stay valid, contents become undefined. A 0x0 view
    /// (minimised window) is accepted: relative targets become 1x1, nothing is created, no error.
    void setViewSize(int width, int height);
    int viewWidth() const { return viewWidth_; }
    int viewHeight() const { return viewHeight_; }

    /// Frame bracket for garbage collection; endFrame destroys free targets unused for
    /// framesUntilFree frames (a depth owner only once no other target shares its depth).
    void beginFrame();
    void endFrame();
    /// Destroys every free target now.
    void trim();

    /// A target matching `desc` (size rule, formats, sampling, shared depth; not the name),
    /// reused from the free list (lowest slot first, so a steady frame gets the same targets)
    /// or created. On bad data: an invalid handle, `*error` set, lastErrorMessage() says why,
    /// no GL object left behind and no GL error. Contents of a reused target are undefined.
    RenderTargetHandle acquire(const RenderTargetDesc& desc, RttError* error = nullptr);
    /// Returns the target to the free list; the handle (and copies of it) become stale.
    /// RttError::InvalidHandle for a stale or unknown handle.
    RttError release(RenderTargetHandle handle);
    bool isValid(RenderTargetHandle handle) const;

    /// Queries; a stale handle gives 0 / nullptr.
    int width(RenderTargetHandle handle) const;
    int height(RenderTargetHandle handle) const;
    /// The normalised descriptor the target was made from (name points into the pool).
    const RenderTargetDesc* desc(RenderTargetHandle handle) const;
    /// GL framebuffer name (for binding helpers and host adapters).
    uint32_t framebuffer(RenderTargetHandle handle) const;
    /// GL texture of colour attachment `index` (0 if unused).
    uint32_t colorTexture(RenderTargetHandle handle, int index = 0) const;
    /// GL texture of the depth attachment, the shared one included; 0 when there is none or it
    /// is a renderbuffer (set RenderTargetDesc::sampledDepth on the depth owner).
    uint32_t depthTexture(RenderTargetHandle handle) const;
    /// Depth format actually attached (the owner's for a shared depth).
    DepthFormat depthFormat(RenderTargetHandle handle) const;

    const RenderTargetLimits& limits() const { return limits_; }
    RenderTargetPoolStats stats() const;
    const std::string& lastErrorMessage() const { return lastError_; }

    /// Test seam: the next target creation builds its GL objects, then fails with `error` (e.g.
    /// FramebufferIncomplete, AllocationFailed), exercising the real cleanup path.
    void failNextCreateForTesting(RttError error) { injectedFailure_ = error; }

private:
    enum class State : uint8_t { Empty, Free, InUse };
    struct Slot {
        State state = State::Empty;
        uint32_t generation = 1;
        RenderTargetDesc desc;  // normalised; desc.name points at `name`
        std::string name;
        int sharedDepthSlot = -1;  // slot whose depth this target attaches
        int dependents = 0;        // targets attaching this slot's depth
        int width = 0, height = 0;
        uint32_t fbo = 0;
        uint32_t color[kMaxColorAttachments] = {};
        uint32_t depthTexture = 0;
        uint32_t depthRenderbuffer = 0;
        uint64_t lastUsedFrame = 0;
    };

    const Slot* live(RenderTargetHandle handle) const;
    RttError create(const RenderTargetDesc& desc, const char* name, int sharedDepthSlot, int width,
                    int height, int* slotIndex);
    void allocateStorage(Slot& slot);
    void destroy(int slotIndex);
    RttError fail(RttError error, RttError* out, std::string message);

    std::vector<Slot> slots_;
    std::vector<int> emptySlots_;
    RenderTargetLimits limits_;
    int framesUntilFree_ = 3;
    int viewWidth_ = 0, viewHeight_ = 0;
    uint64_t frame_ = 0;
    int liveTextures_ = 0, liveRenderbuffers_ = 0, liveFramebuffers_ = 0;
    uint64_t totalAllocations_ = 0, reallocations_ = 0;
    int allocationsThisFrame_ = 0;
    std::string lastError_;
    RttError injectedFailure_ = RttError::None;
};

}  // namespace cube::rtt
