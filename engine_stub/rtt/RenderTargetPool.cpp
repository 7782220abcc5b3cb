#include "rtt/RenderTargetPool.h"

#include <algorithm>
#include <cstring>

#include "gl/Gl.h"
#include "rtt/GlFormat.h"

namespace cube::rtt {

namespace {

// Bindings object creation changes; restored on scope exit so the pool never leaks state.
class SavedBindings {
public:
    SavedBindings() {
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
        glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer_);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
        glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_);
        // A bound unpack buffer would turn glTexImage2D's null pointer into offset 0 of it.
        if (unpack_) glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    }
    ~SavedBindings() {
        glBindTexture(GL_TEXTURE_2D, GLuint(texture_));
        glBindRenderbuffer(GL_RENDERBUFFER, GLuint(renderbuffer_));
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_));
        if (unpack_) glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(unpack_));
    }
    SavedBindings(const SavedBindings&) = delete;
    SavedBindings& operator=(const SavedBindings&) = delete;

private:
    GLint texture_ = 0, renderbuffer_ = 0, draw_ = 0, read_ = 0, unpack_ = 0;
};

int limitOr(int requested, int driver) { return requested > 0 && requested < driver ? requested : driver; }

// The one normal form targets are matched in: fields that do not apply are reset.
RenderTargetDesc normalise(const RenderTargetDesc& in) {
    RenderTargetDesc d = in;
    if (isRelative(d)) {
        d.width = d.height = 0;
    } else {
        d.scale = 1.0f;
    }
    if (d.depth == DepthFormat::None) d.sampledDepth = false;
    d.sharedDepth = {};  // matched through the owner's slot index instead
    d.name = "";
    return d;
}

bool sameShape(const RenderTargetDesc& a, const RenderTargetDesc& b) {
    return sameSizeRule(a, b) && a.color == b.color && a.depth == b.depth &&
           a.sampledDepth == b.sampledDepth && a.filter == b.filter && a.wrap == b.wrap;
}

void label(GLenum kind, GLuint object, const std::string& name, const char* suffix) {
    if (!gl::hasDebug() || name.empty() || object == 0) return;
    const std::string text = name + suffix;
    glObjectLabel(kind, object, GLsizei(text.size()), text.c_str());
}

}  // namespace

RenderTargetPool::RenderTargetPool(const RenderTargetPoolDesc& desc)
    : framesUntilFree_(desc.framesUntilFree > 0 ? desc.framesUntilFree : 1) {
    GLint maxTex = 0, maxRb = 0, maxAttach = 0, maxDraw = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTex);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRb);
    glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &maxAttach);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDraw);
    limits_.maxTextureSize = limitOr(desc.maxTextureSize, maxTex);
    limits_.maxRenderbufferSize = limitOr(desc.maxRenderbufferSize, maxRb);
    limits_.maxColorAttachments =
        limitOr(desc.maxColorAttachments, std::min({int(maxAttach), int(maxDraw), kMaxColorAttachments}));
}

RenderTargetPool::~RenderTargetPool() {
    // Sharers first, so owners are no longer pinned.
    for (size_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].state != State::Empty && slots_[i].sharedDepthSlot >= 0) destroy(int(i));
    for (size_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].state != State::Empty) destroy(int(i));
}

RttError RenderTargetPool::fail(RttError error, RttError* out, std::string message) {
    lastError_ = std::move(message);
    if (out) *out = error;
    return error;
}

const RenderTargetPool::Slot* RenderTargetPool::live(RenderTargetHandle handle) const {
    if (!handle.valid() || handle.index >= slots_.size()) return nullptr;
    const Slot& s = slots_[handle.index];
    return s.state == State::InUse && s.generation == handle.generation ? &s : nullptr;
}

bool RenderTargetPool::isValid(RenderTargetHandle handle) const { return live(handle) != nullptr; }

