#pragma once
// Part of API 2's C++ layer (fx/detail/PluginBridge.h includes it; not a header to include
// yourself): the host's C++ frame graph (fx::FrameBuilder, fx::PassContext) seen as the C
// fxFrameBuilder / fxPassContext of fx/fx.h, for the duration of one declare call or one pass.
// Each pass the plugin adds becomes a std::function the host's graph owns; its last copy
// releases the plugin's pass (fxPassCallback::release), once.
#include <cstring>
#include <functional>
#include <memory>
#include <utility>

#include "fx/HostAdapter.h"
#include "fx/fx.h"

namespace fx {
namespace detail {

// The C++ layer compiles as C++11: there fx::Target (a default member initialiser) is not an
// aggregate, so `Target{id}` does not compile; this does under every standard.
inline Target targetFrom(uint32_t id) {
    Target t;
    t.id = id;
    return t;
}

// std::index_sequence is C++14; the same, for C++11.
template <size_t... I>
struct IndexSequence {};
template <size_t N, size_t... I>
struct MakeIndexSequence : MakeIndexSequence<N - 1, N - 1, I...> {};
template <size_t... I>
struct MakeIndexSequence<0, I...> {
    using type = IndexSequence<I...>;
};

// ---- the host's frame graph -------------------------------------------------------------------------

class PassContextBridge {
public:
    explicit PassContextBridge(PassContext& ctx) : ctx_(ctx), c_(fxDescInit_<fxPassContext>()) {
        c_.user = this;
        c_.bindForDraw = [](void* u, uint32_t t) { self(u).bindForDraw(targetFrom(t)); };
        c_.texture = [](void* u, uint32_t t, int attachment, fxTextureRef* out) {
            const TextureRef r = self(u).texture(targetFrom(t), attachment);
            out->name = r.name;
            out->format = static_cast<int>(r.format);
            out->width = r.width;
            out->height = r.height;
        };
        c_.width = [](void* u, uint32_t t) { return self(u).width(targetFrom(t)); };
        c_.height = [](void* u, uint32_t t) { return self(u).height(targetFrom(t)); };
    }
    const fxPassContext* c() const { return &c_; }

private:
    static PassContext& self(void* u) { return static_cast<PassContextBridge*>(u)->ctx_; }
    PassContext& ctx_;
    fxPassContext c_;
};

/// Owns one plugin pass on the host side: released once, when the host's graph drops the last
/// copy of the pass's std::function (after it ran, or culled).
struct PassHolder {
    explicit PassHolder(fxPassCallback cb) : callback(cb) {}
    ~PassHolder() {
        if (callback.release) callback.release(callback.user);
    }
    PassHolder(const PassHolder&) = delete;
    PassHolder& operator=(const PassHolder&) = delete;
    fxPassCallback callback;
};

// FrameBuilder::addPass takes initializer lists (1.x); a C pass has counted arrays. Each count
// up to these is spelled out once at compile time.
constexpr int kMaxPassReads = 8;
constexpr int kMaxPassWrites = 4;

template <size_t... R, size_t... W>
void addPassWith(FrameBuilder& f, const char* name, const uint32_t* reads, const uint32_t* writes,
                 std::function<void(PassContext&)>&& fn, IndexSequence<R...>, IndexSequence<W...>) {
    (void)reads;
    (void)writes;
    f.addPass(name, {targetFrom(reads[R])...}, {targetFrom(writes[W])...}, std::move(fn));
}

template <size_t NR>
void addPassReads(FrameBuilder& f, const char* name, const uint32_t* reads, const uint32_t* writes,
                  int writeCount, std::function<void(PassContext&)>&& fn) {
    using R = typename MakeIndexSequence<NR>::type;
    switch (writeCount) {
    case 0: addPassWith(f, name, reads, writes, std::move(fn), R{}, typename MakeIndexSequence<0>::type{}); break;
    case 1: addPassWith(f, name, reads, writes, std::move(fn), R{}, typename MakeIndexSequence<1>::type{}); break;
    case 2: addPassWith(f, name, reads, writes, std::move(fn), R{}, typename MakeIndexSequence<2>::type{}); break;
    case 3: addPassWith(f, name, reads, writes, std::move(fn), R{}, typename MakeIndexSequence<3>::type{}); break;
    default: addPassWith(f, name, reads, writes, std::move(fn), R{}, typename MakeIndexSequence<4>::type{}); break;
    }
}

class FrameBridge {
public:
    explicit FrameBridge(FrameBuilder& frame) : frame_(frame), c_(fxDescInit_<fxFrameBuilder>()) {
        c_.user = this;
        c_.sceneColor = [](void* u) { return self(u).sceneColor().id; };
        c_.sceneDepth = [](void* u) { return self(u).sceneDepth().id; };
        c_.createTarget = [](void* u, const char* name, const fxTargetDesc* d) {
            TargetDesc t;
            t.scale = d->scale == 0.0f ? 1.0f : d->scale;
            t.width = d->width;
            t.height = d->height;
            t.format = static_cast<TargetFormat>(d->format);
            t.linearFilter = d->nearestFilter == 0;
            t.depth = d->depth != 0;
            return self(u).createTarget(name, t).id;
        };
        c_.addPass = &FrameBridge::addPass;
        c_.sceneZBuffer = [](void* u) { return self(u).sceneZBuffer().id; };
        const HostDepth mapping = frame.sceneZBufferMapping();
        c_.zBufferClipZeroToOne = mapping.clipDepthZeroToOne ? 1 : 0;
        c_.zBufferRangeNear = mapping.depthRangeNear;
        c_.zBufferRangeFar = mapping.depthRangeFar;
    }
    const fxFrameBuilder* c() const { return &c_; }

private:
    static FrameBuilder& self(void* u) { return static_cast<FrameBridge*>(u)->frame_; }
    static void addPass(void* u, const char* name, const uint32_t* reads, int readCount,
                        const uint32_t* writes, int writeCount, fxPassCallback callback) {
        auto holder = std::make_shared<PassHolder>(callback);
        if (readCount < 0 || readCount > kMaxPassReads || writeCount < 0 || writeCount > kMaxPassWrites) {
            return;  // the plugin never declares more (its own check refuses first); released here
        }
        std::function<void(PassContext&)> fn = [holder](PassContext& ctx) {
            PassContextBridge bridge(ctx);
            holder->callback.run(holder->callback.user, bridge.c());
        };
        FrameBuilder& f = self(u);
        switch (readCount) {
        case 0: addPassReads<0>(f, name, reads, writes, writeCount, std::move(fn)); break;
        case 1: addPassReads<1>(f, name, reads, writes, writeCount, std::move(fn)); break;
        case 2: addPassReads<2>(f, name, reads, writes, writeCount, std::move(fn)); break;
        case 3: addPassReads<3>(f, name, reads, writes, writeCount, std::move(fn)); break;
        case 4: addPassReads<4>(f, name, reads, writes, writeCount, std::move(fn)); break;
        case 5: addPassReads<5>(f, name, reads, writes, writeCount, std::move(fn)); break;
        case 6: addPassReads<6>(f, name, reads, writes, writeCount, std::move(fn)); break;
        case 7: addPassReads<7>(f, name, reads, writes, writeCount, std::move(fn)); break;
        default: addPassReads<8>(f, name, reads, writes, writeCount, std::move(fn)); break;
        }
    }
    FrameBuilder& frame_;
    fxFrameBuilder c_;
};

}  // namespace detail
}  // namespace fx
