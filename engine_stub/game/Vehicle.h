#pragma once
// The scripted car: a deterministic drive (a straight, a braking burnout/donut where the rear
// wheels spin, then a brush along the barrier) so every run and every fxbench mode sees the same
// frames. The pose is a pure function of time; velocities come from the same function.
#include <array>
#include <string>

#include <glm/glm.hpp>

namespace cube {

struct SceneData;

struct WheelState {
    glm::vec3 contact{0.0f};   ///< contact patch, world space
    glm::vec3 velocity{0.0f};  ///< m/s, world space
    float slip = 0.0f;         ///< 0 rolling .. 1 spinning
    std::string surface;       ///< from the scene's ground tags ("" off the map)
    bool rear = false;
};

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
    /// 0..1: how hard the car body presses into a solid (barrier, tyres) this step.
    float collisionAmount() const { return collisionAmount_; }
    glm::vec3 collisionPoint() const { return collisionPoint_; }

private:
    std::array<glm::vec3, 4> wheelOffsets_{};  ///< car-local contact points
    bool active_ = true;
    bool hasWheels_ = true;
    DrivePose pose_;
    glm::vec3 velocity_{0.0f};
    std::array<WheelState, 4> wheels_{};
    float collisionAmount_ = 0.0f;
    glm::vec3 collisionPoint_{0.0f};
};

}  // namespace cube
