#pragma once
// The library side of the C boundary: the host's C callbacks and frame graph (fx/fx.h) seen as
// the plugin's own C++ interfaces (fx/HostAdapter.h), so everything behind fxGetApi is written
// against one set of types. The mirror image, for C++ hosts, is fx/detail/PluginBridge.h.
#include <string>

#include "fx/HostAdapter.h"
#include "fx/fx.h"
#include "../base/ApiErrors.h"

namespace fx {

/// fxHostCallbacks (copied at creation) as a HostAdapter.
class CHostAdapter final : public HostAdapter {
public:
    /// `c`: read up to its size (a 2.0/2.1 host's ends before parallelFor, which stays null).
    /// `up`: the host world's up axis; every vector read from the callbacks is turned into the
    /// plugin's Y-up world (WorldBasis.h).
    explicit CHostAdapter(const fxHostCallbacks& c, UpAxis up = UpAxis::Y) : c_(c), up_(up) {}
    void* getProcAddress(const char* name) override { return c_.getProcAddress(c_.user, name); }
    // Each callback optional on its own: both are needed for any wheel.
    int wheelCount() const override { return c_.wheelCount && c_.wheel ? c_.wheelCount(c_.user) : 0; }
    WheelContact wheel(int index) const override;
    glm::vec3 wind() const override;
    glm::vec3 collisionPoint() const override;
    void log(LogLevel level, const char* message) override { c_.log(c_.user, static_cast<int>(level), message); }
    void parallelFor(uint32_t count, Task task, void* data) override {
        if (c_.parallelFor) {
            c_.parallelFor(c_.user, count, task, data);
        } else {
            HostAdapter::parallelFor(count, task, data);
        }
    }

private:
    fxHostCallbacks c_;
    UpAxis up_;
};

/// fxPassContext as a PassContext, for the duration of one pass.
class CPassContext final : public PassContext {
public:
    explicit CPassContext(const fxPassContext& c) : c_(c) {}
    void bindForDraw(Target target) override { c_.bindForDraw(c_.user, target.id); }
    TextureRef texture(Target target, int attachment) override;
    int width(Target target) override { return c_.width(c_.user, target.id); }
    int height(Target target) override { return c_.height(c_.user, target.id); }

private:
    const fxPassContext& c_;
};

/// fxFrameBuilder as a FrameBuilder, for the duration of one declare call. Each pass's
/// std::function moves to the heap and is handed to the host as an fxPassCallback, deleted by
/// its release().
class CFrameBuilder final : public FrameBuilder {
public:
    CFrameBuilder(const fxFrameBuilder& c, ApiErrors& errors) : c_(c), errors_(errors) {}
    Target sceneColor() override { return Target{c_.sceneColor(c_.user)}; }
    Target sceneDepth() override { return Target{c_.sceneDepth(c_.user)}; }
    Target sceneZBuffer() override;
    HostDepth sceneZBufferMapping() override;
    Target createTarget(const char* name, const TargetDesc& desc) override;
    void addPass(const char* name, std::initializer_list<Target> reads, std::initializer_list<Target> writes,
                 std::function<void(PassContext&)> execute) override;

private:
    const fxFrameBuilder& c_;
    ApiErrors& errors_;
};

/// "" when `f` can be used, else what is wrong with it.
std::string frameBuilderProblem(const fxFrameBuilder* f);


/// The view as the plugin draws it: right-handed (a left-handed pair becomes view' = F view,
/// proj' = proj F with F = diag(1, 1, -1, 1): the same clip coordinates, camera down -Z).
ViewInfo rightHandedView(const fxViewDesc& v, UpAxis up = UpAxis::Y);

}  // namespace fx
