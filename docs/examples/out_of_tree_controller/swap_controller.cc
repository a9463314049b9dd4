// Kind `swap`: each robot drives to the point opposite its start through the
// arena's centre while HRVO keeps it clear of the others. A whole one-class
// plugin with collision avoidance: the robot derives from HrvoRobot, whose
// `hrvo:` keys ReadHrvoRobotParams reads, and it needs a movement sensor
// (swap.yaml configures one). done() tells the world it has arrived.
#include <optional>

#include "dream/agent_host/controller_plugin.h"
#include "dream/kind_api/hrvo_config.h"
#include "dream/agents/hrvo/hrvo_robot.h"

class SwapRobot final : public dream::agents::HrvoRobot {
 public:
  SwapRobot(int id, const dream::agents::RobotParams& params, const dream::config::ConfigNode& section)
      : HrvoRobot(id, params, dream::kind_api::ReadHrvoRobotParams(section)),
        speed_mps_(section.GetDouble("speed_mps", 0.15)),
        tolerance_m_(section.GetDouble("tolerance_m", 0.03)) {
    if (speed_mps_ <= 0.0) section.FailAt("speed_mps", "must be > 0");
    if (tolerance_m_ <= 0.0) section.FailAt("tolerance_m", "must be > 0");
  }

  dream::agents::UnicycleCommand Update(int64_t /*step*/) override {
    if (!has_odometry()) return {};             // knows nothing yet: hold still
    if (!goal_m_) goal_m_ = -pose().head<2>();  // the first fix: the point opposite
    const Eigen::Vector2d error_m = *goal_m_ - pose().head<2>();
    done_ = error_m.norm() <= tolerance_m_;
    if (done_) return {};
    // Head for the goal at speed_mps, slowing down over its last 10 cm; HRVO
    // then picks the closest velocity that keeps clear of the neighbours.
    const Eigen::Vector2d preferred_mps = speed_mps_ * std::min(1.0, error_m.norm() / 0.1) * error_m.normalized();
    return DriveWithVelocity(preferred_mps);
  }

  // The run ends early (stop_when_done) once every robot's done() is true.
  bool done() const override { return done_; }

 private:
  double speed_mps_;
  double tolerance_m_;
  std::optional<Eigen::Vector2d> goal_m_;
  bool done_ = false;
};

DREAM_REGISTER_ROBOT("swap", SwapRobot, {"speed_mps", "tolerance_m", "hrvo"})
