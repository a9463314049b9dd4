#pragma once

#include <functional>
#include <string>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/robot_poses_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::node::testing {

/// A hand-written agent for SimNode tests: answers DREAM_POSES for one robot
/// with whatever `decide` returns; returning false stays silent that step.
class ScriptedAgent {
 public:
  using Decide = std::function<bool(const robot_poses_t& poses, velocity_command_t* command)>;

  ScriptedAgent(lcm::LcmInterface& bus, int robot_id, int64_t agent_id, Decide decide)
      : bus_(bus), robot_id_(robot_id), agent_id_(agent_id), decide_(std::move(decide)) {
    subscriptions_.push_back(lcm::Subscribe<robot_poses_t>(
        bus_, lcm::kPosesChannel, [this](const std::string&, const robot_poses_t& poses) { OnPoses(poses); }, bad_));
  }

 private:
  void OnPoses(const robot_poses_t& poses) {
    velocity_command_t command{};
    command.utime = poses.utime;
    command.step = poses.step;
    command.run_id = poses.run_id;
    command.robot_id = robot_id_;
    command.agent_id = agent_id_;
    if (decide_(poses, &command)) lcm::Publish(bus_, lcm::CommandChannel(robot_id_), command);
  }

  lcm::LcmInterface& bus_;
  int robot_id_;
  int64_t agent_id_;
  Decide decide_;
  lcm::BadMessageLog bad_;
  std::vector<lcm::Subscription> subscriptions_;  // last: ends before what its handler uses
};

}  // namespace dream::node::testing
