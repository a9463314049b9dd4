#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "dream/bridge/difference_stats.h"
#include "dream/bridge/lab_replay_world.h"

namespace dream::bridge {

/// How the agents' commands in a lab replay compare with what the lab sent,
/// robot by robot, over the steps replayed. For a submission that ran the
/// controllers themselves (`--strategy controller`) the two are the same
/// controllers on the same poses, so any difference means a controller that
/// does not decide from its inputs alone (the clock, unseeded randomness).
class CommandAgreement {
 public:
  /// A command difference below this is rounding (the same arithmetic can
  /// differ in the last bits between numpy builds).
  static constexpr double kSameTolerance = 1e-9;

  struct RobotAgreement {
    int robot = 0;
    /// Over the replayed steps at which the robot's agent had a command
    /// (count() of either is how many).
    DifferenceStats v_mps;
    DifferenceStats w_radps;
    /// The first step whose commands differ by more than kSameTolerance; -1 when none.
    int64_t first_different_step = -1;
  };

  /// Over the steps `replay` has taken (0 .. replay.step() - 1).
  static CommandAgreement Of(const LabReplayWorld& replay);

  const std::vector<RobotAgreement>& robots() const { return robots_; }
  int64_t steps() const { return steps_; }
  /// At every replayed step at which a robot's agent had a command, it was
  /// within kSameTolerance of the lab's.
  bool Same() const;
  /// Every robot's agent had a command at every replayed step (a controller
  /// that failed, or an agent that was lost, leaves steps without).
  bool Complete() const;
  /// The robot whose commands differ most (largest of its v and w
  /// differences); -1 when there are no robots.
  int WorstRobot() const;
  /// The largest v and w differences over every robot and step.
  double MaxVDifference() const;
  double MaxWDifference() const;

  /// summary.json's `lab_replay.agents_vs_lab_commands`: one object per robot.
  nlohmann::ordered_json Json() const;

 private:
  /// One figure (v or w) of every robot, as one run's.
  DifferenceStats OverRobots(DifferenceStats RobotAgreement::*figure) const;

  std::vector<RobotAgreement> robots_;
  int64_t steps_ = 0;
};

}  // namespace dream::bridge
