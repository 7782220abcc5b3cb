#pragma once
// The scripted car: a deterministic drive (a straight, a braking burnout/donut where the rear
// wheels spin, then a brush along the barrier) so every run and every fxbench mode sees the same
// frames. The pose is a pure function of time; velocities come from the same function.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/WheelState.h"

namespace cube {

struct SceneData;

/// Script pose at time t (seconds): car centre on the ground plane, heading (radians about +Y,
/// 0 = facing +X) and the slip of the rear and front wheels.
struct DrivePose {
    glm::vec3 position{0.0f};
    float heading = 0.0f;
    float rearSlip = 0.0f;
    float frontSlip = 0.0f;
};

class Vehicle {
public:
    static constexpr double kLoopSeconds = 18.0;
    static const char* const kWheelNames[4];  ///< wheel_FL, wheel_FR, wheel_RL, wheel_RR

    /// Reads the wheel offsets from the subtree of the node named `carNode`. False + error when
    /// that node is absent. Wheels (kWheelNames) missing under it: `*warning` says so, the car
    /// still drives and its wheels never slip (no wheel reactions).
    bool init(const SceneData& scene, std::string* error, const std::string& carNode = "car",
              std::string* warning = nullptr);
    /// A scene without a car: the pose stays at the origin, nothing slips or collides.
    void disable() { active_ = false; }
    bool active() const { return active_; }
    /// Moves to script time t (seconds, wraps every kLoopSeconds) and refreshes wheels and collision.
    /// `stationary`: the car holds the pose of time t with zero velocity (wheels still slip).
    void update(const SceneData& scene, double t, bool stationary = false);

    static DrivePose scriptPose(double t);

    glm::mat4 transform() const;
    const DrivePose& pose() const { return pose_; }
    glm::vec3 velocity() const { return velocity_; }
    const std::array<WheelState, 4>& wheels() const { return wheels_; }
    /// The scene node of wheel i (kWheelNames order), or -1 when the car has no wheels.
    int wheelNode(int i) const { return hasWheels_ && active_ ? wheelNodes_[size_t(i)] : -1; }
    /// Rolling radius (m): half the height of wheel_FL's box in the scene; 0.33 without one.
    float wheelRadius() const { return wheelRadius_; }
    /// Radians wheel i has turned about its axle, the car's +Z (right-hand rule), at the current
    /// time: minus the distance its contact patch has rolled along the car's forward axis since
    /// t = 0, over wheelRadius(), wrapped to (-2 pi, 2 pi). Rolling forward makes it decrease
    /// (the tyre's top moves toward the car's front, +X).
    /// A pure function of time like the pose (tabulated per loop at init), so it does not depend
    /// on the step sizes. Slip is not modelled: a spinning rear wheel turns at its rolling rate.
    float wheelSpin(int i) const { return wheelSpin_[size_t(i)]; }
    /// Wheel i's local transform (relative to its parent node) turned by wheelSpin(i) about its
    /// axle: the car's side axis (+Z) through the node's origin, the hub.
    glm::mat4 wheelLocal(int i) const;

    /// 0..1: how hard the car body presses into a solid (barrier, tyres) this step.
    float collisionAmount() const { return collisionAmount_; }
    glm::vec3 collisionPoint() const { return collisionPoint_; }

private:
    void tabulateRolling();
    double rolledDistance(int wheel, double t) const;

    std::array<glm::vec3, 4> wheelOffsets_{};  ///< car-local contact points
    std::array<int, 4> wheelNodes_{{-1, -1, -1, -1}};
    std::array<glm::mat4, 4> wheelRestLocal_{};
    std::array<glm::vec3, 4> wheelAxleLocal_{};  ///< the car's +Z in each wheel node's frame
    std::array<float, 4> wheelSpin_{};
    float wheelRadius_ = 0.33f;
    /// Distance each wheel has rolled (m, signed along the car's forward axis) at
    /// t = k * kLoopSeconds / (rolled_[w].size() - 1) into a loop, from the loop's start.
    std::array<std::vector<double>, 4> rolled_;
    bool active_ = true;
    bool hasWheels_ = true;
    DrivePose pose_;
    glm::vec3 velocity_{0.0f};
    std::array<WheelState, 4> wheels_{};
    float collisionAmount_ = 0.0f;
    glm::vec3 collisionPoint_{0.0f};
};

}  // namespace cube
