#pragma once
// The one header through which the plugin sees its host. A host (engine_stub, or any other engine)
// implements HostAdapter for the simulation side and FrameBuilder/PassContext for its
// render-to-texture layer, then drives the plugin through fx/Plugin.h.
#include <functional>
#include <initializer_list>

#include "fx/Types.h"

namespace fx {

/// Valid only while a pass declared through FrameBuilder::addPass executes.
class PassContext {
public:
    virtual ~PassContext() = default;
    /// Binds the target's framebuffer for drawing and sets the viewport to its size.
    virtual void bindForDraw(Target target) = 0;
    /// GL texture name of a colour attachment (attachment 0 unless stated) of a target.
    virtual uint32_t texture(Target target, int attachment = 0) = 0;
    virtual int width(Target target) = 0;
    virtual int height(Target target) = 0;
};

/// The host's frame graph as the plugin sees it while declaring passes for one view.
/// Passes run in declaration order inside the host's particle bucket; a pass whose writes no
/// later pass reads is culled and its targets are never allocated.
class FrameBuilder {
public:
    virtual ~FrameBuilder() = default;
    /// The view's colour target with its z-buffer. A pass that writes it draws into the frame.
    virtual Target sceneColor() = 0;
    /// Linear view-space depth (R32F, attachment 0, metres, positive) plus the scene z-buffer.
    /// Reading it is what makes the host run its depth prepass; nobody reading it means no prepass.
    virtual Target sceneDepth() = 0;
    virtual Target createTarget(const char* name, const TargetDesc& desc) = 0;
    virtual void addPass(const char* name, std::initializer_list<Target> reads,
                         std::initializer_list<Target> writes,
                         std::function<void(PassContext&)> execute) = 0;
};

/// The simulation-side services of the host.
class HostAdapter {
public:
    virtual ~HostAdapter() = default;
    /// GL entry points, for a plugin that loads GL itself (may return null when the host shares its loader).
    virtual void* getProcAddress(const char* name) = 0;
    virtual int wheelCount() const = 0;
    virtual WheelContact wheel(int index) const = 0;
    /// Ambient wind at the car, m/s, world space.
    virtual glm::vec3 wind() const { return glm::vec3(0.0f); }
    /// Where the car last touched a wall, world space (meaningful while the collision amount > 0).
    virtual glm::vec3 collisionPoint() const { return glm::vec3(0.0f); }
    virtual void log(LogLevel level, const char* message) = 0;
};

}  // namespace fx
