#pragma once
// The one header through which the plugin sees its host. A host (engine_stub, or any other engine)
// implements HostAdapter for the simulation side and FrameBuilder/PassContext for its
// render-to-texture layer, then drives the plugin through fx/Plugin.h (which states the order of
// calls, the GL context rules and the GL state the plugin touches).
#include <cstdint>
#include <functional>
#include <initializer_list>

#include "fx/Api.h"
#include "fx/Types.h"

namespace fx {

/// Valid only while a pass declared through FrameBuilder::addPass executes, on the thread that
/// runs the host's frame, with the host's GL context current.
class FX_API PassContext {
public:
    virtual ~PassContext() = default;
    /// Binds the target's framebuffer (GL_DRAW_FRAMEBUFFER) for drawing and sets the viewport to
    /// its size; for sceneColor, to the view's rectangle in it (ViewInfo::x, y, width, height;
    /// API 2.1). For sceneColor that framebuffer carries the scene's z-buffer as its depth
    /// attachment (ViewInfo::depth says its convention).
    virtual void bindForDraw(Target target) = 0;
    /// A colour attachment of a target (attachment 0 unless stated); TextureRef::name 0 when the
    /// target has no such attachment.
    virtual TextureRef texture(Target target, int attachment = 0) = 0;
    virtual int width(Target target) = 0;
    virtual int height(Target target) = 0;
};

/// The host's frame graph as the plugin sees it while declaring passes for one view.
/// Passes run in declaration order inside the host's particle bucket, after the opaque scene and
/// the sky; a pass whose writes no later pass reads is culled and its targets are never allocated.
class FX_API FrameBuilder {
public:
    virtual ~FrameBuilder() = default;
    /// The view's colour target (RGBA8 or better, ViewInfo::width x height, or targetWidth x
    /// targetHeight with the view at (x, y) in it: API 2.1) with the scene's z-buffer attached.
    /// A pass that writes it draws into the frame.
    virtual Target sceneColor() = 0;
    /// The scene depth. Contract:
    ///  - attachment 0: linear view-space depth, R32F, metres, positive (distance along -Z of
    ///    the view), ViewInfo::width x height (the view alone), or sceneColor's size with the
    ///    view at (ViewInfo::x, y) (API 2.1);
    ///  - where no geometry was drawn: any value >= ViewInfo::farPlane (engine_stub clears to
    ///    1e30), or 0; the plugin reads values <= 0 as "nothing drawn" too, so a host that clears
    ///    to 0 does not lose its smoke against the sky;
    ///  - it holds the opaque scene (everything particles may hide behind), complete before the
    ///    first plugin pass that reads it runs.
    /// Reading it is what makes the host produce it (a depth prepass, or a copy of the opaque
    /// pass's depth); a frame where no plugin pass reads it needs none.
    virtual Target sceneDepth() = 0;
    /// API 2.1. The z-buffer sceneColor draws on, holding the opaque scene, for passes that
    /// sample it instead of sceneDepth: a pass lists it among its reads (which is what makes the
    /// host keep its writers), and PassContext::texture(it) returns the depth texture
    /// (TargetFormat::Depth). The plugin samples it while sceneColor is bound with depth writes
    /// off, after a texture barrier; it never writes it. Target{} (the default): the host offers
    /// none, and the plugin reads sceneDepth, which the host must then produce. Offer it where its
    /// precision holds at the distances smoke is seen: a reversed-Z float z-buffer errs by about
    /// 6e-8 t at distance t; a standard 24-bit one by 3e-8 t^2 / near (30 cm at 1 km with near
    /// 0.1 m), where the linear R32F sceneDepth is exact.
    virtual Target sceneZBuffer() { return Target{}; }
    /// API 2.1. How that z-buffer was drawn: clip control and depth range (HostDepth's
    /// clipDepthZeroToOne, depthRangeNear, depthRangeFar; its source and texture are not read).
    /// With ViewInfo::proj this is all the plugin needs to turn it into metres.
    virtual HostDepth sceneZBufferMapping() { return HostDepth{}; }
    /// A transient target for this view's passes; TargetDesc's relative sizes follow the view.
    virtual Target createTarget(const char* name, const TargetDesc& desc) = 0;
    virtual void addPass(const char* name, std::initializer_list<Target> reads,
                         std::initializer_list<Target> writes,
                         std::function<void(PassContext&)> execute) = 0;
};

/// The simulation-side services of the host. Called on the thread that calls the plugin.
class FX_API HostAdapter {
public:
    virtual ~HostAdapter() = default;
    /// GL entry points of the host's context (the plugin's private loader fills its own table
    /// from this; it never uses a global loader). Must return non-null for the GL 3.3 core
    /// entry points while a context is current; may return null before one exists.
    virtual void* getProcAddress(const char* name) = 0;
    virtual int wheelCount() const = 0;
    virtual WheelContact wheel(int index) const = 0;
    /// Ambient wind at the car, m/s, world space.
    virtual glm::vec3 wind() const { return glm::vec3(0.0f); }
    /// Where the car last touched a wall, world space (meaningful while the collision amount > 0).
    virtual glm::vec3 collisionPoint() const { return glm::vec3(0.0f); }
    /// Messages from the plugin: load results, data errors ("file:line:col: error[Code] ..."),
    /// refused calls ("fx: error[Code] function: ...").
    virtual void log(LogLevel level, const char* message) = 0;
    /// API 2.2. One piece of the plugin's work, handed to parallelFor.
    using Task = void (*)(void* data, uint32_t index);
    /// API 2.2. The host's job system: calls task(data, i) once for every i in [0, count), on
    /// any of its threads, any number at once, and returns when every call has returned. A task
    /// touches no GL and calls nothing of the host's or the plugin's; it only reads and writes
    /// the plugin's own memory, in slices that do not overlap. The plugin asks for it while
    /// preparing a view (culling, sorting and bounding the particles), while its particle pass
    /// runs (copying the instances into the mapped vertex buffer) and in continueReaction
    /// (advancing the particles), only for work of thousands of particles and more, in at most
    /// kMaxTasks pieces; its results are the same bit for bit however the host runs them. The
    /// default runs them in order on the calling thread.
    static constexpr uint32_t kMaxTasks = 64;
    virtual void parallelFor(uint32_t count, Task task, void* data) {
        for (uint32_t i = 0; i < count; ++i) task(data, i);
    }
};

}  // namespace fx
