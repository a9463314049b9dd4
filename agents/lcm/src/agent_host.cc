#include "dream/agents/agent_host.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <set>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/robot_poses_t.hpp"

namespace dream::agents {

AgentHost::AgentHost(lcm::LcmInterface& lcm, std::vector<HostedRobot> robots, int64_t agent_id)
    : lcm_(lcm), agent_id_(agent_id) {
  std::set<int> ids;
  for (HostedRobot& robot : robots) {
    if (!ids.insert(robot.robot_id).second) {
      throw std::invalid_argument("robot " + std::to_string(robot.robot_id) +
                                  " is listed twice for one agent host");
    }
    RobotSlot slot;
    slot.robot_id = robot.robot_id;
    slot.channel = lcm::CommandChannel(robot.robot_id);
    slot.controller = std::move(robot.controller);
    robots_.push_back(std::move(slot));
  }
  lcm::Subscribe<robot_poses_t>(
      lcm_, lcm::kPosesChannel,
      [this](const std::string& channel, const robot_poses_t& poses) { OnPoses(channel, poses); },
      bad_messages_);
  lcm::Subscribe<run_status_t>(
      lcm_, lcm::kStatusChannel,
      [this](const std::string& channel, const run_status_t& status) { OnStatus(channel, status); },
      bad_messages_);
}

void AgentHost::OnPoses(const std::string& channel, const robot_poses_t& poses) {
  saw_poses_since_check_ = true;
  if (poses.num_robots < 0 || poses.x.size() != static_cast<size_t>(poses.num_robots) || poses.step < 0) {
    bad_messages_.Report(channel, "inconsistent robot_poses_t (num_robots " +
                                      std::to_string(poses.num_robots) + ", step " +
                                      std::to_string(poses.step) + ")");
    return;
  }
  for (RobotSlot& robot : robots_) {
    if (robot.robot_id >= poses.num_robots) {
      bad_messages_.Report(channel, "robot " + std::to_string(robot.robot_id) +
                                        " is not in this run: DREAM_POSES carries " +
                                        std::to_string(poses.num_robots) + " robots");
      continue;
    }
    // The world only moves forward, so a step just behind ours is a late
    // duplicate. Anything further back is authoritative: a restarted world,
    // or recovery after a stray message with a bogus future step.
    if (poses.step == robot.answered_step - 1) continue;
    if (poses.step != robot.answered_step) {
      const auto i = static_cast<size_t>(robot.robot_id);
      ControllerInput input;
      input.step = poses.step;
      input.own_pose = Eigen::Vector3d(poses.x[i], poses.y[i], poses.theta[i]);
      if (!input.own_pose.allFinite()) {
        bad_messages_.Report(channel, "non-finite pose for robot " + std::to_string(robot.robot_id));
        continue;
      }
      const ControllerOutput output = robot.controller->Step(input);
      velocity_command_t& command = robot.last_command;
      command.utime = poses.utime;
      command.step = poses.step;
      command.robot_id = robot.robot_id;
      command.agent_id = agent_id_;
      command.v = output.command.v_mps;
      command.w = output.command.w_radps;
      command.done = output.done;
      robot.answered_step = poses.step;
      last_step_answered_ = std::max(last_step_answered_, poses.step);
    }
    lcm::Publish(lcm_, robot.channel, robot.last_command);
  }
}

void AgentHost::OnStatus(const std::string& channel, const run_status_t& status) {
  (void)channel;
  if (status.state == run_status_t::FINISHED || status.state == run_status_t::ABORTED) {
    world_finished_ = true;
    end_detail_ = status.detail;
  }
}

bool AgentHost::Run(const std::atomic<bool>& stop, double idle_timeout_s) {
  using Clock = std::chrono::steady_clock;
  auto last_activity = Clock::now();
  while (!world_finished_ && !stop.load()) {
    lcm_.HandleSubscriptions(100);
    if (saw_poses_since_check_) {
      saw_poses_since_check_ = false;
      last_activity = Clock::now();
    } else if (std::chrono::duration<double>(Clock::now() - last_activity).count() > idle_timeout_s) {
      spdlog::error(
          "no DREAM_POSES for {:.0f} s on {}: is the simulator (dream sim) running on the same LCM URL?",
          idle_timeout_s, lcm_.url());
      return false;
    }
  }
  return world_finished_;
}

}  // namespace dream::agents