RenderTargetHandle RenderTargetPool::acquire(const RenderTargetDesc& desc, RttError* error) {
    if (error) *error = RttError::None;
    std::string message;
    if (RttError e = validateDesc(desc, limits_, &message); e != RttError::None) {
        fail(e, error, std::move(message));
        return {};
    }
    const char* name = desc.name ? desc.name : "";
    int sharedSlot = -1;
    if (desc.sharedDepth.valid()) {
        const Slot* owner = live(desc.sharedDepth);
        if (!owner || owner->desc.depth == DepthFormat::None) {
            fail(RttError::SharedDepthInvalid, error,
                 std::string("'") + name + "': sharedDepth " +
                     (owner ? "names a target without a depth attachment of its own"
                            : "is a stale or unknown handle") +
                     ": expected a live target that owns its depth");
            return {};
        }
        if (!sameSizeRule(desc, owner->desc)) {
            fail(RttError::SharedDepthSizeMismatch, error,
                 std::string("'") + name + "': sharedDepth target '" + owner->name +
                     "' has a different size or sizing rule: expected identical width/height/scale");
            return {};
        }
        sharedSlot = int(desc.sharedDepth.index);
    }

    const RenderTargetDesc key = normalise(desc);
    int index = -1;
    for (size_t i = 0; i < slots_.size(); ++i) {
        const Slot& s = slots_[i];
        if (s.state == State::Free && s.sharedDepthSlot == sharedSlot && sameShape(s.desc, key)) {
            index = int(i);
            break;
        }
    }
    if (index < 0) {
        int w = 0, h = 0;
        resolveSize(key, viewWidth_, viewHeight_, std::min(limits_.maxTextureSize, limits_.maxRenderbufferSize),
                    &w, &h);
        if (RttError e = create(key, name, sharedSlot, w, h, &index); e != RttError::None) {
            if (error) *error = e;
            return {};
        }
    }
    Slot& s = slots_[size_t(index)];
    s.state = State::InUse;
    s.lastUsedFrame = frame_;
    if (s.name != name) {
        s.name.assign(name);
        label(GL_FRAMEBUFFER, s.fbo, s.name, "");
    }
    s.desc.name = s.name.c_str();
    return {uint32_t(index), s.generation};
}

RttError RenderTargetPool::create(const RenderTargetDesc& desc, const char* name, int sharedDepthSlot,
                                  int width, int height, int* slotIndex) {
    int index;
    if (!emptySlots_.empty()) {
        index = emptySlots_.back();
        emptySlots_.pop_back();
    } else {
        index = int(slots_.size());
        slots_.emplace_back();
        // Growing moved the slots, and with them short names stored inside std::string.
        for (Slot& moved : slots_) moved.desc.name = moved.name.c_str();
    }
    Slot& s = slots_[size_t(index)];
    s.desc = desc;
    s.sharedDepthSlot = sharedDepthSlot;
    s.dependents = 0;
    s.width = width;
    s.height = height;
    s.state = State::Free;  // becomes InUse in acquire; counted by destroy() if we fail below

    SavedBindings saved;
    glGenFramebuffers(1, &s.fbo);
    ++liveFramebuffers_;
    const int colors = colorAttachmentCount(desc);
    for (int i = 0; i < colors; ++i) {
        glGenTextures(1, &s.color[i]);
        ++liveTextures_;
    }
    if (desc.depth != DepthFormat::None) {
        if (desc.sampledDepth) {
            glGenTextures(1, &s.depthTexture);
            ++liveTextures_;
        } else {
            glGenRenderbuffers(1, &s.depthRenderbuffer);
            ++liveRenderbuffers_;
        }
    }
    allocateStorage(s);

    glBindFramebuffer(GL_FRAMEBUFFER, s.fbo);  // draw and read: glReadBuffer sets the read FBO
    GLenum drawBuffers[kMaxColorAttachments];
    for (int i = 0; i < colors; ++i) {
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D,
                               s.color[i], 0);
        drawBuffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    }
    const Slot* owner = sharedDepthSlot >= 0 ? &slots_[size_t(sharedDepthSlot)] : &s;
    const GlFormat depth = glFormat(owner->desc.depth);
    if (owner->depthTexture)
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, depth.attachment, GL_TEXTURE_2D, owner->depthTexture, 0);
    else if (owner->depthRenderbuffer)
        glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, depth.attachment, GL_RENDERBUFFER,
                                  owner->depthRenderbuffer);
    // Depth-only targets need NONE draw/read buffers to be complete on GL 3.3.
    if (colors > 0) {
        glDrawBuffers(colors, drawBuffers);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
    } else {
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
    }
    if (sharedDepthSlot >= 0) ++slots_[size_t(sharedDepthSlot)].dependents;

    const char* statusName = "";
    RttError e = rttErrorFromFramebufferStatus(glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER), &statusName);
    std::string message;
    if (e != RttError::None) message = statusName;
    if (e == RttError::None && gl::checkErrors("RenderTargetPool::create") > 0) {
        e = RttError::AllocationFailed;
        message = "GL error while allocating (see gl::lastError(): " + gl::lastError() + ")";
    }
    if (e == RttError::None && injectedFailure_ != RttError::None) {
        e = injectedFailure_;
        message = "injected by failNextCreateForTesting";
    }
    injectedFailure_ = RttError::None;
    if (e != RttError::None) {
        std::string what = std::string("'") + name + "' " + std::to_string(width) +
                           "x" + std::to_string(height) + " colour";
        for (int i = 0; i < colors; ++i) what += std::string(" ") + colorFormatName(desc.color[size_t(i)]);
        what += std::string(", depth ") + depthFormatName(owner->desc.depth) + ": " + message;
        destroy(index);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);  // restored by `saved` right after
        fail(e, nullptr, std::move(what));
        return e;
    }
    s.name.assign(name);
    label(GL_FRAMEBUFFER, s.fbo, s.name, "");
    static const char* const kColorSuffix[kMaxColorAttachments] = {".color0", ".color1", ".color2", ".color3"};
    for (int i = 0; i < colors; ++i) label(GL_TEXTURE, s.color[i], s.name, kColorSuffix[i]);
    label(GL_TEXTURE, s.depthTexture, s.name, ".depth");
    label(GL_RENDERBUFFER, s.depthRenderbuffer, s.name, ".depth");
    ++totalAllocations_;
    ++allocationsThisFrame_;
    *slotIndex = index;
    return RttError::None;
}

