#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dream/applied_commands_t.hpp"
#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/node/busy_intake.h"
#include "dream/node/command_intake.h"
#include "dream/node/heard.h"
#include "dream/node/node_clock.h"
#include "dream/node/drawing_intake.h"
#include "dream/node/intake_context.h"
#include "dream/node/radio_intake.h"
#include "dream/node/robot_slot.h"
#include "dream/node/run_outcome.h"
#include "dream/config/sim_node_options.h"
#include "dream/world/obstacle_state.h"
#include "dream/world/unicycle_world.h"
#include "dream/world/world.h"

namespace dream {
class velocity_command_t;
class robot_fault_t;
class run_status_t;
}  // namespace dream

namespace dream::node {

class ProgressReporter;
class RefusedRecord;
class RunRecorder;

/// A world on the bus: publishes it, consumes commands, records the run. The
/// world is the in-tree simulator (UnicycleWorld) or any other World, such as
/// the bridge's replay of a lab run (bridge::LabReplayWorld); agents cannot
/// tell which. The run ends at the step limit, when every robot reports done,
/// or when the world has no more steps (World::last_step()).
///
/// Writes DREAM_OBSTACLES, DREAM_STATUS and then DREAM_POSES (the trigger
/// agents answer) for every step; reads DREAM_CMD_<id>. Records its own
/// messages once, as published, and what the run used of what it heard
/// (commands, radio, faults and busy notes of this run's robots that pass the
/// checks; BusyIntake says how a busy note holds off a silent robot), all
/// with the simulated time of the current step. Everything else it hears is
/// refused and counted (bad_messages), never recorded in the run's log: an
/// undecodable or refused command, radio or fault, any other channel (a forged
/// DREAM_APPLIED, made-up names); a RefusedRecord keeps those apart.
///
/// Bad commands never stop the run: a NaN/inf or absurd command is rejected,
/// counted, and its robot holds still for that step; a command for a robot
/// that does not exist, from a second agent claiming a robot, or for a step
/// other than the current one is rejected and counted; undecodable messages
/// are counted per channel.
///
/// Every world message carries the run's random id (run_id()); commands,
/// radio and faults of another run are refused, and a second world seen on
/// the bus (its DREAM_STATUS, or commands answering it) is reported in the
/// outcome's other_worlds. Two different commands for one robot and step are
/// a conflict: the first is applied, the rest refused and counted, and each
/// step's applied commands are recorded on DREAM_APPLIED (applied_commands_t).
///
/// A run log that cannot be written (full disk, file size limit) ends the run
/// cleanly as RunOutcome::End::kFailed, with a reason naming the step, the
/// file and the OS error; the log keeps every whole event before the failure.
class SimNode {
 public:
  /// @param recorder may be null (no log). Must outlive the node.
  /// @throws std::invalid_argument when options are invalid.
  SimNode(lcm::LcmInterface& lcm, world::World& world, RunRecorder* recorder, config::SimNodeOptions options);

  /// Runs to the end; returns how it ended. Handles every subscription on
  /// `lcm`, so in one process it also drives the agents sharing the bus.
  /// Sets no signal handlers: the caller sets `stop` (e.g. from SIGINT).
  RunOutcome Run(const std::atomic<bool>& stop);

  /// This run's identifier: random, never 0, in every message the world sends.
  int64_t run_id() const { return run_id_; }
  /// Other worlds' run ids kept in the outcome, so a flood cannot grow memory.
  static constexpr size_t kMaxOtherWorlds = 16;
  /// Different radio messages of one robot recorded per world step (resends
  /// of the same message are not recorded again; see RadioIntake).
  static constexpr int kMaxRadioPerRobotPerStep = RadioIntake::kMaxPerRobotPerStep;

  /// Shows the run's progress (steps/s, ETA to max_steps) on `reporter` from
  /// the first step on; null (the default): no progress output. Must outlive
  /// Run().
  void set_progress_reporter(ProgressReporter* reporter) { progress_ = reporter; }

  /// Counts and keeps the refused messages (see the class comment) in
  /// `refused`; null (the default): they are only counted in bad_messages.
  /// Must outlive Run().
  void set_refused_record(RefusedRecord* refused) { refused_ = refused; }

  /// Reads the time from `clock` instead of the steady clock (tests: time
  /// that passes only as the test says). Before Run().
  void set_clock(NodeClock clock) { clock_ = std::move(clock); }

 private:
  using Clock = std::chrono::steady_clock;

