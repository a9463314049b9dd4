#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "dream/agents/framework/mailbox.h"
#include "dream/agents/framework/radio.h"
#include "dream/agents/framework/robot.h"
#include "dream/agents/framework/sensor.h"
#include "dream/agents/framework/timer.h"

namespace dream::agents {

/// A sensor and how often it runs.
struct SensorSlot {
  std::unique_ptr<Sensor> sensor;
  int period_steps = 1;
};

/// Everything one robot is made of (the thesis's parts).
struct RobotAgentSpec {
  std::unique_ptr<Robot> robot;
  int robot_period_steps = 1;     ///< how often Update() runs
  int64_t start_delay_steps = 0;  ///< nothing runs while step <= this
  std::vector<SensorSlot> sensors;
  std::unique_ptr<Radio> radio;  ///< null: the robot has no radio
  int radio_period_steps = 1;
  RadioLinkParams link;  ///< loss and delay of incoming messages
};

/// One robot's agent, free of any transport: feed it the world each step and
/// the radio messages of others; it runs its parts when its Timer says so and
/// returns the command (the last one again when Update() did not run), if
/// the radio spoke, the message to broadcast, and what the robot drew.
class RobotAgent {
 public:
  struct Output {
    UnicycleCommand command;
    bool done = false;
    std::optional<RadioMessage> broadcast;
    /// What the robot drew this step, when its Update ran (an empty drawing
    /// clears the last one); nothing when it did not run.
    std::optional<Drawing> drawing;
  };

  /// @param seed seeds the mailbox's loss decisions.
  /// @throws std::invalid_argument when the spec has no robot or bad periods.
  RobotAgent(RobotAgentSpec spec, uint64_t seed);

  Output Step(const WorldSnapshot& world);

  /// A message another robot broadcast; heard (or not) at later steps.
  void Receive(RadioMessage message);

  int id() const { return spec_.robot->id(); }
  const Robot& robot() const { return *spec_.robot; }
  const Mailbox& mailbox() const { return mailbox_; }

 private:
  static std::vector<int> Periods(const RobotAgentSpec& spec);

  RobotAgentSpec spec_;
  Timer timer_;
  Mailbox mailbox_;
  UnicycleCommand last_command_;
};

}  // namespace dream::agents
