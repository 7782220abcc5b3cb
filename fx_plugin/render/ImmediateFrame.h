#pragma once
// The immediate path's frame graph (ImmediateRenderer): fx::FrameBuilder and fx::PassContext over
// the framebuffer the host had bound for drawing and the plugin's own pooled targets, for one
// view, one frame. The semantics the plugin's passes expect from engine_stub's frame graph
// (engine_stub/rtt/) and fx_host's (tests/fx_host/TestFrameGraph.cpp):
//   - passes run in declaration order; a pass runs only if it writes sceneColor or a target a
//     later running pass reads (walked back from sceneColor); targets are allocated only for
//     running passes;
//   - sceneColor is the host's framebuffer (its z-buffer attached); bindForDraw binds it with the
//     viewport the host had at the call, at the view's size, and, when the view asks for it
//     (clipToHostScissor), the scissor the host had enabled at the call: the plugin's draws
//     into the host's framebuffer then stay inside it;
//   - sceneZBuffer (when the host's depth is a z-buffer: a depth texture, or the bound
//     framebuffer's depth) is that z-buffer as a depth texture: the host's own texture, sampled
//     in place, or the plugin's copy of the framebuffer's depth, which the copy hook makes right
//     before the first running pass that reads it, over the pixels the running passes read;
//   - sceneDepth is the linear R32F depth: the host's own texture (LinearR32F), or a pooled R32F
//     target that the depth hook fills right before the first running pass that reads it (the
//     path of contexts that cannot sample a z-buffer in place, SceneDepthSource.h). A frame
//     whose passes read no depth copies and linearises nothing;
//   - createTarget sizes follow the view (TargetDesc::scale, at least 1 px) unless absolute.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "fx/HostAdapter.h"
#include "DepthMapping.h"
#include "ImmediateTargetPool.h"

namespace fx {

/// What one immediate frame draws into and reads from. Defaults: nothing (set every field).
struct ImmediateFrameSetup {
    int width = 0, height = 0;           ///< the view's size (sceneColor, sceneDepth)
    uint32_t hostFramebuffer = 0;        ///< GL_DRAW_FRAMEBUFFER at the call (0 = default)
    int viewportX = 0, viewportY = 0;    ///< the host's viewport origin at the call
    bool hostScissor = false;            ///< the host had the scissor test on at the call
    int scissorBox[4] = {0, 0, 0, 0};    ///< its box
    int linearWidth = 0, linearHeight = 0;  ///< hostLinearDepth's size (0 = the view's)
    uint32_t hostLinearDepth = 0;        ///< the host's R32F linear depth, or 0 = produce it
    /// Fills the linear depth into `framebuffer` (R32F colour, width x height) over `region` at
    /// least (the union of what the running passes read; outside it the value may be anything
    /// that reads as nothing drawn). Called at most once a frame, inside the frame's GL state guard.
    std::function<void(uint32_t framebuffer, const DepthRegion& region)> produceDepth;
    /// The host's depth is a z-buffer (sceneZBuffer is offered), drawn under `zMapping`'s clip
    /// control and depth range.
    bool zBuffer = false;
    HostDepth zMapping;
    uint32_t hostZTexture = 0;  ///< its depth texture, sampled in place; 0 = copy it (copyZBuffer)
    int zWidth = 0, zHeight = 0;  ///< hostZTexture's size (0 = the view's: the copy is the view's rectangle)
    /// Copies the framebuffer's depth over `region` at least into a depth texture of the plugin's
    /// and returns it. Called at most once a frame, inside the frame's GL state guard.
    std::function<uint32_t(const DepthRegion& region)> copyZBuffer;
};

class ImmediateFrame final : public FrameBuilder {
public:
    static constexpr uint32_t kSceneColor = 1, kSceneDepth = 2, kSceneZBuffer = 3;
    static constexpr uint32_t kFirstCreated = 4;  ///< createTarget's ids count up from here

    ImmediateFrame(ImmediateTargetPool& pool, ImmediateFrameSetup setup);

    Target sceneColor() override { return Target{kSceneColor}; }
    Target sceneDepth() override { return Target{kSceneDepth}; }
    Target sceneZBuffer() override { return setup_.zBuffer ? Target{kSceneZBuffer} : Target{}; }
    HostDepth sceneZBufferMapping() override { return setup_.zMapping; }
    Target createTarget(const char* name, const TargetDesc& desc) override;
    void addPass(const char* name, std::initializer_list<Target> reads, std::initializer_list<Target> writes,
                 std::function<void(PassContext&)> execute) override;

    /// The plugin's renderers (not the host): the next pass added that reads the scene depth
    /// (sceneDepth or sceneZBuffer) reads it
    /// only inside `region` (a bound of its fragments' footprint, tiles included). A depth-reading
    /// pass added without one reads the whole view. Only the union over the running passes is
    /// copied and linearised: on a CPU rasteriser the full-screen depth passes cost what their
    /// pixels cost.
    void setNextDepthRegion(const DepthRegion& region) { nextRegion_ = region; }
    /// The union the last execute() produced depth over (whole when nothing narrowed it).
    const DepthRegion& producedDepthRegion() const { return produced_; }

    bool empty() const { return passes_.empty(); }
    /// Culls, allocates and runs the passes. Restores the GL state it changes itself (each plugin
    /// pass restores its own).
    void execute();
    const std::vector<std::string>& executed() const { return executed_; }

private:
    struct Pass {
        std::string name;
        std::vector<uint32_t> reads, writes;
        std::function<void(PassContext&)> run;
        DepthRegion depthRegion;  ///< where it reads the scene depth (whole unless a renderer narrowed it)
        bool readsDepth(uint32_t which) const;
    };
    struct Created {
        std::string name;
        TargetDesc desc;
        size_t slot = SIZE_MAX;  ///< pool slot once allocated
    };
    class Context;

    void allocate(uint32_t id);
    const PooledTarget* slotOf(uint32_t id) const;

    ImmediateTargetPool& pool_;
    ImmediateFrameSetup setup_;
    std::vector<Pass> passes_;
    std::vector<Created> created_;  ///< id - kFirstCreated
    size_t depthSlot_ = SIZE_MAX;   ///< the produced linear depth's pool slot
    bool depthReady_ = false;
    uint32_t zTexture_ = 0;         ///< sceneZBuffer's texture once there (the host's, or the copy)
    DepthRegion nextRegion_;
    DepthRegion produced_;
    std::vector<std::string> executed_;
};

}  // namespace fx
