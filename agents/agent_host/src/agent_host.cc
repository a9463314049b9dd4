#include "dream/agent_host/agent_host.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <set>

#include "dream/agent_host/drawing_message.h"
#include "dream/agent_host/snapshot_from_messages.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/message_limits.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"

namespace dream::agent_host {

AgentHost::AgentHost(lcm::LcmInterface& lcm, std::vector<std::unique_ptr<agents::RobotAgent>> agents, int64_t agent_id)
    : lcm_(lcm), agent_id_(agent_id) {
  std::set<int> ids;
  for (std::unique_ptr<agents::RobotAgent>& agent : agents) {
    if (!ids.insert(agent->id()).second) {
      throw std::invalid_argument("robot " + std::to_string(agent->id()) + " is listed twice for one agent host");
    }
    RobotSlot slot;
    slot.command_channel = lcm::CommandChannel(agent->id());
    slot.radio_channel = lcm::RadioChannel(agent->id());
    slot.draw_channel = lcm::DrawChannel(agent->id());
    slot.agent = std::move(agent);
    robots_.push_back(std::move(slot));
  }
  // LCM dispatches in arrival order, and a neighbour sends its radio message
  // of step k before its command, which the world needs before it publishes
  // step k + 1: so the mailbox holds it by the time we act on step k + 1.
  subscriptions_.push_back(lcm::Subscribe(lcm_, lcm::kRadioChannelRegex, this, &AgentHost::OnRadio, bad_messages_));
  subscriptions_.push_back(lcm::Subscribe(lcm_, lcm::kObstaclesChannel, this, &AgentHost::OnObstacles, bad_messages_));
  subscriptions_.push_back(lcm::Subscribe(lcm_, lcm::kPosesChannel, this, &AgentHost::OnPoses, bad_messages_));
  subscriptions_.push_back(lcm::Subscribe(lcm_, lcm::kStatusChannel, this, &AgentHost::OnStatus, bad_messages_));
}

AgentHost::~AgentHost() {
  for (const RobotSlot& robot : robots_) {
    const lcm::BadMessageLog& bad = robot.bad_radio_payloads;
    if (bad.total() == 0) continue;
    std::string senders;
    for (const auto& [channel, count] : bad.per_channel()) {
      senders += (senders.empty() ? "" : ", ") + channel + " x" + std::to_string(count);
    }
    spdlog::warn("robot {} dropped {} radio payload(s) that did not decode: {}", robot.agent->id(), bad.total(),
                 senders);
  }
}

void AgentHost::OnObstacles(const std::string& channel, const obstacles_t& obstacles) {
  if (obstacles.num_obstacles < 0 || obstacles.obstacles.size() != static_cast<size_t>(obstacles.num_obstacles)) {
    bad_messages_.Report(channel, "inconsistent obstacles_t");
    return;
  }
  // Step 0's obstacles come before the first DREAM_POSES: kept, and dropped
  // on joining if they were of another run.
  if (follower_.joined() && !follower_.InRun(obstacles.run_id)) {
    bad_messages_.Report(channel, "obstacles of another run");
    return;
  }
  obstacles_run_id_ = obstacles.run_id;
  std::vector<int> non_finite;
  TakeObstacles(obstacles, &world_, &non_finite);
  for (int id : non_finite) bad_messages_.Report(channel, "non-finite obstacle " + std::to_string(id));
}

void AgentHost::OnRadio(const std::string& channel, const radio_message_t& message) {
  const std::optional<int> sender = lcm::RobotIdFromChannel(channel, lcm::kRadioChannelPrefix);
  if (!sender || *sender != message.sender_id || message.payload_size < 0 ||
      message.payload.size() != static_cast<size_t>(message.payload_size)) {
    bad_messages_.Report(channel, "radio message does not match its channel or payload size", message.agent_id);
    return;
  }
  if (!follower_.joined()) {
    // Bounded: a neighbour's answer to step 0 is all that can come first.
    if (radio_before_joining_.size() < static_cast<size_t>(2 * lcm::MessageLimits::kRobots)) {
      radio_before_joining_.emplace_back(channel, message);
    } else {
      bad_messages_.Report(channel, "radio message before the world's first step, beyond the queue's bound",
                           message.agent_id);
    }
    return;
  }
  if (!follower_.InRun(message.run_id)) {
    bad_messages_.Report(channel, "radio message of another run", message.agent_id);
    return;
  }
  Deliver(channel, message);
}

void AgentHost::Deliver(const std::string& channel, const radio_message_t& message) {
  // Every sender gets a mailbox slot in each hosted robot: only the run's
  // robots may have one, or forged ids would grow memory without bound.
  if (message.sender_id >= world_.num_robots()) {
    bad_messages_.Report(channel,
                         "radio sender " + std::to_string(message.sender_id) + " is not a robot of this run (" +
                             std::to_string(world_.num_robots()) + " robots)",
                         message.agent_id);
    return;
  }
  // Sent while answering step k, so heard at k or k + 1; a later step is a
  // forgery that would shadow the sender's real messages in the mailboxes.
  if (message.step < 0 || message.step > follower_.step() + 1) {
    bad_messages_.Report(channel,
                         "radio message sent at step " + std::to_string(message.step) + " while the world is at step " +
                             std::to_string(follower_.step()),
                         message.agent_id);
    return;
  }
  for (RobotSlot& robot : robots_) {
    robot.agent->Receive(agents::RadioMessage{message.sender_id, message.step, message.payload});
  }
}

void AgentHost::ReportBadRadioPayloads(RobotSlot& robot) {
  const agents::Robot& control = robot.agent->robot();
  // The usual case, checked cheaply: nothing new since the last step.
  if (control.bad_radio_messages() == robot.bad_radio_payloads.total()) return;
  const std::string reason = "robot " + std::to_string(control.id()) + ": payload did not decode";
  for (const auto& [sender, count] : control.bad_radio_messages_by_sender()) {
    const std::string channel =
        sender == agents::Robot::kUnknownSender ? kUnknownSenderChannel : lcm::RadioChannel(sender);
    for (long seen = robot.bad_radio_payloads.count(channel); seen < count; ++seen) {
      robot.bad_radio_payloads.Report(channel, reason);
    }
  }
}

void AgentHost::Fail(RobotSlot& robot, const robot_poses_t& poses, const std::string& detail) {
  robot.fault = detail;
  robot.last_radio.reset();
  robot.last_drawing.reset();
  spdlog::error("robot {} stops at step {}: its controller failed: {}", robot.agent->id(), poses.step, detail);
  robot_fault_t fault{};
  fault.utime = poses.utime;
  fault.step = poses.step;
  fault.run_id = poses.run_id;
  fault.robot_id = robot.agent->id();
  fault.agent_id = agent_id_;
  fault.detail = detail;
  lcm::Publish(lcm_, lcm::kFaultChannelPrefix + std::to_string(robot.agent->id()), fault);
}

bool AgentHost::Answer(RobotSlot& robot, const robot_poses_t& poses) {
  const agents::RobotAgent::Output output = robot.agent->Step(world_);
  ReportBadRadioPayloads(robot);
  velocity_command_t& command = robot.last_command;
  command.utime = poses.utime;
  command.step = poses.step;
  command.run_id = poses.run_id;
  command.robot_id = robot.agent->id();
  command.agent_id = agent_id_;
  command.v = output.command.v_mps;
  command.w = output.command.w_radps;
  command.done = output.done;
  robot.last_radio.reset();
  robot.last_drawing.reset();
  if (output.drawing) TakeDrawing(robot, poses, std::move(*output.drawing));
  if (output.broadcast &&
      output.broadcast->payload.size() > static_cast<size_t>(lcm::MessageLimits::kRadioPayloadBytes)) {
    // Every receiver, and the world, would drop it: the robot would talk to no one, unseen.
    Fail(robot, poses,
         "robot " + std::to_string(robot.agent->id()) + ": OnRadio returned a payload of " +
             std::to_string(output.broadcast->payload.size()) + " bytes, over the limit of " +
             std::to_string(lcm::MessageLimits::kRadioPayloadBytes) + " bytes (every receiver would drop it)");
    return false;
  }
  if (!std::isfinite(command.v) || !std::isfinite(command.w)) {
    // The world would refuse it at every step and the robot would hold still, unexplained.
    Fail(robot, poses,
         "robot " + std::to_string(robot.agent->id()) + ": Update returned a command that is not finite (v=" +
             std::to_string(command.v) + " m/s, w=" + std::to_string(command.w) + " rad/s; the world would refuse it)");
    return false;
  }
  if (output.broadcast) {
    radio_message_t radio{};
    radio.utime = poses.utime;
    radio.step = poses.step;
    radio.run_id = poses.run_id;
    radio.sender_id = robot.agent->id();
    radio.agent_id = agent_id_;
    radio.payload = output.broadcast->payload;
    radio.payload_size = static_cast<int32_t>(radio.payload.size());
    robot.last_radio = std::move(radio);
  }
  last_step_answered_ = std::max(last_step_answered_, poses.step);
  return true;
}

void AgentHost::TakeDrawing(RobotSlot& robot, const robot_poses_t& poses, agents::Drawing drawing) {
  for (const auto& [reason, count] : drawing.clip_reasons()) {
    if (!robot.clip_reasons_logged.insert(reason).second) continue;
    spdlog::warn("robot {} drew past its bounds at step {}: {} x{} (counted in each {}'s `clipped` from now on)",
                 robot.agent->id(), poses.step, reason, count, robot.draw_channel);
  }
  if (drawing.SameShapes(robot.drawn) && drawing.clipped() == robot.drawn.clipped()) return;
  drawing_t message = DrawingMessageOf(drawing);
  message.utime = poses.utime;
  message.step = poses.step;
  message.run_id = poses.run_id;
  message.robot_id = robot.agent->id();
  message.agent_id = agent_id_;
  robot.last_drawing = std::move(message);
  robot.drawn = std::move(drawing);
}

void AgentHost::OnPoses(const std::string& channel, const robot_poses_t& poses) {
  const auto n = static_cast<size_t>(poses.num_robots);
  if (poses.num_robots < 0 || poses.step < 0 || poses.x.size() != n || poses.v.size() != n) {
    bad_messages_.Report(channel, "inconsistent robot_poses_t (num_robots " + std::to_string(poses.num_robots) +
                                      ", step " + std::to_string(poses.step) + ")");
    return;
  }
  for (size_t i = 0; i < n; ++i) {
    const bool finite = std::isfinite(poses.x[i]) && std::isfinite(poses.y[i]) && std::isfinite(poses.theta[i]) &&
                        std::isfinite(poses.v[i]) && std::isfinite(poses.w[i]);
    if (!finite) {
      bad_messages_.Report(channel, "non-finite pose or velocity for robot " + std::to_string(i));
      return;
    }
  }
  if (expected_robots_ >= 0 && poses.num_robots != expected_robots_) {
    bad_messages_.Report(channel, "a world of " + std::to_string(poses.num_robots) +
                                      " robots; this agent's config has " + std::to_string(expected_robots_));
    last_other_world_robots_ = poses.num_robots;
    return;
  }
  const bool joining = !follower_.joined();
  const lcm::WorldFollower::StepDecision decision = follower_.OnPoses(poses.run_id, poses.step);
  if (decision == lcm::WorldFollower::StepDecision::kIgnore) return;
  saw_poses_since_check_ = true;  // only the followed run's steps keep this host waiting
  if (decision == lcm::WorldFollower::StepDecision::kNewStep) {
    TakePoses(poses, &world_);
    bad_messages_.set_step(poses.step);  // kept with each channel's first refusal
  }
  if (joining) {
    if (obstacles_run_id_ != poses.run_id) world_.obstacles.clear();
    for (const auto& [radio_channel, radio] : radio_before_joining_) {
      if (radio.run_id == poses.run_id) Deliver(radio_channel, radio);
    }
    radio_before_joining_.clear();
    radio_before_joining_.shrink_to_fit();
  }
  for (RobotSlot& robot : robots_) {
    if (robot.agent->id() >= poses.num_robots) {
      bad_messages_.Report(channel, "robot " + std::to_string(robot.agent->id()) +
                                        " is not in this run: DREAM_POSES carries " + std::to_string(poses.num_robots) +
                                        " robots");
      continue;
    }
    if (!robot.fault.empty()) continue;  // given up: the world was told, and stops the robot
    if (decision == lcm::WorldFollower::StepDecision::kNewStep && !Answer(robot, poses)) continue;
    if (robot.last_radio) lcm::Publish(lcm_, robot.radio_channel, *robot.last_radio);
    if (robot.last_drawing) lcm::Publish(lcm_, robot.draw_channel, *robot.last_drawing);
    lcm::Publish(lcm_, robot.command_channel, robot.last_command);
  }
}

void AgentHost::OnStatus(const std::string& channel, const run_status_t& status) {
  (void)channel;
  const bool ending = status.state == run_status_t::FINISHED || status.state == run_status_t::ABORTED;
  if (ending && follower_.EndsRun(status.run_id, status.step)) {
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
      if (!follower_.joined() && last_other_world_robots_ >= 0) {
        spdlog::error(
            "DREAM_POSES on {} came from a world of {} robots, but this agent's config has {}: start the agents "
            "with the config the simulator (dream sim) runs",
            lcm_.url(), last_other_world_robots_, expected_robots_);
        return false;
      }
      spdlog::error("no DREAM_POSES for {:g} s on {}: is the simulator (dream sim) running on the same LCM URL?",
                    idle_timeout_s, lcm_.url());
      return false;
    }
  }
  return world_finished_;
}

}  // namespace dream::agent_host
