#pragma once
// engine_stub's render side of the plugin boundary: fx::FrameBuilder over the rtt FrameGraph.
//
// The plugin declares its passes before the view has created its colour target, because the
// colour target's descriptor depends on the answer: when a particle needs scene depth the depth
// prepass runs, and with prepass-EQUAL the colour target then shares the prepass z-buffer. So
// this builder records the plugin's passes against two placeholder targets (scene colour, scene
// depth), the view then builds its targets, and replay() adds the passes to the graph with the
// placeholders bound to the real targets.
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
    FxFrameBuilder(rtt::FrameGraph& graph, const std::string& prefix, int order, int viewWidth, int viewHeight)
        : graph_(graph), prefix_(prefix), order_(order), viewWidth_(viewWidth), viewHeight_(viewHeight) {}

    fx::Target sceneColor() override { return {kSceneColor}; }
    fx::Target sceneDepth() override { return {kSceneDepth}; }
    fx::Target createTarget(const char* name, const fx::TargetDesc& desc) override;
    void addPass(const char* name, std::initializer_list<fx::Target> reads,
                 std::initializer_list<fx::Target> writes,
                 std::function<void(fx::PassContext&)> execute) override;

    bool empty() const { return passes_.empty(); }
    /// True when a recorded pass reads the scene depth: the view must run its depth prepass.
    bool readsSceneDepth() const;
    /// Adds the recorded passes to the graph with the placeholders bound to the view's targets.
    void replay(rtt::FrameGraphResource sceneColor, rtt::FrameGraphResource sceneDepth);

    static rtt::RenderTargetDesc toRenderTargetDesc(const fx::TargetDesc& desc, const char* name);

private:
    static constexpr uint32_t kSceneColor = 0xFFFFFFF0u;
    static constexpr uint32_t kSceneDepth = 0xFFFFFFF1u;
    struct Recorded {
        std::string name;
        std::vector<fx::Target> reads, writes;
        std::function<void(fx::PassContext&)> execute;
    };
    rtt::FrameGraphResource map(fx::Target t) const;

    rtt::FrameGraph& graph_;
    std::string prefix_;
    int order_;
    int viewWidth_, viewHeight_;
    std::vector<Recorded> passes_;
    std::vector<std::string> names_;  // keeps createTarget names alive for the frame
    rtt::FrameGraphResource color_, depth_;
};

}  // namespace cube
