#pragma once
// engine_stub's side of the plugin boundary: the simulation services of fx::HostAdapter,
// fed from the scripted vehicle, and the engine's job system for the plugin's parallel work.
// (The render side, fx::FrameBuilder, is in game/FxFrameBuilder.)
#include <string>

#include "fx/HostAdapter.h"

namespace cube {

class Vehicle;
class Platform;
class JobSystem;

class EngineFxHost final : public fx::HostAdapter {
public:
    /// None of the three is owned; each must outlive the host. Null `jobs`: parallelFor runs
    /// every task in order on the calling thread (fx::HostAdapter's default).
    EngineFxHost(const Vehicle* vehicle, const Platform* platform, JobSystem* jobs = nullptr)
        : vehicle_(vehicle), platform_(platform), jobs_(jobs) {}
    void* getProcAddress(const char* name) override;
    int wheelCount() const override { return 4; }
    fx::WheelContact wheel(int index) const override;
    glm::vec3 wind() const override { return glm::vec3(1.2f, 0.0f, 0.4f); }
    glm::vec3 collisionPoint() const override;
    void log(fx::LogLevel level, const char* message) override;
    void parallelFor(uint32_t count, Task task, void* data) override;

    static fx::Surface surfaceFromTag(const std::string& tag);

private:
    const Vehicle* vehicle_;
    const Platform* platform_;
    JobSystem* jobs_;
};

}  // namespace cube
