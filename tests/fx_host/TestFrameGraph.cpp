// The fx_host's render-to-texture layer: fx::FrameBuilder / fx::PassContext over plain FBOs.
#include <glad/gl.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "FxTestHost.h"

namespace fxtest {

namespace {

GLenum internalFormat(fx::TargetFormat f) {
    switch (f) {
    case fx::TargetFormat::RGBA8: return GL_RGBA8;
    case fx::TargetFormat::RGBA16F: return GL_RGBA16F;
    case fx::TargetFormat::R32F: return GL_R32F;
    case fx::TargetFormat::RG32F: return GL_RG32F;
    case fx::TargetFormat::Depth: break;  // sceneZBuffer's texture only, never a target's
    }
    return GL_RGBA8;
}

// A new 2D texture filtered with `filter` both ways, left bound for the caller to allocate.
GLuint boundTexture(GLint filter) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    return t;
}

GLuint makeTexture(GLenum format, int w, int h, bool linear) {
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);  // a null upload must not read from a host PBO
    const GLuint t = boundTexture(linear ? GL_LINEAR : GL_NEAREST);
    const bool isFloat = format == GL_R32F || format == GL_RG32F || format == GL_RGBA16F;
    const GLenum layout = format == GL_R32F ? GL_RED : format == GL_RG32F ? GL_RG : GL_RGBA;
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), w, h, 0, layout, isFloat ? GL_FLOAT : GL_UNSIGNED_BYTE,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

GLuint makeDepthBuffer(int w, int h, bool floatDepth) {
    GLuint rb = 0;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, floatDepth ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    return rb;
}

