#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "dream/agents/framework/actuator_limits.h"
#include "dream/agents/framework/drawing.h"
#include "dream/agents/framework/radio_message.h"
#include "dream/agents/framework/robot_params.h"
#include "dream/agents/framework/sensor_readings.h"
#include "dream/agents/framework/unicycle_command.h"

namespace dream::agents {

/// The thesis's Robot: one robot's controller. It never sees the world; it
/// knows only what its accessories report through the On*() callbacks, which
/// by default keep the latest reading. Subclasses implement Update() (the
/// control law, run when the Timer says so) and, if they talk, OnRadio().
///
/// Per step the RobotAgent calls, in this order and only when due: sensors
/// (OnOdometry, OnMovement, OnObstacles), then OnRadio, then Update. (The
/// thesis ran Update first, so a robot could act before its first odometry
/// and think it was at (0, 0); sensing first avoids that.)
class Robot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  Robot(int id, RobotParams params);
  virtual ~Robot() = default;

  int id() const { return id_; }

  virtual void OnOdometry(const OdometryReading& reading);
  virtual void OnMovement(const MovementReading& reading);
  virtual void OnObstacles(const ObstacleReading& reading);

  /// Called when the radio's period elapses, with the latest message from
  /// each neighbour the radio can hear. Returns the payload to broadcast, or
  /// nothing to stay silent. Default: silent.
  virtual std::optional<std::vector<uint8_t>> OnRadio(const std::vector<RadioMessage>& heard);

  /// The control law: the command for this step. Called when the Timer says
  /// so; in between, the last command is repeated.
  virtual UnicycleCommand Update(int64_t step) = 0;

  /// True once the robot considers its task complete.
  virtual bool done() const { return false; }

  /// Radio payloads this robot could not decode (malformed neighbour messages):
  /// the sum over bad_radio_messages_by_sender().
  long bad_radio_messages() const;
  /// The same, per sender id; kUnknownSender counts those reported without
  /// their message. The agent host logs them by the sender's channel.
  const std::map<int, long>& bad_radio_messages_by_sender() const { return bad_radio_messages_by_sender_; }
  static constexpr int kUnknownSender = -1;

  /// The thesis's dxi_to_dxu at heading `theta_rad` with `params`' gains, for
  /// code that has no Robot (test harnesses); robots use the member below.
  static UnicycleCommand DxiToDxu(const Eigen::Vector2d& dxi_mps, double theta_rad, const RobotParams& params);

  /// What the robot drew since the last call (in OnRadio and Update), handed
  /// over and cleared: the RobotAgent takes it each time Update runs.
  Drawing TakeDrawing();

 protected:
  /// The thesis's dxi_to_dxu: v = k_v (c dx + s dy), w = k_w atan2(-s dx + c dy, v) / (pi/2),
  /// with the heading from the latest odometry. (The turn uses the already
  /// scaled v, as the thesis does: a target 45 degrees off turns by more.)
  UnicycleCommand DxiToDxu(const Eigen::Vector2d& dxi_mps) const { return DxiToDxu(dxi_mps, pose().z(), params_); }
  /// The thesis's actuator_limit (see ActuatorLimits).
  UnicycleCommand LimitActuators(const UnicycleCommand& command) const { return actuator_limits_.Apply(command); }

  const RobotParams& params() const { return params_; }
  bool has_odometry() const { return odometry_.has_value(); }
  /// Latest own pose; (0, 0, 0) before the first odometry reading.
  Eigen::Vector3d pose() const { return odometry_ ? odometry_->pose : Eigen::Vector3d::Zero(); }
  const MovementReading& movement() const { return movement_; }
  const ObstacleReading& obstacles() const { return obstacles_; }
  /// Where the controller draws for this step (world coordinates): lines,
  /// circles, polygons, arrows and text that `dream view` and `dream render`
  /// show until its next Update. Drawing never changes the run.
  Drawing& drawing() { return drawing_; }
  /// Counts `message` as one this robot could not decode (it is dropped).
  void CountBadRadioMessage(const RadioMessage& message);
  /// The same when the message is not at hand: its sender stays unknown.
  void CountBadRadioMessage();

 private:
  int id_;
  RobotParams params_;
  ActuatorLimits actuator_limits_;
  std::optional<OdometryReading> odometry_;
  MovementReading movement_;
  ObstacleReading obstacles_;
  std::map<int, long> bad_radio_messages_by_sender_;
  Drawing drawing_;
};

}  // namespace dream::agents
