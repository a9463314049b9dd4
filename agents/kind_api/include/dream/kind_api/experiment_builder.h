#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "dream/agents/framework/experiment_metrics.h"
#include "dream/agents/framework/robot.h"

namespace dream::kind_api {

/// One experiment kind (`controller: {kind: ...}`): it has read and checked
/// its own keys of the section when constructed, and builds each robot's
/// control law and, if it has any, the experiment's own metrics. Sensors,
/// radio and timer come from the common keys (AgentPartsConfig). A kind that
/// is only a Robot subclass needs no builder of its own: see
/// ControllerKind::OfRobot.
class ExperimentBuilder {
 public:
  virtual ~ExperimentBuilder() = default;
  /// The control law of robot `robot_id`.
  virtual std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const = 0;
  /// The experiment's own outcome figures, or nullptr (the default) for
  /// none. SafetyMetrics (minimum pairwise distance, near misses) is always
  /// added, so every kind's summary has those.
  virtual std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const { return nullptr; }
  /// Where the robots are meant to go, for pictures: per robot its goal
  /// points in order (a formation sequence has several). Empty (the
  /// default): nothing to draw. The success rule over the run's figures is
  /// the metrics' ExperimentMetrics::JudgeGoal.
  virtual std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const { return {}; }
};

}  // namespace dream::kind_api
