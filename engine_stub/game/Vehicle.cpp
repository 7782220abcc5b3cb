#include "game/Vehicle.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/SceneData.h"

namespace cube {

const char* const Vehicle::kWheelNames[4] = {"wheel_FL", "wheel_FR", "wheel_RL", "wheel_RR"};

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kFrontAxle = 1.35f;

float smoothstep01(float u) {
    u = std::clamp(u, 0.0f, 1.0f);
    return u * u * (3.0f - 2.0f * u);
}

// Heading of a car at `pos` rotating about a pivot so that its front axle stays on the pivot.
glm::vec3 aroundFrontAxle(glm::vec3 pivot, float heading) {
    return pivot - kFrontAxle * glm::vec3(std::cos(heading), 0.0f, -std::sin(heading));
}

}  // namespace

// The drive, in phases (times in seconds within one loop):
//  0-3   straight along +X at 15 m/s, rolling
//  3-4   hard braking
//  4-9   burnout donut: two turns about the front axle, rear wheels spinning
//  9-11  launch along +X with the rear wheels still slipping
//  11-16 drift right onto the kerb and grass and brush the barrier at z = 8.5
//  16-18 back to the track centre
DrivePose Vehicle::scriptPose(double tIn) {
    double t = std::fmod(tIn, kLoopSeconds);
    if (t < 0.0) t += kLoopSeconds;
    const float tf = float(t);
    DrivePose p;
    const float x3 = -60.0f + 15.0f * 3.0f;            // -15 at t=3
    const float x4 = x3 + 15.0f * 1.0f - 7.5f * 1.0f;  // -7.5 at t=4 (15 m/s to 0 over 1 s)
    if (tf < 3.0f) {
        p.position = {-60.0f + 15.0f * tf, 0.0f, 0.0f};
        p.rearSlip = p.frontSlip = 0.02f;
    } else if (tf < 4.0f) {
        const float u = tf - 3.0f;
        p.position = {x3 + 15.0f * u - 7.5f * u * u, 0.0f, 0.0f};
        p.rearSlip = 0.25f;
        p.frontSlip = 0.3f;
    } else if (tf < 9.0f) {
        const float u = (tf - 4.0f) / 5.0f;
        // Counter-clockwise seen from above: heading grows. Two full turns, smooth start/stop.
        p.heading = 4.0f * kPi * smoothstep01(u);
        const glm::vec3 pivot{x4 + kFrontAxle, 0.0f, 0.0f};
        p.position = aroundFrontAxle(pivot, p.heading);
        const float omega = 4.0f * kPi * 6.0f * u * (1.0f - u) / 5.0f;  // d heading / dt
        p.rearSlip = std::clamp(0.35f + omega / 4.0f, 0.0f, 1.0f);
        p.frontSlip = 0.1f;
    } else if (tf < 11.0f) {
        const float u = tf - 9.0f;
        p.position = {x4 + 3.0f * u * u, 0.0f, 0.0f};
        p.rearSlip = std::max(0.05f, 0.9f - 0.4f * u);
        p.frontSlip = 0.03f;
    } else {
        const float x11 = x4 + 12.0f;
        const float u = tf - 11.0f;
        float z = 7.5f * smoothstep01(u / 2.5f);
        if (tf > 16.0f) z = 7.5f * (1.0f - smoothstep01((tf - 16.0f) / 2.0f));
        p.position = {x11 + 12.0f * u, 0.0f, z};
        // Heading follows the path's direction (dz/dx), negative because +Z is to the right.
        const float dt = 1e-3f;
        float z2 = 7.5f * smoothstep01((u + dt) / 2.5f);
        if (tf + dt > 16.0f) z2 = 7.5f * (1.0f - smoothstep01((tf + dt - 16.0f) / 2.0f));
        p.heading = -std::atan2(z2 - z, 12.0f * dt);
        p.rearSlip = 0.15f;
        p.frontSlip = 0.08f;
    }
    return p;
}

bool Vehicle::init(const SceneData& scene, std::string* error) {
    const int car = scene.findNode("car");
    if (car < 0) {
        *error = "scene has no node named 'car'";
        return false;
    }
    const glm::mat4 carInv = glm::inverse(scene.nodes[size_t(car)].world);
    for (int i = 0; i < 4; ++i) {
        const int n = scene.findNode(kWheelNames[i]);
        if (n < 0 || !scene.isDescendant(n, car)) {
            *error = std::string("scene has no wheel node '") + kWheelNames[i] + "' under 'car'";
            return false;
        }
        glm::vec3 centre = glm::vec3(carInv * scene.nodes[size_t(n)].world[3]);
        wheelOffsets_[size_t(i)] = {centre.x, 0.0f, centre.z};  // contact patch below the hub
        wheels_[size_t(i)].rear = i >= 2;
    }
    return true;
}

glm::mat4 Vehicle::transform() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), pose_.position);
    return glm::rotate(m, pose_.heading, glm::vec3(0.0f, 1.0f, 0.0f));
}

void Vehicle::update(const SceneData& scene, double t) {
    pose_ = scriptPose(t);
    constexpr double h = 1.0 / 1000.0;  // central difference of the script, deterministic
    const DrivePose a = scriptPose(t - h), b = scriptPose(t + h);
    const bool wrapped = glm::length(b.position - a.position) > 1.0f;
    velocity_ = wrapped ? glm::vec3(0.0f) : (b.position - a.position) / float(2.0 * h);
    // Headings are compared modulo a turn: the donut ends at 4*pi, the next phase starts at 0.
    const float dHeading = std::remainder(b.heading - a.heading, 2.0f * kPi);
    const float omega = wrapped ? 0.0f : dHeading / float(2.0 * h);
    const glm::mat4 m = transform();
    for (size_t i = 0; i < 4; ++i) {
        WheelState& w = wheels_[i];
        w.contact = glm::vec3(m * glm::vec4(wheelOffsets_[i], 1.0f));
        const glm::vec3 r = w.contact - pose_.position;
        w.velocity = velocity_ + glm::cross(glm::vec3(0.0f, omega, 0.0f), r);
        w.slip = w.rear ? pose_.rearSlip : pose_.frontSlip;
        w.surface = scene.surfaceAt(w.contact.x, w.contact.z);
    }
    // Body corners and side midpoints at bumper height against solid nodes.
    collisionAmount_ = 0.0f;
    constexpr float kProbeRadius = 0.2f;
    const glm::vec3 probes[] = {{2.2f, 0.5f, 0.9f}, {0.0f, 0.5f, 0.9f}, {-2.2f, 0.5f, 0.9f},
                                {2.2f, 0.5f, -0.9f}, {0.0f, 0.5f, -0.9f}, {-2.2f, 0.5f, -0.9f}};
    for (const glm::vec3& local : probes) {
        const glm::vec3 c = glm::vec3(m * glm::vec4(local, 1.0f));
        int node = -1;
        const float depth = scene.penetrationDepth(c, kProbeRadius, &node);
        const float amount = std::clamp(depth / kProbeRadius, 0.0f, 1.0f);
        if (amount > collisionAmount_) {
            collisionAmount_ = amount;
            collisionPoint_ = c;
        }
    }
}

}  // namespace cube
