#include "game/EngineFxHost.h"

#include <cstdio>

#include "game/JobSystem.h"
#include "game/Vehicle.h"
#include "platform/Platform.h"

namespace cube {

fx::Surface EngineFxHost::surfaceFromTag(const std::string& tag) {
    if (tag == "asphalt") return fx::Surface::Asphalt;
    if (tag == "kerb") return fx::Surface::Kerb;
    if (tag == "gravel") return fx::Surface::Gravel;
    if (tag == "sand") return fx::Surface::Sand;
    return fx::Surface::Grass;  // grass and off the map
}

void* EngineFxHost::getProcAddress(const char* name) {
    return platform_ ? platform_->getProcAddress(name) : nullptr;
}

fx::WheelContact EngineFxHost::wheel(int index) const {
    fx::WheelContact c;
    if (index < 0 || index >= 4 || !vehicle_) return c;
    const WheelState& w = vehicle_->wheels()[size_t(index)];
    c.position = w.contact;
    c.velocity = w.velocity;
    c.slip = w.slip;
    c.surface = surfaceFromTag(w.surface);
    c.grounded = true;
    c.rear = w.rear;
    return c;
}

glm::vec3 EngineFxHost::collisionPoint() const {
    return vehicle_ ? vehicle_->collisionPoint() : glm::vec3(0.0f);
}

void EngineFxHost::log(fx::LogLevel level, const char* message) {
    const char* tag = level == fx::LogLevel::Error ? "error" : level == fx::LogLevel::Warning ? "warning" : "info";
    std::fprintf(stderr, "fx %s: %s\n", tag, message);
}

void EngineFxHost::parallelFor(uint32_t count, Task task, void* data) {
    if (jobs_) {
        jobs_->parallelFor(count, task, data);
    } else {
        fx::HostAdapter::parallelFor(count, task, data);
    }
}

}  // namespace cube
