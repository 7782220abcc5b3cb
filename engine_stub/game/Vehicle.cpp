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
//  0-3   along +X at 15 m/s, moving over to z = 4 (near the barrier side), rolling
//  3-4   hard braking
//  4-9   burnout donut at z = 4: two turns about the front axle, rear wheels spinning; the
//        smoke spreads over the track and the kerb and reaches the barrier at z = 8.5
//  9-11  launch along +X with the rear wheels still slipping
//  11-16 drift right onto the kerb and grass and brush the barrier (car side at z = 8.4)
//  16-18 back to the track centre
namespace {

constexpr float kLane = 4.0f;          // z of the donut and the launch
constexpr float kBrush = 7.5f;         // z of the car centre while brushing the barrier
constexpr float kX3 = -60.0f + 45.0f;  // x at t = 3
constexpr float kX4 = kX3 + 7.5f;      // x at t = 4 (15 m/s to 0 over 1 s)
constexpr float kX11 = kX4 + 12.0f;    // x at t = 11

// Position on the path outside the donut (which turns in place).
glm::vec3 pathPoint(float t) {
    if (t < 3.0f) return {-60.0f + 15.0f * t, 0.0f, kLane * smoothstep01((t - 0.5f) / 2.5f)};
    if (t < 4.0f) {
        const float u = t - 3.0f;
        return {kX3 + 15.0f * u - 7.5f * u * u, 0.0f, kLane};
    }
    if (t < 11.0f) {
        const float u = std::max(0.0f, t - 9.0f);
        return {kX4 + 3.0f * u * u, 0.0f, kLane};
    }
    const float u = t - 11.0f;
    float z = kLane + (kBrush - kLane) * smoothstep01(u / 2.5f);
    if (t > 16.0f) z = kBrush * (1.0f - smoothstep01((t - 16.0f) / 2.0f));
    return {kX11 + 12.0f * u, 0.0f, z};
}

// Heading along the path's direction of travel (+Z is to the right, hence the minus).
float pathHeading(float t) {
    const float h = 1e-3f;
    const glm::vec3 d = pathPoint(t + h) - pathPoint(t - h);
    return (std::abs(d.x) + std::abs(d.z) < 1e-9f) ? 0.0f : -std::atan2(d.z, d.x);
}

}  // namespace

DrivePose Vehicle::scriptPose(double tIn) {
    double t = std::fmod(tIn, kLoopSeconds);
    if (t < 0.0) t += kLoopSeconds;
    const float tf = float(t);
    DrivePose p;
    if (tf >= 4.0f && tf < 9.0f) {
        const float u = (tf - 4.0f) / 5.0f;
        // Counter-clockwise seen from above: heading grows. Two full turns, smooth start/stop.
        p.heading = 4.0f * kPi * smoothstep01(u);
        p.position = aroundFrontAxle(glm::vec3(kX4 + kFrontAxle, 0.0f, kLane), p.heading);
        const float omega = 4.0f * kPi * 6.0f * u * (1.0f - u) / 5.0f;  // d heading / dt
        p.rearSlip = std::clamp(0.35f + omega / 4.0f, 0.0f, 1.0f);
        p.frontSlip = 0.1f;
        return p;
    }
    p.position = pathPoint(tf);
    p.heading = pathHeading(tf);
    if (tf < 3.0f) {
        p.rearSlip = p.frontSlip = 0.02f;
    } else if (tf < 4.0f) {
        p.rearSlip = 0.25f;
        p.frontSlip = 0.3f;
    } else if (tf < 11.0f) {
        p.rearSlip = std::max(0.05f, 0.9f - 0.4f * (tf - 9.0f));
        p.frontSlip = 0.03f;
    } else {
        p.rearSlip = 0.15f;
        p.frontSlip = 0.08f;
    }
    return p;
}

