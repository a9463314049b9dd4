// Kind `orbit`: each robot circles, counter-clockwise, the point radius_m to
// the left of where it starts. A whole controller plugin: one Robot subclass
// and one line naming it (docs/writing-a-controller.md).
#include <cmath>
#include <optional>

#include "dream/agent_host/controller_plugin.h"
#include "dream/agents/geometry/single_integrator_to_unicycle.h"

class OrbitRobot final : public dream::agents::Robot {
 public:
  // Reads its own keys of the `controller:` section; errors name file:line:key.
  OrbitRobot(int id, const dream::agents::RobotParams& params, const dream::config::ConfigNode& section)
      : Robot(id, params),
        radius_m_(section.GetDouble("radius_m", 0.25)),
        speed_mps_(section.GetDouble("speed_mps", 0.1)) {
    if (radius_m_ <= 0.0) section.FailAt("radius_m", "must be > 0");
    if (speed_mps_ <= 0.0) section.FailAt("speed_mps", "must be > 0");
  }

  dream::agents::UnicycleCommand Update(int64_t /*step*/) override {
    if (!has_odometry()) return {};  // knows nothing yet: hold still
    const Eigen::Vector2d position_m = pose().head<2>();
    const Eigen::Vector2d left(-std::sin(pose().z()), std::cos(pose().z()));
    if (!center_m_) center_m_ = position_m + radius_m_ * left;  // the first fix places the circle
    const Eigen::Vector2d outward = (position_m - *center_m_).normalized();
    const Eigen::Vector2d along(-outward.y(), outward.x());
    const double radius_error_m = radius_m_ - (position_m - *center_m_).norm();
    const Eigen::Vector2d velocity_mps = speed_mps_ * along + kRadialGain * radius_error_m * outward;
    return LimitActuators(si_to_uni_.Map(velocity_mps, pose().z()));
  }

 private:
  static constexpr double kRadialGain = 2.0;  // 1/s: how hard a robot is pulled back onto its circle
  double radius_m_;
  double speed_mps_;
  std::optional<Eigen::Vector2d> center_m_;
  dream::agents::SingleIntegratorToUnicycle si_to_uni_;
};

// The plugin's entry points: kind `orbit`, its robot class, and its keys
// besides the common robot, sensors and radio (any other key is an error).
DREAM_REGISTER_ROBOT("orbit", OrbitRobot, {"radius_m", "speed_mps"})