void RenderTargetPool::allocateStorage(Slot& s) {
    const GLint filter = s.desc.filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR;
    const GLint wrap = s.desc.wrap == Wrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    auto texture = [&](GLuint tex, const GlFormat& f) {
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        glTexImage2D(GL_TEXTURE_2D, 0, GLint(f.internalFormat), s.width, s.height, 0, f.format, f.type,
                     nullptr);
    };
    for (int i = 0; i < kMaxColorAttachments; ++i)
        if (s.color[i]) texture(s.color[i], glFormat(s.desc.color[size_t(i)]));
    if (s.depthTexture) texture(s.depthTexture, glFormat(s.desc.depth));
    if (s.depthRenderbuffer) {
        glBindRenderbuffer(GL_RENDERBUFFER, s.depthRenderbuffer);
        glRenderbufferStorage(GL_RENDERBUFFER, glFormat(s.desc.depth).internalFormat, s.width, s.height);
    }
}

void RenderTargetPool::destroy(int index) {
    Slot& s = slots_[size_t(index)];
    if (s.fbo) {
        glDeleteFramebuffers(1, &s.fbo);
        --liveFramebuffers_;
    }
    for (GLuint& tex : s.color) {
        if (tex) {
            glDeleteTextures(1, &tex);
            --liveTextures_;
        }
        tex = 0;
    }
    if (s.depthTexture) {
        glDeleteTextures(1, &s.depthTexture);
        --liveTextures_;
    }
    if (s.depthRenderbuffer) {
        glDeleteRenderbuffers(1, &s.depthRenderbuffer);
        --liveRenderbuffers_;
    }
    if (s.sharedDepthSlot >= 0) --slots_[size_t(s.sharedDepthSlot)].dependents;
    s.fbo = s.depthTexture = s.depthRenderbuffer = 0;
    s.sharedDepthSlot = -1;
    s.state = State::Empty;
    if (++s.generation == 0) s.generation = 1;
    emptySlots_.push_back(index);
}

