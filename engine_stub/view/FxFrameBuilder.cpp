#include "view/FxFrameBuilder.h"

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

// fx::PassContext over rtt::PassContext (fx target ids are graph resource ids).
class FxPassContext final : public fx::PassContext {
public:
    /// `view`: x, y, width, height of the view in `color` when it is a part of it (width 0: all of it).
    FxPassContext(rtt::PassContext& ctx, rtt::FrameGraphResource zOwner, rtt::FrameGraphResource color,
                  const int (&view)[4])
        : ctx_(ctx), zOwner_(zOwner), color_(color) {
        for (int i = 0; i < 4; ++i) view_[i] = view[i];
    }
    void bindForDraw(fx::Target t) override {
        if (!ctx_.bindForDraw(map(t))) return;
        if (t.id == color_.id && view_[2] > 0) ctx_.setViewport(view_[0], view_[1], view_[2], view_[3]);
    }
    fx::TextureRef texture(fx::Target t, int attachment) override {
        if (t.id == FxFrameBuilder::kZBufferId) {
            fx::TextureRef ref;
            ref.name = zOwner_.valid() && attachment == 0 ? ctx_.depthTexture(zOwner_) : 0u;
            if (ref.name == 0) return fx::TextureRef{};
            ref.format = fx::TargetFormat::Depth;
            ref.width = width(t);
            ref.height = height(t);
            return ref;
        }
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
    /// The z-buffer's handle is its owner's size.
    rtt::FrameGraphResource map(fx::Target t) const {
        return t.id == FxFrameBuilder::kZBufferId ? zOwner_ : rtt::FrameGraphResource{t.id};
    }
    rtt::PassContext& ctx_;
    rtt::FrameGraphResource zOwner_, color_;
    int view_[4] = {0, 0, 0, 0};
};

rtt::ColorFormat toColorFormat(fx::TargetFormat f) {
    switch (f) {
        case fx::TargetFormat::RGBA8: return rtt::ColorFormat::RGBA8;
        case fx::TargetFormat::RGBA16F: return rtt::ColorFormat::RGBA16F;
        case fx::TargetFormat::R32F: return rtt::ColorFormat::R32F;
        case fx::TargetFormat::RG32F: return rtt::ColorFormat::RG32F;
        case fx::TargetFormat::Depth: break;  // not a target's format (sceneZBuffer's texture only)
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
    // Float depth: a plugin z-buffer holds depths computed for a reversed-Z host (the half-res
    // z-test); 32-bit float keeps them as precise as the host's own.
    r.depth = d.depth ? rtt::DepthFormat::Depth32F : rtt::DepthFormat::None;
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
    reads_.clear();
    writes_.clear();
    bool readsZ = false;
    for (fx::Target t : reads) {
        if (t.id == kZBufferId) {
            readsZ = zOwner_.valid();
            continue;
        }
        reads_.push_back(rtt::FrameGraphResource{t.id});
        readsDepth_ = readsDepth_ || t.id == depth_.id;
    }
    for (fx::Target t : writes) writes_.push_back(rtt::FrameGraphResource{t.id});
    const std::string passName = prefix_ + (name ? name : "fx_pass");
    const rtt::FrameGraphResource zOwner = zOwner_, color = color_;
    const int view[4] = {x_, y_, placed_ ? viewWidth_ : 0, viewHeight_};
    auto run = [execute = std::move(execute), zOwner, color, view](rtt::PassContext& ctx) {
        FxPassContext fxCtx(ctx, zOwner, color, view);
        execute(fxCtx);
    };
    if (!readsZ) {
        graph_.addPass(passName.c_str(), order_, reads_.data(), reads_.size(), writes_.data(), writes_.size(),
                       std::move(run));
        return;
    }
    // Sampling the z-buffer is a depth read of its owner: rtt keeps the owner's writers (the
    // opaque pass, or the depth prepass) and allocates that depth as a texture.
    graph_.addPass(passName.c_str(), order_,
                   [&](rtt::PassBuilder& b) {  // runs now
                       for (rtt::FrameGraphResource r : reads_) b.read(r);
                       b.readDepth(zOwner);
                       for (rtt::FrameGraphResource w : writes_) b.write(w);
                   },
                   std::move(run));
}

}  // namespace cube
