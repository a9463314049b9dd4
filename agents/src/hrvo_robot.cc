#include "dream/agents/hrvo/hrvo_robot.h"

#include <stdexcept>

#include "dream/agents/hrvo/hrvo_exact.h"
#include "dream/agents/hrvo/hrvo_thesis.h"

namespace dream::agents {
namespace {

std::unique_ptr<HrvoAvoidance> MakeHrvo(const HrvoRobotParams& params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument(error);
  if (params.variant == HrvoVariant::kThesis) return std::make_unique<HrvoThesis>(params.hrvo);
  return std::make_unique<HrvoExact>(params.hrvo);
}

UnicycleWallGuardParams WallGuardParams(const HrvoParams& hrvo) {
  UnicycleWallGuardParams guard;
  guard.arena_min_m = Eigen::Vector2d(hrvo.x_min_m, hrvo.y_min_m);
  guard.arena_max_m = Eigen::Vector2d(hrvo.x_max_m, hrvo.y_max_m);
  guard.horizon_s = hrvo.boundary_horizon_s;
  return guard;
}

}  // namespace

HrvoRobot::HrvoRobot(int id, const RobotParams& robot_params, const HrvoRobotParams& params)
    : Robot(id, robot_params),
      hrvo_(MakeHrvo(params)),
      guard_walls_(params.hrvo.check_boundaries),
      wall_guard_(WallGuardParams(params.hrvo)) {}

Eigen::Vector2d HrvoRobot::AvoidCollisions(const Eigen::Vector2d& preferred_mps) {
  neighbours_.clear();
  for (const NeighbourDetection& detection : movement().neighbours) {
    neighbours_.push_back({detection.RelativePosition(), detection.velocity_mps});
  }
  dxi_mps_ = hrvo_->SafeVelocity(pose().head<2>(), dxi_mps_, preferred_mps, neighbours_);
  return dxi_mps_;
}

UnicycleCommand HrvoRobot::DriveWithVelocity(const Eigen::Vector2d& preferred_mps) {
  const UnicycleCommand command = LimitActuators(DxiToDxu(AvoidCollisions(preferred_mps)));
  return guard_walls_ ? wall_guard_.Apply(pose(), command) : command;
}

}  // namespace dream::agents
