#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "dream/agents/fields/field_rule.h"
#include "dream/agents/hrvo/hrvo_avoidance.h"
#include "dream/agents/hrvo/hrvo_params.h"
#include "dream/agents/framework/robot.h"
#include "dream/agents/geometry/unicycle_wall_guard.h"

namespace dream::agents {

/// Which HRVO a robot uses.
enum class HrvoVariant {
  kExact,   ///< HrvoExact: the exact closest safe velocity (default)
  kThesis,  ///< HrvoThesis: the thesis's 201-sample search, for comparison
};

struct HrvoRobotParams {
  HrvoVariant variant = HrvoVariant::kExact;
  HrvoParams hrvo;
  bool IsValid(std::string* error) const { return hrvo.IsValid(error); }
  /// The keys of a config's `hrvo:` section, once for reading, checking and the docs.
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Choice("variant", variant, {{"exact", HrvoVariant::kExact}, {"thesis", HrvoVariant::kThesis}},
                  "HRVO variant");
    fields.Number("safety_radius_m", hrvo.safety_radius_m, FieldRule::AboveUpTo(0.0, 10.0),
                  "centre distance HRVO keeps between robots, m");
    fields.Flag("check_boundaries", hrvo.check_boundaries, "refuse velocities that would leave the arena ...");
    fields.Number("boundary_horizon_s", hrvo.boundary_horizon_s, FieldRule::AboveUpTo(0.0, 100.0),
                  "... within this long, s");
  }
};

/// The thesis's Robot_hrvo: a Robot whose controllers ask for a planar
/// velocity and get the closest collision-free one, given the neighbours its
/// movement sensor reports, then drive it through dxi_to_dxu and the
/// actuator limits.
class HrvoRobot : public Robot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  HrvoRobot(int id, const RobotParams& robot_params, const HrvoRobotParams& params);

 protected:
  /// The safe velocity closest to `preferred_mps` (world frame, m/s) given the
  /// latest movement reading; it becomes the robot's current velocity.
  Eigen::Vector2d AvoidCollisions(const Eigen::Vector2d& preferred_mps);

  /// AvoidCollisions, then the thesis's dxi_to_dxu and actuator_limit, then
  /// (with the arena check on) UnicycleWallGuard, so the heading's swing
  /// towards a new velocity cannot carry the robot over a wall.
  UnicycleCommand DriveWithVelocity(const Eigen::Vector2d& preferred_mps);

  /// The last safe velocity chosen (the thesis's dxi).
  const Eigen::Vector2d& dxi() const { return dxi_mps_; }

 private:
  std::unique_ptr<HrvoAvoidance> hrvo_;
  bool guard_walls_;
  UnicycleWallGuard wall_guard_;
  Eigen::Vector2d dxi_mps_ = Eigen::Vector2d::Zero();
  std::vector<HrvoNeighbour> neighbours_;  // scratch
};

}  // namespace dream::agents
