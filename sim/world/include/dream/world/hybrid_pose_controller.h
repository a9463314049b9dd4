#pragma once

#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/unicycle_command.h"

namespace dream::world {

// rps V2's two-phase pose controller (rps/utilities/controllers.py
// create_pose_controller_hybrid) with the gains its start-up drive uses
// (robotarium.py initialize()): approach the goal point through the
// single-integrator-to-unicycle map, then turn on the spot.
//
// Like rps's closure it keeps one "approaching" flag per robot between calls,
// and forgets them (all approaching again) whenever it is called with a
// different number of robots than last time. The start-up drive calls it for
// all robots and for single robots in turn, so that reset is part of the
// drive's behaviour, and is kept here on purpose.
class HybridPoseController {
 public:
  struct Gains {
    double linear_velocity_gain = 0.8;
    double angular_velocity_limit_radps = 1.0471975511965976;  // pi / 3
    double velocity_magnitude_limit_mps = 0.15;
    double position_error_m = 0.05;
    double position_epsilon_m = 0.03;
    double rotation_error_rad = 0.1;
  };

  HybridPoseController() = default;
  explicit HybridPoseController(const Gains& gains) : gains_(gains) {}

  // One command per robot towards goals[i]; the sizes must agree (unchecked:
  // the drive is the only caller).
  void Apply(const std::vector<Pose2>& states, const std::vector<Pose2>& goals, std::vector<UnicycleCommand>* commands);
  // The controller called with one robot (rps's x[:, i].reshape(-1, 1)).
  UnicycleCommand ApplyOne(const Pose2& state, const Pose2& goal);

 private:
  UnicycleCommand Command(const Pose2& state, const Pose2& goal, char* approaching) const;

  Gains gains_;
  std::vector<char> approaching_;
};

}  // namespace dream::world
