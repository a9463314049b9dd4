#include "dream/agents/framework/robot_agent.h"

#include <stdexcept>

namespace dream::agents {

std::vector<int> RobotAgent::Periods(const RobotAgentSpec& spec) {
  if (!spec.robot) throw std::invalid_argument("a robot agent needs a robot");
  // Component order: sensors, then radio, then the robot's control law.
  std::vector<int> periods;
  for (const SensorSlot& slot : spec.sensors) {
    if (!slot.sensor) throw std::invalid_argument("sensor slot without a sensor");
    periods.push_back(slot.period_steps);
  }
  periods.push_back(spec.radio_period_steps);
  periods.push_back(spec.robot_period_steps);
  return periods;
}

RobotAgent::RobotAgent(RobotAgentSpec spec, uint64_t seed)
    : spec_(std::move(spec)), timer_(spec_.start_delay_steps, Periods(spec_)), mailbox_(spec_.link, seed) {}

RobotAgent::Output RobotAgent::Step(const WorldSnapshot& world) {
  const std::vector<bool>& due = timer_.Tick(world.step);
  const size_t radio_slot = spec_.sensors.size();
  Output output;
  for (size_t i = 0; i < spec_.sensors.size(); ++i) {
    if (due[i]) spec_.sensors[i].sensor->Sense(world, *spec_.robot);
  }
  if (due[radio_slot] && spec_.radio) {
    std::optional<std::vector<uint8_t>> payload = spec_.robot->OnRadio(mailbox_.Heard(*spec_.radio, id(), world));
    if (payload && spec_.radio->publishes()) {
      output.broadcast = RadioMessage{id(), world.step, std::move(*payload)};
    }
  }
  if (due[radio_slot + 1]) {
    last_command_ = spec_.robot->Update(world.step);
    output.drawing = spec_.robot->TakeDrawing();
  }
  output.command = last_command_;
  output.done = spec_.robot->done();
  return output;
}

void RobotAgent::Receive(RadioMessage message) {
  if (message.sender_id == id()) return;
  mailbox_.Post(std::move(message));
}

}  // namespace dream::agents
