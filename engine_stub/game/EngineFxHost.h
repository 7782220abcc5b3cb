#pragma once
// engine_stub's side of the plugin boundary: the simulation services of fx::HostAdapter,
// fed from the scripted vehicle. (The render side, fx::FrameBuilder, is in game/FxFrameBuilder.)
#include <string>

#include "fx/HostAdapter.h"

namespace cube {

class Vehicle;
class Platform;

class EngineFxHost final : public fx::HostAdapter {
public:
    EngineFxHost(const Vehicle* vehicle, const Platform* platform) : vehicle_(vehicle), platform_(platform) {}
    void* getProcAddress(const char* name) override;
    int wheelCount() const override { return 4; }
    fx::WheelContact wheel(int index) const override;
    glm::vec3 wind() const override { return glm::vec3(1.2f, 0.0f, 0.4f); }
    glm::vec3 collisionPoint() const override;
    void log(fx::LogLevel level, const char* message) override;

    static fx::Surface surfaceFromTag(const std::string& tag);

private:
    const Vehicle* vehicle_;
    const Platform* platform_;
};

}  // namespace cube