GLuint makeDepthTexture(int w, int h, bool floatDepth) {
    const GLuint t = boundTexture(GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, floatDepth ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24, w, h, 0,
                 GL_DEPTH_COMPONENT, floatDepth ? GL_FLOAT : GL_UNSIGNED_INT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

GLuint makeFramebuffer(GLuint colour, GLuint depth, GLuint depthTexture = 0) {
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    if (depth) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (depthTexture) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depthTexture, 0);
    assert(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return fbo;
}

}  // namespace

class TestFrameGraph::Context final : public fx::PassContext {
public:
    explicit Context(TestFrameGraph& g) : g_(g) {}
    const std::string* pass = nullptr;  ///< the pass running (TestFrameGraph::drew)
    void bindForDraw(fx::Target t) override {
        if (pass && (g_.drew_.empty() || g_.drew_.back() != *pass)) g_.drew_.push_back(*pass);
        if (t.id == kSceneColor) {
            glBindFramebuffer(GL_FRAMEBUFFER, g_.colorFbo_);
            glViewport(0, 0, g_.width_, g_.height_);
        } else if (t.id == kSceneDepth) {
            glBindFramebuffer(GL_FRAMEBUFFER, g_.depthFbo_);
            glViewport(0, 0, g_.width_, g_.height_);
        } else {
            TargetSlot* s = g_.slotFor(t.id);
            assert(s && "bindForDraw: a target this pass did not declare");
            glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
            glViewport(0, 0, s->width, s->height);
        }
    }
    fx::TextureRef texture(fx::Target t, int) override {
        if (t.id == kSceneColor) return {g_.colorTex_, fx::TargetFormat::RGBA8, g_.width_, g_.height_};
        if (t.id == kSceneDepth) return {g_.depthTex_, fx::TargetFormat::R32F, g_.width_, g_.height_};
        if (t.id == kSceneZBuffer) return {g_.zBufferTex_, fx::TargetFormat::Depth, g_.width_, g_.height_};
        TargetSlot* s = g_.slotFor(t.id);
        if (!s) return fx::TextureRef{};
        return {s->texture, s->desc.format, s->width, s->height};
    }
    int width(fx::Target t) override {
        TargetSlot* s = t.id > kSceneDepth ? g_.slotFor(t.id) : nullptr;
        return s ? s->width : g_.width_;
    }
    int height(fx::Target t) override {
        TargetSlot* s = t.id > kSceneDepth ? g_.slotFor(t.id) : nullptr;
        return s ? s->height : g_.height_;
    }

private:
    TestFrameGraph& g_;
};

TestFrameGraph::TestFrameGraph(int width, int height, bool floatDepth, bool zBuffer)
    : width_(width), height_(height) {
    colorTex_ = makeTexture(GL_RGBA8, width, height, true);
    if (zBuffer) {
        zBufferTex_ = makeDepthTexture(width, height, floatDepth);
        zMapping_.clipDepthZeroToOne = floatDepth;
    } else {
        colorDepth_ = makeDepthBuffer(width, height, floatDepth);
    }
    colorFbo_ = makeFramebuffer(colorTex_, colorDepth_, zBufferTex_);
    depthTex_ = makeTexture(GL_R32F, width, height, false);
    depthDepth_ = makeDepthBuffer(width, height, floatDepth);
    depthFbo_ = makeFramebuffer(depthTex_, depthDepth_);
}

TestFrameGraph::~TestFrameGraph() {
    for (TargetSlot& s : pool_) {
        glDeleteFramebuffers(1, &s.framebuffer);
        glDeleteTextures(1, &s.texture);
        if (s.depth) glDeleteRenderbuffers(1, &s.depth);
    }
    glDeleteFramebuffers(1, &colorFbo_);
    glDeleteFramebuffers(1, &depthFbo_);
    glDeleteTextures(1, &colorTex_);
    glDeleteTextures(1, &depthTex_);
    if (colorDepth_) glDeleteRenderbuffers(1, &colorDepth_);
    if (zBufferTex_) glDeleteTextures(1, &zBufferTex_);
    glDeleteRenderbuffers(1, &depthDepth_);
}

void TestFrameGraph::beginFrame() {
    passes_.clear();
    frameTargets_.clear();
    created_.clear();
    declared_.clear();
    executed_.clear();
    drew_.clear();
    stateMismatches_.clear();
    for (TargetSlot& s : pool_) s.inUse = false;
    targetsCreated_ = targetsAllocated_ = 0;
    sceneDepthUsed_ = false;
    zBufferUsed_ = false;
    pluginPasses_ = false;
}

fx::Target TestFrameGraph::createTarget(const char* name, const fx::TargetDesc& desc) {
    ++targetsCreated_;
    created_.emplace_back(name ? name : "", desc);
    return fx::Target{uint32_t(created_.size()) + kSceneDepth};
}

void TestFrameGraph::addPass(const char* name, std::initializer_list<fx::Target> reads,
                             std::initializer_list<fx::Target> writes,
                             std::function<void(fx::PassContext&)> execute) {
    Pass p;
    p.name = name ? name : "";
    for (fx::Target t : reads) p.reads.push_back(t.id);
    for (fx::Target t : writes) p.writes.push_back(t.id);
    p.execute = std::move(execute);
    p.plugin = pluginPasses_;
    declared_.push_back(p.name);
    passes_.push_back(std::move(p));
}

bool TestFrameGraph::ran(const std::string& pass) const {
    return std::find(executed_.begin(), executed_.end(), pass) != executed_.end();
}

bool TestFrameGraph::drewIn(const std::string& pass) const {
    return std::find(drew_.begin(), drew_.end(), pass) != drew_.end();
}

std::vector<std::string> TestFrameGraph::allocatedTargetNames() const {
    std::vector<std::string> names;
    for (const auto& [id, slot] : frameTargets_) names.push_back(pool_[slot].name);
    return names;
}

TestFrameGraph::TargetSlot* TestFrameGraph::slotFor(uint32_t id) {
    auto it = frameTargets_.find(id);
    return it == frameTargets_.end() ? nullptr : &pool_[it->second];
}

void TestFrameGraph::allocate(uint32_t id) {
    if (id == kSceneDepth) sceneDepthUsed_ = true;
    if (id == kSceneZBuffer) zBufferUsed_ = true;
    if (id == kSceneZBuffer) return;
    if (id <= kSceneDepth || frameTargets_.count(id)) return;
    const auto& [name, desc] = created_[id - kSceneDepth - 1];
    const auto relative = [&](int size) {
        const float exact = float(size) * desc.scale;
        return std::max(1, int(roundSizesUp ? std::ceil(exact) : exact));
    };
    const int w = desc.width > 0 ? desc.width : relative(width_);
    const int h = desc.height > 0 ? desc.height : relative(height_);
    size_t slot = pool_.size();
    for (size_t i = 0; i < pool_.size(); ++i) {
        const TargetSlot& s = pool_[i];
        if (!s.inUse && s.width == w && s.height == h && s.desc.format == desc.format &&
            s.desc.linearFilter == desc.linearFilter && s.desc.depth == desc.depth) {
            slot = i;
            break;
        }
    }
    if (slot == pool_.size()) {
        TargetSlot s;
        s.desc = desc;
        s.width = w;
        s.height = h;
        s.texture = makeTexture(internalFormat(desc.format), w, h, desc.linearFilter);
        if (desc.depth) s.depth = makeDepthBuffer(w, h, true);  // a z-buffer of its own, float
        s.framebuffer = makeFramebuffer(s.texture, s.depth);
        pool_.push_back(s);
    }
    pool_[slot].name = name;
    pool_[slot].inUse = true;
    frameTargets_[id] = slot;
    ++targetsAllocated_;
}

void TestFrameGraph::execute() {
    // Cull: walk back from the presented target.
    std::vector<bool> alive(passes_.size(), false);
    std::vector<uint32_t> needed{kSceneColor};
    for (size_t k = passes_.size(); k-- > 0;) {
        const Pass& p = passes_[k];
        bool keep = false;
        for (uint32_t w : p.writes) {
            keep = keep || std::find(needed.begin(), needed.end(), w) != needed.end();
        }
        if (!keep) continue;
        alive[k] = true;
        for (uint32_t r : p.reads) needed.push_back(r);
    }
    for (size_t k = 0; k < passes_.size(); ++k) {
        if (!alive[k]) continue;
        for (uint32_t r : passes_[k].reads) allocate(r);
        for (uint32_t w : passes_[k].writes) allocate(w);
    }
    Context ctx(*this);
    for (size_t k = 0; k < passes_.size(); ++k) {
        if (!alive[k]) continue;
        Pass& p = passes_[k];
        if (p.plugin && skipPluginPass && skipPluginPass(p.name)) continue;
        const bool check = p.plugin && checkPluginState;
        if (p.plugin && beforePluginPass) beforePluginPass();
        GlStateSnapshot before;
        if (check) before = captureGlState();
        ctx.pass = p.plugin ? &p.name : nullptr;
        p.execute(ctx);
        ctx.pass = nullptr;
        if (p.plugin && afterPluginPass) afterPluginPass(p.name);
        drainGlErrors(p.name.c_str());
        if (check) {
            const std::string d = before.diff(captureGlState());
            if (!d.empty()) stateMismatches_.push_back(p.name + ": " + d);
        }
        executed_.push_back(p.name);
    }
}

void TestFrameGraph::setSceneDepthSampling(int minFilter, int magFilter, int maxLevel) {
    glBindTexture(GL_TEXTURE_2D, depthTex_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, magFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, maxLevel);
    glBindTexture(GL_TEXTURE_2D, 0);
}

Image TestFrameGraph::readColor() const { return readFramebuffer(colorFbo_, width_, height_); }

std::vector<float> TestFrameGraph::readLinearDepth() const {
    std::vector<float> depth(size_t(width_) * size_t(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, depthFbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RED, GL_FLOAT, depth.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return depth;
}

std::vector<float> TestFrameGraph::readTarget(const std::string& name, int* width, int* height) const {
    for (const auto& [id, index] : frameTargets_) {
        const TargetSlot& slot = pool_[index];
        if (slot.name != name) continue;
        std::vector<float> rgba(size_t(slot.width) * size_t(slot.height) * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, slot.framebuffer);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, slot.width, slot.height, GL_RGBA, GL_FLOAT, rgba.data());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        *width = slot.width;
        *height = slot.height;
        return rgba;
    }
    return {};
}

}  // namespace fxtest
