#pragma once

// One sample of each dream message type, with its ids set (a run id, an
// agent id where the type has one) and every variable-length field
// non-empty: the seeds of the decoder and mutation tests, and what the
// tests of the ids and the drawings read. Their bytes are what those tests'
// offsets count on: change a value only with them.
#include <cstdint>
#include <vector>

#include "dream/applied_commands_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::testing {

inline constexpr int64_t kSampleRunId = 0x5eed0000c0ffee;
inline constexpr int64_t kSampleAgentId = 0x1234567890;
inline constexpr int64_t kSampleStep = 3;

/// Two robots, the second turning.
inline robot_poses_t SamplePoses() {
  robot_poses_t poses{};
  poses.step = kSampleStep;
  poses.run_id = kSampleRunId;
  poses.num_robots = 2;
  poses.x = {0.1, -0.2};
  poses.y = {0.3, 0.4};
  poses.theta = {0.0, 1.0};
  poses.v = {0.05, 0.0};
  poses.w = {0.0, -0.5};
  return poses;
}

inline obstacles_t SampleObstacles() {
  obstacles_t obstacles{};
  obstacles.step = kSampleStep;
  obstacles.run_id = kSampleRunId;
  obstacles.num_obstacles = 2;
  obstacles.obstacles.resize(2);
  obstacles.obstacles[1].id = 1;
  obstacles.obstacles[1].width = 0.2;
  return obstacles;
}

/// Robot 1 lost.
inline run_status_t SampleRunStatus() {
  run_status_t status{};
  status.step = kSampleStep;
  status.run_id = kSampleRunId;
  status.command_conflicts = 2;
  status.state = run_status_t::RUNNING;
  status.num_robots = 2;
  status.num_lost = 1;
  status.lost_robot_ids = {1};
  status.detail = "robot 1 is silent";
  return status;
}

/// Robot 1's command.
inline velocity_command_t SampleCommand() {
  velocity_command_t command{};
  command.step = kSampleStep;
  command.run_id = kSampleRunId;
  command.robot_id = 1;
  command.agent_id = kSampleAgentId;
  command.v = 0.1;
  return command;
}

inline radio_message_t SampleRadioMessage() {
  radio_message_t radio{};
  radio.step = kSampleStep;
  radio.run_id = kSampleRunId;
  radio.sender_id = 1;
  radio.agent_id = kSampleAgentId;
  radio.payload = {1, 2, 3, 4, 5};
  radio.payload_size = 5;
  return radio;
}

inline robot_fault_t SampleFault() {
  robot_fault_t fault{};
  fault.step = kSampleStep;
  fault.run_id = kSampleRunId;
  fault.robot_id = 1;
  fault.agent_id = kSampleAgentId;
  fault.detail = "controller.py:12: in update: ValueError: boom";
  return fault;
}

/// Robot 0's command applied (with a conflict), robot 1 without one.
inline applied_commands_t SampleAppliedCommands() {
  applied_commands_t applied{};
  applied.step = kSampleStep;
  applied.run_id = kSampleRunId;
  applied.num_robots = 2;
  applied.applied_agent_id = {kSampleAgentId, 0};
  applied.commanded_v = {0.1, 0.0};
  applied.commanded_w = {-0.5, 0.0};
  applied.conflicts = {1, 0};
  return applied;
}

inline run_verdict_t SampleVerdict() {
  run_verdict_t verdict{};
  verdict.step = kSampleStep;
  verdict.run_id = kSampleRunId;
  verdict.verdict = run_verdict_t::NOT_READY;
  verdict.goal = run_verdict_t::GOAL_MISSED;
  verdict.exit_code = 5;
  verdict.goal_completion_step = -1;
  verdict.goal_text = "missed (1 of 2 robots arrived)";
  verdict.reasons = "goal: the go_to_goal experiment missed its goal";
  return verdict;
}

/// Robot 1's drawing: a red line from (0, 0) to (1, 0.5), then "hi" at (-0.5, 0.5).
inline drawing_t SampleDrawing() {
  drawing_t drawing{};
  drawing.step = kSampleStep;
  drawing.run_id = kSampleRunId;
  drawing.robot_id = 1;
  drawing.agent_id = kSampleAgentId;
  drawing.num_shapes = 2;
  drawing.kind = {drawing_t::LINE, drawing_t::TEXT};
  drawing.rgba = {static_cast<int32_t>(0xff0000ffu), 0x000000ff};
  drawing.width = {0.01, 0.0};
  drawing.size = {0.0, 0.05};
  drawing.fill = {0, 0};
  drawing.point_count = {2, 1};
  drawing.text_length = {0, 2};
  drawing.num_points = 3;
  drawing.x = {0.0, 1.0, -0.5};
  drawing.y = {0.0, 0.5, 0.5};
  drawing.num_text_bytes = 2;
  drawing.text = {'h', 'i'};
  return drawing;
}

/// Robot 1's answer held up by robot 0's call.
inline robot_busy_t SampleBusy() {
  robot_busy_t busy{};
  busy.step = kSampleStep;
  busy.run_id = kSampleRunId;
  busy.robot_id = 1;
  busy.agent_id = kSampleAgentId;
  busy.call_robot_id = 0;
  busy.call_s = 0.25;
  return busy;
}

/// Robots 1 and 0 in one message, robot 0 done.
inline robot_commands_t SampleCommandBatch() {
  robot_commands_t commands{};
  commands.step = kSampleStep;
  commands.run_id = kSampleRunId;
  commands.agent_id = kSampleAgentId;
  commands.num_commands = 2;
  commands.robot_id = {1, 0};
  commands.v = {0.1, -0.05};
  commands.w = {0.5, 0.0};
  commands.done = {0, 1};
  return commands;
}

/// A DREAM_CMDS message of run `run_id` from agent `agent_id` at `step`, one
/// entry per id in order: robot k asks v = 0.01 (k + 1), w = -0.1 (k + 1),
/// and robot 1 alone says done, so every entry's fields differ.
inline robot_commands_t CommandBatchOf(const std::vector<int32_t>& ids, int64_t run_id, int64_t agent_id,
                                       int64_t step = 0, int64_t utime = 0) {
  robot_commands_t batch{};
  batch.utime = utime;
  batch.step = step;
  batch.run_id = run_id;
  batch.agent_id = agent_id;
  batch.num_commands = static_cast<int32_t>(ids.size());
  for (const int32_t id : ids) {
    batch.robot_id.push_back(id);
    batch.v.push_back(0.01 * (id + 1));
    batch.w.push_back(-0.1 * (id + 1));
    batch.done.push_back(id == 1 ? 1 : 0);
  }
  return batch;
}

}  // namespace dream::testing
