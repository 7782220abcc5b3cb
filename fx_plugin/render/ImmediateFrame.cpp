// The immediate path's frame graph: culling, pooled targets, the depth hook.
#include "ImmediateFrame.h"

#include <algorithm>
#include <cassert>
#include <cstdint>

#include "GlStateGuard.h"
#include "PrivateGl.h"

namespace fx {

class ImmediateFrame::Context final : public PassContext {
public:
    explicit Context(ImmediateFrame& f) : f_(f) {}
    void bindForDraw(Target t) override {
        const ImmediateFrameSetup& s = f_.setup_;
        if (t.id == kSceneColor) {
            glBindFramebuffer(GL_FRAMEBUFFER, s.hostFramebuffer);
            glViewport(s.viewportX, s.viewportY, s.width, s.height);
            if (s.hostScissor) {  // the host's clip holds for the plugin's draws into its framebuffer
                glEnable(GL_SCISSOR_TEST);
                glScissor(s.scissorBox[0], s.scissorBox[1], s.scissorBox[2], s.scissorBox[3]);
            }
            return;
        }
        const PooledTarget* p = f_.slotOf(t.id);
        assert(p && "bindForDraw: a target this pass did not declare, or the host's sceneDepth");
        if (!p) return;
        glBindFramebuffer(GL_FRAMEBUFFER, p->framebuffer);
        glViewport(0, 0, p->width, p->height);
    }
    TextureRef texture(Target t, int attachment) override {
        const ImmediateFrameSetup& s = f_.setup_;
        if (attachment != 0 || t.id == kSceneColor) return TextureRef{};  // the host's framebuffer: no texture
        if (t.id == kSceneDepth && s.hostLinearDepth) {
            return {s.hostLinearDepth, TargetFormat::R32F, s.linearWidth ? s.linearWidth : s.width,
                    s.linearHeight ? s.linearHeight : s.height};
        }
        if (t.id == kSceneZBuffer) {
            // The host's texture at its own size (the view's, or the framebuffer's with the view at
            // the viewport's origin); the plugin's copy is the view's rectangle.
            const bool host = s.hostZTexture != 0 && f_.zTexture_ == s.hostZTexture;
            return f_.zTexture_ ? TextureRef{f_.zTexture_, TargetFormat::Depth, host && s.zWidth ? s.zWidth : s.width,
                                             host && s.zHeight ? s.zHeight : s.height}
                                : TextureRef{};
        }
        const PooledTarget* p = f_.slotOf(t.id);
        if (!p) return TextureRef{};
        return {p->texture, p->desc.format, p->width, p->height};
    }
    int width(Target t) override {
        if (t.id == kSceneDepth || t.id == kSceneZBuffer) return texture(t, 0).valid() ? texture(t, 0).width : f_.setup_.width;
        const PooledTarget* p = t.id == kSceneColor ? nullptr : f_.slotOf(t.id);
        return p ? p->width : f_.setup_.width;
    }
    int height(Target t) override {
        if (t.id == kSceneDepth || t.id == kSceneZBuffer) return texture(t, 0).valid() ? texture(t, 0).height : f_.setup_.height;
        const PooledTarget* p = t.id == kSceneColor ? nullptr : f_.slotOf(t.id);
        return p ? p->height : f_.setup_.height;
    }

private:
    ImmediateFrame& f_;
};

ImmediateFrame::ImmediateFrame(ImmediateTargetPool& pool, ImmediateFrameSetup setup)
    : pool_(pool), setup_(std::move(setup)) {}

Target ImmediateFrame::createTarget(const char* name, const TargetDesc& desc) {
    created_.push_back(Created{name ? name : "", desc, SIZE_MAX});
    return Target{uint32_t(created_.size()) - 1 + kFirstCreated};
}

void ImmediateFrame::addPass(const char* name, std::initializer_list<Target> reads,
                             std::initializer_list<Target> writes, std::function<void(PassContext&)> execute) {
    Pass p;
    p.name = name ? name : "";
    for (Target t : reads) {
        if (t.valid()) p.reads.push_back(t.id);
    }
    for (Target t : writes) {
        if (t.valid()) p.writes.push_back(t.id);
    }
    p.run = std::move(execute);
    if (p.readsDepth(kSceneDepth) || p.readsDepth(kSceneZBuffer)) {
        p.depthRegion = nextRegion_;
        nextRegion_ = DepthRegion{};
    }
    passes_.push_back(std::move(p));
}

bool ImmediateFrame::Pass::readsDepth(uint32_t which) const {
    return std::find(reads.begin(), reads.end(), which) != reads.end();
}

const PooledTarget* ImmediateFrame::slotOf(uint32_t id) const {
    size_t slot = SIZE_MAX;
    if (id == kSceneDepth) {
        slot = depthSlot_;
    } else if (id >= kFirstCreated && id - kFirstCreated < created_.size()) {
        slot = created_[id - kFirstCreated].slot;
    }
    return slot == SIZE_MAX ? nullptr : &pool_.at(slot);
}

void ImmediateFrame::allocate(uint32_t id) {
    if (id == kSceneColor || id == kSceneZBuffer) return;  // the host's, or the copy hook's
    if (id == kSceneDepth) {
        if (setup_.hostLinearDepth || depthSlot_ != SIZE_MAX) return;
        TargetDesc d;
        d.format = TargetFormat::R32F;
        d.linearFilter = false;
        depthSlot_ = pool_.acquire(d, setup_.width, setup_.height);
        return;
    }
    if (id < kFirstCreated || id - kFirstCreated >= created_.size()) return;  // not a handle of this frame
    Created& c = created_[id - kFirstCreated];
    if (c.slot != SIZE_MAX) return;
    const int w = c.desc.width > 0 ? c.desc.width : std::max(1, int(float(setup_.width) * c.desc.scale));
    const int h = c.desc.height > 0 ? c.desc.height : std::max(1, int(float(setup_.height) * c.desc.scale));
    c.slot = pool_.acquire(c.desc, w, h);
}

void ImmediateFrame::execute() {
    // Cull: walk back from the presented target.
    std::vector<bool> alive(passes_.size(), false);
    std::vector<uint32_t> needed{kSceneColor};
    for (size_t k = passes_.size(); k-- > 0;) {
        const Pass& p = passes_[k];
        bool keep = false;
        for (uint32_t w : p.writes) keep = keep || std::find(needed.begin(), needed.end(), w) != needed.end();
        if (!keep) continue;
        alive[k] = true;
        needed.insert(needed.end(), p.reads.begin(), p.reads.end());
    }
    {
        GlStateGuard guard;  // allocation binds textures and framebuffers
        for (size_t k = 0; k < passes_.size(); ++k) {
            if (!alive[k]) continue;
            for (uint32_t r : passes_[k].reads) allocate(r);
            for (uint32_t w : passes_[k].writes) allocate(w);
        }
    }
    // The depth the running passes read: the union of their regions (whole if any reads it all).
    produced_ = DepthRegion{0, 0, 0, 0, false};
    bool anyReader = false;
    for (size_t k = 0; k < passes_.size(); ++k) {
        const Pass& p = passes_[k];
        if (!alive[k] || !(p.readsDepth(kSceneDepth) || p.readsDepth(kSceneZBuffer))) continue;
        const DepthRegion& r = p.depthRegion;
        if (r.whole || produced_.whole) {
            produced_ = DepthRegion{};
        } else if (!anyReader) {
            produced_ = r;
        } else {
            produced_.x0 = std::min(produced_.x0, r.x0);
            produced_.y0 = std::min(produced_.y0, r.y0);
            produced_.x1 = std::max(produced_.x1, r.x1);
            produced_.y1 = std::max(produced_.y1, r.y1);
        }
        anyReader = true;
    }
    if (!produced_.whole) {
        produced_.x0 = std::max(0, produced_.x0);
        produced_.y0 = std::max(0, produced_.y0);
        produced_.x1 = std::min(setup_.width, produced_.x1);
        produced_.y1 = std::min(setup_.height, produced_.y1);
        if (produced_.x0 == 0 && produced_.y0 == 0 && produced_.x1 == setup_.width && produced_.y1 == setup_.height) {
            produced_ = DepthRegion{};
        }
    }
    Context ctx(*this);
    for (size_t k = 0; k < passes_.size(); ++k) {
        if (!alive[k]) continue;
        Pass& p = passes_[k];
        if (p.readsDepth(kSceneDepth) && !depthReady_ && depthSlot_ != SIZE_MAX && setup_.produceDepth) {
            GlStateGuard guard;
            DebugGroup group("fx_linearize_depth");
            setup_.produceDepth(pool_.at(depthSlot_).framebuffer, produced_);
            depthReady_ = true;
        }
        if (p.readsDepth(kSceneZBuffer) && !zTexture_) {
            if (setup_.hostZTexture) {
                zTexture_ = setup_.hostZTexture;  // sampled in place
            } else if (setup_.copyZBuffer) {
                GlStateGuard guard;
                DebugGroup group("fx_copy_depth");
                zTexture_ = setup_.copyZBuffer(produced_);
            }
        }
        p.run(ctx);
        executed_.push_back(p.name);
    }
}

}  // namespace fx