RttError RenderTargetPool::release(RenderTargetHandle handle) {
    if (!live(handle)) {
        lastError_ = "release: stale or unknown handle";
        return RttError::InvalidHandle;
    }
    Slot& s = slots_[handle.index];
    s.state = State::Free;
    s.lastUsedFrame = frame_;
    if (++s.generation == 0) s.generation = 1;
    return RttError::None;
}

void RenderTargetPool::setViewSize(int width, int height) {
    width = std::max(width, 0);
    height = std::max(height, 0);
    if (width == viewWidth_ && height == viewHeight_) return;
    viewWidth_ = width;
    viewHeight_ = height;
    const int maxSize = std::min(limits_.maxTextureSize, limits_.maxRenderbufferSize);
    SavedBindings saved;
    for (Slot& s : slots_) {
        if (s.state == State::Empty || !isRelative(s.desc)) continue;
        int w = 0, h = 0;
        resolveSize(s.desc, viewWidth_, viewHeight_, maxSize, &w, &h);
        if (w == s.width && h == s.height) continue;
        s.width = w;
        s.height = h;
        allocateStorage(s);  // same texture/renderbuffer names: FBO attachments and sharers stay valid
        ++reallocations_;
    }
}

void RenderTargetPool::beginFrame() {
    ++frame_;
    allocationsThisFrame_ = 0;
}

void RenderTargetPool::endFrame() {
    auto stale = [&](const Slot& s) {
        return s.state == State::Free && s.dependents == 0 && frame_ - s.lastUsedFrame >= uint64_t(framesUntilFree_);
    };
    // Sharers first: destroying them unpins their depth owners in the same call.
    for (size_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].sharedDepthSlot >= 0 && stale(slots_[i])) destroy(int(i));
    for (size_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].sharedDepthSlot < 0 && stale(slots_[i])) destroy(int(i));
}

void RenderTargetPool::trim() {
    for (size_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].state == State::Free && slots_[i].sharedDepthSlot >= 0) destroy(int(i));
    for (size_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].state == State::Free && slots_[i].dependents == 0) destroy(int(i));
}

int RenderTargetPool::width(RenderTargetHandle handle) const {
    const Slot* s = live(handle);
    return s ? s->width : 0;
}

int RenderTargetPool::height(RenderTargetHandle handle) const {
    const Slot* s = live(handle);
    return s ? s->height : 0;
}

const RenderTargetDesc* RenderTargetPool::desc(RenderTargetHandle handle) const {
    const Slot* s = live(handle);
    return s ? &s->desc : nullptr;
}

uint32_t RenderTargetPool::framebuffer(RenderTargetHandle handle) const {
    const Slot* s = live(handle);
    return s ? s->fbo : 0;
}

uint32_t RenderTargetPool::colorTexture(RenderTargetHandle handle, int index) const {
    const Slot* s = live(handle);
    return s && index >= 0 && index < kMaxColorAttachments ? s->color[index] : 0;
}

uint32_t RenderTargetPool::depthTexture(RenderTargetHandle handle) const {
    const Slot* s = live(handle);
    if (!s) return 0;
    if (s->sharedDepthSlot >= 0) s = &slots_[size_t(s->sharedDepthSlot)];
    return s->depthTexture;
}

DepthFormat RenderTargetPool::depthFormat(RenderTargetHandle handle) const {
    const Slot* s = live(handle);
    if (!s) return DepthFormat::None;
    if (s->sharedDepthSlot >= 0) s = &slots_[size_t(s->sharedDepthSlot)];
    return s->desc.depth;
}

RenderTargetPoolStats RenderTargetPool::stats() const {
    RenderTargetPoolStats st;
    for (const Slot& s : slots_) {
        if (s.state == State::InUse) ++st.targetsInUse;
        if (s.state == State::Free) ++st.targetsFree;
    }
    st.liveTextures = liveTextures_;
    st.liveRenderbuffers = liveRenderbuffers_;
    st.liveFramebuffers = liveFramebuffers_;
    st.totalAllocations = totalAllocations_;
    st.reallocations = reallocations_;
    st.allocationsThisFrame = allocationsThisFrame_;
    st.frame = frame_;
    return st;
}

}  // namespace cube::rtt
