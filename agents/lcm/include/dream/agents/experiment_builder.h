#pragma once

#include <memory>

#include "dream/agents/experiment_metrics.h"
#include "dream/agents/robot.h"

namespace dream::agents {

/// One experiment kind (`controller: {kind: ...}`): it has read and checked
/// its own keys of the section when constructed, and builds each robot's
/// control law and the experiment's metrics. Sensors, radio and timer come
/// from the common keys (AgentPartsConfig).
class ExperimentBuilder {
 public:
  virtual ~ExperimentBuilder() = default;
  /// The control law of robot `robot_id`.
  virtual std::unique_ptr<Robot> MakeRobot(int robot_id, const RobotParams& params) const = 0;
  /// The experiment's outcome figures (SafetyMetrics is always added too).
  virtual std::unique_ptr<ExperimentMetrics> MakeMetrics() const = 0;
};

}  // namespace dream::agents
