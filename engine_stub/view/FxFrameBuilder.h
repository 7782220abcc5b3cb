#pragma once
// engine_stub's render side of the plugin boundary: fx::FrameBuilder straight onto the view's
// rtt::FrameGraph. The view has declared its scene colour and scene depth targets before it
// calls the plugin, so fx targets are the graph's own resources (fx::Target::id ==
// rtt::FrameGraphResource::id) and each fx pass is added to the graph the moment the plugin
// declares it, at the particle bucket's place in the frame. Nothing is recorded or replayed.
#include <string>
#include <vector>

#include "fx/HostAdapter.h"
#include "rtt/FrameGraph.h"

namespace cube {

class FxFrameBuilder final : public fx::FrameBuilder {
public:
    /// `prefix` names this view's passes ("chase."); every pass gets the order key `order` (the
    /// particle bucket's) and runs in declaration order after the host's own particle passes.
    /// `viewWidth` x `viewHeight` is the view's colour target: the plugin's relative sizes
    /// ("half the view") are resolved against it, not against the pool's main view size.
    FxFrameBuilder(rtt::FrameGraph& graph, rtt::FrameGraphResource sceneColor, rtt::FrameGraphResource sceneDepth,
                   const std::string& prefix, int order, int viewWidth, int viewHeight)
        : graph_(graph), color_(sceneColor), depth_(sceneDepth), prefix_(prefix), order_(order),
          viewWidth_(viewWidth), viewHeight_(viewHeight) {}

    fx::Target sceneColor() override { return {color_.id}; }
    fx::Target sceneDepth() override { return {depth_.id}; }
    /// The z-buffer (API 2.1), once offerZBuffer() named its owner: a handle of its own that a
    /// pass's reads turn into rtt's readDepth(owner) (the owner's depth becomes a texture), and
    /// that the pass context resolves to the owner's depth texture.
    fx::Target sceneZBuffer() override { return zOwner_.valid() ? fx::Target{kZBufferId} : fx::Target{}; }
    fx::HostDepth sceneZBufferMapping() override { return zMapping_; }
    fx::Target createTarget(const char* name, const fx::TargetDesc& desc) override;
    void addPass(const char* name, std::initializer_list<fx::Target> reads,
                 std::initializer_list<fx::Target> writes,
                 std::function<void(fx::PassContext&)> execute) override;

    /// The view is the rectangle at (x, y) of sceneColor, view size (split screen): the plugin's
    /// bindForDraw(sceneColor) sets it as the viewport (fx::ViewInfo::x, y say the same).
    void placeView(int x, int y) {
        placed_ = true;
        x_ = x;
        y_ = y;
    }
    /// True when a pass the plugin declared reads the scene depth (the prepass will then run).
    bool readsSceneDepth() const { return readsDepth_; }
    /// Offers the plugin the z-buffer `owner`'s depth attachment holds (the colour target's own,
    /// or the depth prepass's that it shares), drawn under clip control ZERO_TO_ONE or not.
    void offerZBuffer(rtt::FrameGraphResource owner, bool clipZeroToOne) {
        zOwner_ = owner;
        zMapping_.clipDepthZeroToOne = clipZeroToOne;
    }
    /// fx::Target id of sceneZBuffer(): outside the graph's resource ids.
    static constexpr uint32_t kZBufferId = 0xFFFFFFF0u;

    static rtt::RenderTargetDesc toRenderTargetDesc(const fx::TargetDesc& desc, const char* name);

private:
    rtt::FrameGraph& graph_;
    rtt::FrameGraphResource color_, depth_;
    rtt::FrameGraphResource zOwner_;
    fx::HostDepth zMapping_;
    std::string prefix_;
    int order_;
    int viewWidth_, viewHeight_;
    bool placed_ = false;
    int x_ = 0, y_ = 0;
    bool readsDepth_ = false;
    std::vector<std::string> names_;  // keeps createTarget names alive for the frame
    std::vector<rtt::FrameGraphResource> reads_, writes_;  // scratch for addPass
};

}  // namespace cube