bool Vehicle::init(const SceneData& scene, std::string* error, const std::string& carNode,
                   std::string* warning) {
    const int car = scene.findNode(carNode);
    if (car < 0) {
        *error = "scene has no node named '" + carNode + "'";
        return false;
    }
    active_ = true;
    hasWheels_ = true;
    const glm::mat4 carInv = glm::inverse(scene.nodes[size_t(car)].world);
    wheelRadius_ = 0.33f;
    for (int i = 0; i < 4; ++i) {
        const int n = scene.findNode(kWheelNames[i]);
        if (n < 0 || !scene.isDescendant(n, car)) {
            hasWheels_ = false;
            if (warning)
                *warning = std::string("no wheel node '") + kWheelNames[i] + "' under '" + carNode +
                           "': the car drives, wheel reactions are off";
            wheelOffsets_ = {};
            wheelNodes_ = {{-1, -1, -1, -1}};
            break;
        }
        const SceneNode& node = scene.nodes[size_t(n)];
        const glm::mat4 inCar = carInv * node.world;
        glm::vec3 centre = glm::vec3(inCar[3]);
        wheelOffsets_[size_t(i)] = {centre.x, 0.0f, centre.z};  // contact patch below the hub
        wheelNodes_[size_t(i)] = n;
        wheelRestLocal_[size_t(i)] = node.local;
        wheelAxleLocal_[size_t(i)] = glm::normalize(glm::inverse(glm::mat3(inCar)) * glm::vec3(0.0f, 0.0f, 1.0f));
        if (i == 0 && !node.meshes.empty() && node.aabbMax.y > node.aabbMin.y)
            wheelRadius_ = 0.5f * (node.aabbMax.y - node.aabbMin.y);
    }
    for (int i = 0; i < 4; ++i) wheels_[size_t(i)].rear = i >= 2;
    tabulateRolling();
    return true;
}

// Contact patches along one loop: the distance each rolls along the car's forward axis between
// samples 5 ms apart (the heading at the middle of the step), summed. Linear interpolation
// between samples is then good to well under a millimetre (accelerations stay below 20 m/s^2).
void Vehicle::tabulateRolling() {
    constexpr int kSteps = int(kLoopSeconds * 200.0);
    const double h = kLoopSeconds / kSteps;
    auto contact = [&](const DrivePose& p, size_t w) {
        const glm::vec3 o = wheelOffsets_[w];
        const float c = std::cos(p.heading), s = std::sin(p.heading);
        // Rotation about +Y by the heading, as transform() applies it.
        return p.position + glm::vec3(c * o.x + s * o.z, 0.0f, -s * o.x + c * o.z);
    };
    // Sample at most a hair before the loop's end: scriptPose wraps at kLoopSeconds.
    auto at = [&](int k) { return scriptPose(std::min(k * h, kLoopSeconds - 1e-6)); };
    for (size_t w = 0; w < 4; ++w) {
        rolled_[w].assign(size_t(kSteps) + 1, 0.0);
        DrivePose a = at(0);
        for (int k = 0; k < kSteps; ++k) {
            const DrivePose b = at(k + 1), mid = scriptPose((k + 0.5) * h);
            const glm::vec3 fwd(std::cos(mid.heading), 0.0f, -std::sin(mid.heading));
            rolled_[w][size_t(k) + 1] = rolled_[w][size_t(k)] + double(glm::dot(contact(b, w) - contact(a, w), fwd));
            a = b;
        }
    }
}

double Vehicle::rolledDistance(int wheel, double t) const {
    const std::vector<double>& table = rolled_[size_t(wheel)];
    if (table.size() < 2 || !(t > 0.0)) return 0.0;
    const double loops = std::floor(t / kLoopSeconds);
    const double u = (t - loops * kLoopSeconds) / kLoopSeconds * double(table.size() - 1);
    const size_t k = std::min(size_t(u), table.size() - 2);
    const double f = u - double(k);
    return loops * table.back() + table[k] + f * (table[k + 1] - table[k]);
}

glm::mat4 Vehicle::wheelLocal(int i) const {
    return glm::rotate(wheelRestLocal_[size_t(i)], wheelSpin_[size_t(i)], wheelAxleLocal_[size_t(i)]);
}

glm::mat4 Vehicle::transform() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), pose_.position);
    return glm::rotate(m, pose_.heading, glm::vec3(0.0f, 1.0f, 0.0f));
}

void Vehicle::update(const SceneData& scene, double t, bool stationary) {
    if (!active_) {
        pose_ = DrivePose{};
        velocity_ = glm::vec3(0.0f);
        for (WheelState& w : wheels_) w = WheelState{w.contact, glm::vec3(0.0f), 0.0f, "", w.rear};
        collisionAmount_ = 0.0f;
        return;
    }
    pose_ = scriptPose(t);
    constexpr double h = 1.0 / 1000.0;  // central difference of the script, deterministic
    const DrivePose a = scriptPose(t - h), b = scriptPose(t + h);
    const bool wrapped = stationary || glm::length(b.position - a.position) > 1.0f;
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
        w.slip = !hasWheels_ ? 0.0f : w.rear ? pose_.rearSlip : pose_.frontSlip;
        w.surface = scene.surfaceAt(w.contact.x, w.contact.z);
        // Rolling forward turns the tyre's top toward +X: negative about the car's +Z.
        const double turns = rolledDistance(int(i), t) / double(wheelRadius_);
        wheelSpin_[i] = hasWheels_ ? -float(std::fmod(turns, 2.0 * 3.14159265358979323846)) : 0.0f;
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
