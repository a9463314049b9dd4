#include "dream/bridge/lab_replay_world.h"

#include <cmath>
#include <stdexcept>

#include "dream/lcm/channels.h"
#include "dream/node/run_recorder.h"
#include "dream/velocity_command_t.hpp"

namespace dream::bridge {
namespace {

const RunTrack& Checked(const RunTrack& track) {
  const auto n = static_cast<size_t>(track.num_robots);
  const size_t steps = track.utime.size();
  if (track.num_robots < 1 || steps < 2) {
    throw std::invalid_argument("LabReplayWorld: the lab run needs at least one robot and one step");
  }
  if (track.poses.size() != steps * n || track.commands.size() != steps * n || track.obstacles.size() != steps) {
    throw std::invalid_argument("LabReplayWorld: the lab run's arrays do not match its step and robot counts");
  }
  return track;
}

}  // namespace

LabReplayWorld::LabReplayWorld(RunTrack track, const world::WorldParams& params, node::RunRecorder* lab_command_log)
    : track_((Checked(track), std::move(track))),
      params_(params),
      lab_command_log_(lab_command_log),
      checker_(params, track_.num_robots),
      poses_(static_cast<size_t>(track_.num_robots)),
      velocities_(static_cast<size_t>(track_.num_robots)),
      lab_commands_(static_cast<size_t>(track_.num_robots)),
      held_(static_cast<size_t>(track_.num_robots)),
      has_held_(static_cast<size_t>(track_.num_robots), 0),
      agent_commands_(static_cast<size_t>(track_.last_step()) * static_cast<size_t>(track_.num_robots)),
      has_agent_command_(agent_commands_.size(), 0) {
  Load();
}

void LabReplayWorld::Load() {
  const auto n = static_cast<size_t>(track_.num_robots);
  const size_t k = static_cast<size_t>(step_);
  for (size_t i = 0; i < n; ++i) {
    poses_[i] = track_.poses[k * n + i];
    lab_commands_[i] = track_.commands[k * n + i];
    velocities_[i] = k == 0 ? world::UnicycleCommand{} : track_.commands[(k - 1) * n + i];
  }
}

void LabReplayWorld::GetObstacleStates(std::vector<world::ObstacleState>* states) const {
  *states = track_.obstacles[static_cast<size_t>(step_)];
}

void LabReplayWorld::CheckRobotId(int robot_id, const char* caller) const {
  if (robot_id < 0 || robot_id >= track_.num_robots) {
    throw std::out_of_range(std::string("LabReplayWorld::") + caller + ": robot_id " + std::to_string(robot_id) +
                            " is not in [0, " + std::to_string(track_.num_robots) + ")");
  }
}

void LabReplayWorld::SetCommand(int robot_id, const world::UnicycleCommand& command) {
  CheckRobotId(robot_id, "SetCommand");
  if (!std::isfinite(command.v_mps) || !std::isfinite(command.w_radps)) {
    throw std::invalid_argument("LabReplayWorld::SetCommand: robot " + std::to_string(robot_id) +
                                " command is not finite");
  }
  held_[static_cast<size_t>(robot_id)] = command;
  has_held_[static_cast<size_t>(robot_id)] = 1;
}

void LabReplayWorld::StopRobot(int robot_id) {
  CheckRobotId(robot_id, "StopRobot");
  held_[static_cast<size_t>(robot_id)] = world::UnicycleCommand{};
  has_held_[static_cast<size_t>(robot_id)] = 0;
}

void LabReplayWorld::Step() {
  if (step_ >= track_.last_step()) {
    throw std::out_of_range("LabReplayWorld::Step: the lab run ends at step " + std::to_string(track_.last_step()));
  }
  const auto n = static_cast<size_t>(track_.num_robots);
  const size_t k = static_cast<size_t>(step_);
  checker_.Check(step_, poses_, &lab_commands_, track_.obstacles[k]);
  for (size_t i = 0; i < n; ++i) {
    agent_commands_[k * n + i] = held_[i];
    has_agent_command_[k * n + i] = has_held_[i];
  }
  if (lab_command_log_ != nullptr) {
    velocity_command_t message;
    message.utime = utime();
    message.step = step_;
    message.run_id = 0;  // recorded from the lab's files, not answering any world
    message.agent_id = 0;
    message.done = false;
    std::vector<uint8_t> buffer;
    for (size_t i = 0; i < n; ++i) {
      message.robot_id = static_cast<int32_t>(i);
      message.v = lab_commands_[i].v_mps;
      message.w = lab_commands_[i].w_radps;
      buffer.resize(static_cast<size_t>(message.getEncodedSize()));
      message.encode(buffer.data(), 0, static_cast<int>(buffer.size()));
      lab_command_log_->Write(lcm::LabCommandChannel(static_cast<int>(i)), utime(), buffer.data(),
                              static_cast<int>(buffer.size()));
    }
  }
  ++step_;
  Load();
}

bool LabReplayWorld::has_agent_command(int64_t step, int robot) const {
  CheckRobotId(robot, "has_agent_command");
  if (step < 0 || step >= step_) return false;
  return has_agent_command_[static_cast<size_t>(step) * static_cast<size_t>(track_.num_robots) +
                            static_cast<size_t>(robot)] != 0;
}

const world::UnicycleCommand& LabReplayWorld::agent_command(int64_t step, int robot) const {
  CheckRobotId(robot, "agent_command");
  if (step < 0 || step >= step_) throw std::out_of_range("LabReplayWorld::agent_command: step not taken yet");
  return agent_commands_[static_cast<size_t>(step) * static_cast<size_t>(track_.num_robots) +
                         static_cast<size_t>(robot)];
}

}  // namespace dream::bridge