  /// Every message heard: dispatched by channel, then recorded or refused.
  void OnMessage(const std::string& channel, const void* data, int size);
  Heard Hear(const std::string& channel, const void* data, int size);
  /// Records a message used, or keeps a refused one apart (RefusedRecord).
  void Keep(const std::string& channel, Heard heard, const void* data, int size);
  /// DREAM_CMDS: each entry taken and kept as the DREAM_CMD_<id> it stands for.
  void HearCommands(const std::string& channel, const void* data, int size);
  Heard OnFault(const std::string& channel, const robot_fault_t& fault);
  void OnStatus(const std::string& channel, const run_status_t& status);
  /// Notes a run id of another world (logged once per id).
  void NoteOtherWorld(int64_t run_id, const std::string& seen_on);
  /// Lockstep: the robot has a command for the step the world is at.
  bool Answered(const RobotSlot& robot) const { return robot.command_step == world_.step(); }
  /// Handles what has arrived on the bus (bounded, so a flood cannot hold the world).
  void DrainArrived();
  /// Past start_timeout_s: true when what arrived answers the start after
  /// all, or a host still setting robots up holds it (BusyIntake::HoldsStart).
  bool StartHeld(Clock::time_point now);
  /// Records which commands are applied at this step (DREAM_APPLIED).
  void RecordApplied();
  /// Writes one event to the recorder, if any; a write failure is remembered
  /// (the recorder is failed from then on) for Run() to end the run.
  void Record(const std::string& channel, const void* data, int size);
  bool RecorderFailed() const;
  std::string RecorderFailureReason() const;
  void PublishStep(bool record);
  void PublishStatus(int8_t state, const std::string& detail, bool record);
  template <typename Message>
  void PublishAndRecord(const char* channel, const Message& message, bool record);
  bool AllLiveAnswered() const;
  bool AllRobotsLost() const;
  /// Whether stop_when_done is on and every robot's last command said done.
  bool AllDone() const {
    return options_.stop_when_done &&
           std::all_of(robots_.begin(), robots_.end(), [](const RobotSlot& robot) { return robot.done; });
  }
  void MarkSilentRobotsLost(Clock::time_point now);
  void AdvanceWorld();
  /// Waiting for agents: starts the run once every robot has answered; ends
  /// it (the outcome) when they have not within start_timeout_s.
  std::optional<RunOutcome> StartWhenAllAnswered(Clock::time_point now, Clock::time_point* next_realtime_step);
  /// Running: whether the world may take its next step now (lockstep: every
  /// live robot answered; real time: its time came), marking silent robots lost.
  bool ReadyForNextStep(Clock::time_point now, Clock::time_point next_realtime_step);
  /// Steps the world and publishes the new step; the outcome when the run ends there.
  std::optional<RunOutcome> TakeStep();
  /// Publishes the step again when answers are awaited, then handles what arrives.
  void ResendStepAndListen(Clock::time_point now, Clock::time_point next_realtime_step);
  RunOutcome Finish(RunOutcome::End end, const std::string& reason);
  int64_t SimUtime() const;

  lcm::LcmInterface& lcm_;
  world::World& world_;
  std::vector<world::ObstacleState> obstacle_states_;  // scratch for PublishStep
  applied_commands_t applied_;                         // scratch for RecordApplied
  std::vector<uint8_t> encoded_;                       // scratch: the message being published or recorded
  std::vector<uint8_t> entry_encoded_;                 // scratch: a DREAM_CMDS entry as its DREAM_CMD_<id>
  RunRecorder* recorder_;
  int64_t recorder_failed_at_step_ = -1;
  config::SimNodeOptions options_;
  lcm::BadMessageLog bad_messages_;
  std::vector<RobotSlot> robots_;
  int8_t state_;
  int64_t run_id_;
  NodeClock clock_;               // before commands_, which reads it
  IntakeContext intake_context_;  // what commands_ and busy_ share; before them
  CommandIntake commands_;
  BusyIntake busy_;
  RadioIntake radio_;
  DrawingIntake drawings_;
  std::set<int64_t> other_worlds_;
  std::set<int> robots_ever_lost_;
  std::map<int, std::string> robot_faults_;
  Clock::time_point run_start_;
  Clock::time_point step_published_;
  Clock::time_point last_resend_;
  ProgressReporter* progress_ = nullptr;
  RefusedRecord* refused_ = nullptr;
  /// Last: unsubscribed first, before anything the handler uses is gone.
  lcm::Subscription subscription_;
};

}  // namespace dream::node
