#include "game/FxFrameBuilder.h"

#include <algorithm>
#include <cmath>

#include "rtt/RenderTargetPool.h"

namespace cube {

namespace {

fx::TargetFormat toTargetFormat(rtt::ColorFormat f) {
    switch (f) {
        case rtt::ColorFormat::RGBA16F: return fx::TargetFormat::RGBA16F;
        case rtt::ColorFormat::R32F: return fx::TargetFormat::R32F;
        case rtt::ColorFormat::RG32F: return fx::TargetFormat::RG32F;
        case rtt::ColorFormat::RGBA8:
        case rtt::ColorFormat::None: break;
    }
    return fx::TargetFormat::RGBA8;
}

// fx::PassContext over rtt::PassContext, translating fx targets to graph resources.
class FxPassContext final : public fx::PassContext {
public:
    FxPassContext(rtt::PassContext& ctx, rtt::FrameGraphResource color, rtt::FrameGraphResource depth,
                  uint32_t colorId, uint32_t depthId)
        : ctx_(ctx), color_(color), depth_(depth), colorId_(colorId), depthId_(depthId) {}
    void bindForDraw(fx::Target t) override { ctx_.bindForDraw(map(t)); }
    fx::TextureRef texture(fx::Target t, int attachment) override {
        const rtt::FrameGraphResource r = map(t);
        fx::TextureRef ref;
        ref.name = ctx_.texture(r, attachment);
        if (ref.name == 0) return fx::TextureRef{};
        const rtt::RenderTargetDesc* d = ctx_.pool().desc(ctx_.handle(r));
        if (d && attachment >= 0 && attachment < rtt::kMaxColorAttachments) {
            ref.format = toTargetFormat(d->color[size_t(attachment)]);
        }
        ref.width = ctx_.width(r);
        ref.height = ctx_.height(r);
        return ref;
    }
    int width(fx::Target t) override { return ctx_.width(map(t)); }
    int height(fx::Target t) override { return ctx_.height(map(t)); }

private:
    rtt::FrameGraphResource map(fx::Target t) const {
        if (t.id == colorId_) return color_;
        if (t.id == depthId_) return depth_;
        return rtt::FrameGraphResource{t.id};
    }
    rtt::PassContext& ctx_;
    rtt::FrameGraphResource color_, depth_;
    uint32_t colorId_, depthId_;
};

rtt::ColorFormat toColorFormat(fx::TargetFormat f) {
    switch (f) {
        case fx::TargetFormat::RGBA8: return rtt::ColorFormat::RGBA8;
        case fx::TargetFormat::RGBA16F: return rtt::ColorFormat::RGBA16F;
        case fx::TargetFormat::R32F: return rtt::ColorFormat::R32F;
        case fx::TargetFormat::RG32F: return rtt::ColorFormat::RG32F;
    }
    return rtt::ColorFormat::RGBA8;
}

}  // namespace

rtt::RenderTargetDesc FxFrameBuilder::toRenderTargetDesc(const fx::TargetDesc& d, const char* name) {
    rtt::RenderTargetDesc r;
    r.width = d.width;
    r.height = d.height;
    r.scale = d.scale;
    r.color[0] = toColorFormat(d.format);
    r.depth = d.depth ? rtt::DepthFormat::Depth24 : rtt::DepthFormat::None;
    r.filter = d.linearFilter ? rtt::Filter::Linear : rtt::Filter::Nearest;
    r.name = name ? name : "";
    return r;
}

fx::Target FxFrameBuilder::createTarget(const char* name, const fx::TargetDesc& desc) {
    names_.push_back(prefix_ + (name ? name : "fx_target"));
    rtt::RenderTargetDesc d = toRenderTargetDesc(desc, nullptr);
    if (rtt::isRelative(d) && d.scale > 0.0f && std::isfinite(d.scale)) {
        // Relative to this view (a mirror inset is smaller than the main view the pool follows).
        rtt::resolveSize(d, viewWidth_, viewHeight_, graph_.pool().limits().maxTextureSize, &d.width, &d.height);
    }
    const rtt::FrameGraphResource r = graph_.create(names_.back().c_str(), d);
    return {r.id};
}

void FxFrameBuilder::addPass(const char* name, std::initializer_list<fx::Target> reads,
                             std::initializer_list<fx::Target> writes,
                             std::function<void(fx::PassContext&)> execute) {
    passes_.push_back({prefix_ + (name ? name : "fx_pass"), reads, writes, std::move(execute)});
}

bool FxFrameBuilder::readsSceneDepth() const {
    return std::any_of(passes_.begin(), passes_.end(), [](const Recorded& p) {
        return std::any_of(p.reads.begin(), p.reads.end(), [](fx::Target t) { return t.id == kSceneDepth; });
    });
}

rtt::FrameGraphResource FxFrameBuilder::map(fx::Target t) const {
    if (t.id == kSceneColor) return color_;
    if (t.id == kSceneDepth) return depth_;
    return rtt::FrameGraphResource{t.id};
}

void FxFrameBuilder::replay(rtt::FrameGraphResource sceneColor, rtt::FrameGraphResource sceneDepth) {
    color_ = sceneColor;
    depth_ = sceneDepth;
    for (Recorded& p : passes_) {
        std::vector<rtt::FrameGraphResource> reads, writes;
        for (fx::Target t : p.reads) reads.push_back(map(t));
        for (fx::Target t : p.writes) writes.push_back(map(t));
        auto execute = std::move(p.execute);
        graph_.addPass(p.name.c_str(), order_, reads.data(), reads.size(), writes.data(), writes.size(),
                       [execute, sceneColor, sceneDepth](rtt::PassContext& ctx) {
                           FxPassContext fxCtx(ctx, sceneColor, sceneDepth, kSceneColor, kSceneDepth);
                           execute(fxCtx);
                       });
    }
    passes_.clear();
}

}  // namespace cube
