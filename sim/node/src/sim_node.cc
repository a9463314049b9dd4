#include "dream/node/sim_node.h"

#include <spdlog/spdlog.h>

#include <cmath>
#include <optional>
#include <utility>
#include <stdexcept>
#include <thread>

#include "dream/applied_commands_t.hpp"
#include "dream/config/controller_config.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/message_limits.h"
#include "dream/lcm/run_id.h"
#include "dream/lcm/wire_text.h"
#include "dream/node/world_messages.h"
#include "dream/obstacles_t.hpp"
#include "dream/node/refused_record.h"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/node/progress_reporter.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/node/run_recorder.h"
#include "dream/velocity_command_t.hpp"

namespace dream::node {

// A sim_only run's robots are published in one DREAM_POSES, which receivers
// refuse past the bus's bound.
static_assert(config::ControllerConfig::kMaxRobotsSimOnly == lcm::MessageLimits::kRobots,
              "sim_only's robot limit must be what one message of the bus carries");

namespace {

double SecondsBetween(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

std::string JoinIds(const std::vector<int>& ids) {
  std::string text;
  for (int id : ids) text += (text.empty() ? "" : ", ") + std::to_string(id);
  return text;
}

}  // namespace

SimNode::SimNode(lcm::LcmInterface& lcm, world::World& world, RunRecorder* recorder, config::SimNodeOptions options)
    : lcm_(lcm),
      world_(world),
      recorder_(recorder),
      options_(options),
      robots_(static_cast<size_t>(world.num_robots())),
      state_(run_status_t::WAITING_FOR_AGENTS),
      run_id_(lcm::NewRunId()),
      intake_context_{world,
                      options_,
                      run_id_,
                      robots_,
                      bad_messages_,
                      clock_,
                      [this](int64_t run_id, const std::string& seen_on) { NoteOtherWorld(run_id, seen_on); }},
      commands_(intake_context_),
      busy_(intake_context_),
      radio_(world, run_id_, bad_messages_),
      drawings_(world, run_id_, bad_messages_) {
  std::string error;
  if (!options_.IsValid(&error)) throw std::invalid_argument("sim options: " + error);
  bad_messages_.set_step(world_.step());
  // One handler hears everything, so that what each message turned out to be
  // (used or refused) decides where it is recorded; everything but the
  // world's own poses and obstacles, which OnMessage would drop anyway: over
  // udpm each comes back every step, and LCM now drops them in its receive
  // thread instead of waking this one (docs/performance.md).
  subscription_ = lcm_.Subscribe(
      std::string("(?!") + lcm::kPosesChannel + "$|" + lcm::kObstaclesChannel + "$).*",
      [this](const std::string& channel, const void* data, int size) { OnMessage(channel, data, size); });
}

int64_t SimNode::SimUtime() const { return world_.utime(); }

void SimNode::Record(const std::string& channel, const void* data, int size) {
  if (recorder_ == nullptr || recorder_->failed()) return;
  try {
    recorder_->Write(channel, SimUtime(), data, size);
  } catch (const std::runtime_error&) {
    // Not thrown on: this may run inside an LCM handler, where LcmBus would
    // count it and carry on. The recorder stays failed; Run() ends the run.
    recorder_failed_at_step_ = world_.step();
  }
}

bool SimNode::RecorderFailed() const { return recorder_ != nullptr && recorder_->failed(); }

std::string SimNode::RecorderFailureReason() const {
  const int64_t step = recorder_failed_at_step_ >= 0 ? recorder_failed_at_step_ : world_.step();
  return "the run log could not be written at step " + std::to_string(step) + ": " + recorder_->failure();
}

void SimNode::RecordApplied() {
  if (recorder_ == nullptr) return;
  // A member, so the step loop reuses its vectors' capacity.
  applied_commands_t& applied = applied_;
  applied.applied_agent_id.clear();
  applied.commanded_v.clear();
  applied.commanded_w.clear();
  applied.conflicts.clear();
  applied.utime = SimUtime();
  applied.step = world_.step();
  applied.run_id = run_id_;
  applied.num_robots = world_.num_robots();
  const bool lockstep = options_.mode == config::WorldMode::kLockstep;
  for (const RobotSlot& robot : robots_) {
    const bool driven = !robot.lost && (lockstep ? Answered(robot) : robot.command_step >= 0);
    applied.applied_agent_id.push_back(driven ? robot.owner_agent_id : 0);
    applied.commanded_v.push_back(driven ? robot.v_mps : 0.0);
    applied.commanded_w.push_back(driven ? robot.w_radps : 0.0);
    applied.conflicts.push_back(robot.command_step == world_.step() ? robot.conflicts : 0);
  }
  const int size = applied.getEncodedSize();
  encoded_.resize(static_cast<size_t>(size));
  applied.encode(encoded_.data(), 0, size);
  Record(lcm::kAppliedChannel, encoded_.data(), size);
}

template <typename Message>
void SimNode::PublishAndRecord(const char* channel, const Message& message, bool record) {
  const int size = message.getEncodedSize();
  encoded_.resize(static_cast<size_t>(size));
  message.encode(encoded_.data(), 0, size);
  lcm_.Publish(channel, encoded_.data(), size);
  if (record) Record(channel, encoded_.data(), size);
}

void SimNode::PublishStatus(int8_t state, const std::string& detail, bool record) {
  run_status_t status;
  status.utime = SimUtime();
  status.run_id = run_id_;
  status.state = state;
  WorldMessages::Fill(world_, &status);
  status.rejected_commands = commands_.rejected_commands();
  status.command_conflicts = commands_.command_conflicts();
  for (size_t i = 0; i < robots_.size(); ++i) {
    if (robots_[i].lost) status.lost_robot_ids.push_back(static_cast<int32_t>(i));
  }
  status.num_lost = static_cast<int32_t>(status.lost_robot_ids.size());
  // The reason may quote a path or URL we were given: sent as a string the bus accepts.
  status.detail = lcm::WireText::Of(detail, lcm::MessageLimits::kDetailBytes);
  PublishAndRecord(lcm::kStatusChannel, status, record);
}

void SimNode::PublishStep(bool record) {
  obstacles_t obstacles;
  obstacles.utime = SimUtime();
  obstacles.run_id = run_id_;
  WorldMessages::Fill(world_, &obstacle_states_, &obstacles);
  PublishAndRecord(lcm::kObstaclesChannel, obstacles, record);

  PublishStatus(state_, state_ == run_status_t::WAITING_FOR_AGENTS ? "waiting for agents" : "running", record);

  robot_poses_t poses;
  poses.utime = SimUtime();
  poses.run_id = run_id_;
  WorldMessages::Fill(world_, &poses);
  PublishAndRecord(lcm::kPosesChannel, poses, record);
}

bool SimNode::StartHeld(Clock::time_point now) {
  DrainArrived();  // what has arrived counts before the start is given up
  return AllLiveAnswered() || busy_.HoldsStart(now, step_published_);
}

void SimNode::DrainArrived() {
  for (int handled = 0; handled < 10000 && lcm_.HandleSubscriptions(0) > 0; ++handled) {
  }
}

bool SimNode::AllRobotsLost() const {
  for (const RobotSlot& robot : robots_) {
    if (!robot.lost) return false;
  }
  return true;
}

bool SimNode::AllLiveAnswered() const {
  for (const RobotSlot& robot : robots_) {
    if (!Answered(robot) && !robot.lost) return false;
  }
  return true;
}

void SimNode::MarkSilentRobotsLost(Clock::time_point now) {
  std::vector<int> newly_lost;
  for (size_t i = 0; i < robots_.size(); ++i) {
    RobotSlot& robot = robots_[i];
    const bool silent = options_.mode == config::WorldMode::kLockstep
                            ? !Answered(robot) && !busy_.Holds(robot, now, step_published_)
                            : SecondsBetween(robot.last_heard, now) > options_.agent_timeout_s;
    if (silent && !robot.lost) {
      robot.lost = true;
      robots_ever_lost_.insert(static_cast<int>(i));
      world_.StopRobot(static_cast<int>(i));
      newly_lost.push_back(static_cast<int>(i));
    }
  }
  if (!newly_lost.empty()) {
    spdlog::warn(
        "step {}: no command for {:.1f} s from robot(s) {}: marked lost, their robots stop; "
        "they rejoin when their agent speaks again",
        world_.step(), SecondsBetween(step_published_, now), JoinIds(newly_lost));
  }
}

void SimNode::AdvanceWorld() {
  RecordApplied();
  if (options_.mode == config::WorldMode::kLockstep) {
    for (size_t i = 0; i < robots_.size(); ++i) {
      RobotSlot& robot = robots_[i];
      const int id = static_cast<int>(i);
      if (Answered(robot)) {
        world_.SetCommand(id, world::UnicycleCommand{robot.v_mps, robot.w_radps});
      } else {
        world_.StopRobot(id);
      }
    }
  }
  world_.Step();
  bad_messages_.set_step(world_.step());
}

RunOutcome SimNode::Finish(RunOutcome::End end, const std::string& reason) {
  const int8_t state = end == RunOutcome::End::kFinished ? run_status_t::FINISHED : run_status_t::ABORTED;
  state_ = state;
  if (progress_ != nullptr) {
    const auto now = clock_.now();
    progress_->Update(world_.step(), now);
    progress_->Finish(now);
  }
  PublishStatus(state, reason, true);
  // Agents exit on this message; repeat it (unrecorded) so one lost datagram
  // does not leave them waiting for their idle timeout.
  PublishStatus(state, reason, false);
  PublishStatus(state, reason, false);
  RunOutcome outcome;
  outcome.end = end;
  outcome.reason = reason;
  if (recorder_ != nullptr && !recorder_->failed()) {
    // A full disk may only show when the last buffered events reach it.
    try {
      recorder_->Flush();
    } catch (const std::runtime_error&) {
      recorder_failed_at_step_ = world_.step();
    }
  }
  if (RecorderFailed()) {
    // The log lacks the end of the run, whatever else ended it.
    outcome.end = RunOutcome::End::kFailed;
    outcome.reason = RecorderFailureReason();
  }
  outcome.steps = world_.step();
  outcome.wall_time_s = SecondsBetween(run_start_, clock_.now());
  outcome.rejected_commands = commands_.rejected_commands();
  outcome.command_conflicts = commands_.command_conflicts();
  outcome.run_id = run_id_;
  outcome.other_worlds = other_worlds_;
  outcome.robots_ever_lost = robots_ever_lost_;
  outcome.robot_faults = robot_faults_;
  for (size_t i = 0; i < robots_.size(); ++i) {
    if (robots_[i].done) outcome.robots_done.insert(static_cast<int>(i));
  }
  outcome.bad_messages = bad_messages_.per_channel();
  outcome.bad_message_senders = bad_messages_.senders();
  if (refused_ != nullptr) {
    outcome.refused = refused_->per_channel();
    refused_->Close();
    if (refused_->events_kept() > 0) outcome.refused_log = refused_->path();
    outcome.refused_log_events = refused_->events_kept();
  }
  for (const auto& [channel, first] : bad_messages_.first()) {
    outcome.bad_message_first[channel] = "step " + std::to_string(first.step) + ": " + first.reason;
  }
  outcome.handler_failures = lcm_.handler_failures();
  outcome.dropped_messages = lcm_.dropped_messages();
  outcome.log_events = recorder_ != nullptr ? recorder_->events_written() : 0;
  return outcome;
}

std::optional<RunOutcome> SimNode::StartWhenAllAnswered(Clock::time_point now, Clock::time_point* next_realtime_step) {
  if (AllLiveAnswered()) {
    state_ = run_status_t::RUNNING;
    spdlog::info("all {} robots have agents; running ({})", world_.num_robots(), config::WorldModeName(options_.mode));
    *next_realtime_step = now;
    if (progress_ != nullptr) progress_->Start(options_.max_steps, world_.step(), now);
    // Agents answered step 0; in real time their answer is the latest command.
  } else if (SecondsBetween(step_published_, now) > options_.start_timeout_s && !StartHeld(now)) {
    std::vector<int> missing;
    for (size_t i = 0; i < robots_.size(); ++i) {
      if (!Answered(robots_[i])) missing.push_back(static_cast<int>(i));
    }
    return Finish(RunOutcome::End::kStartTimeout,
                  "no agent answered for robot(s) " + JoinIds(missing) + " within " +
                      std::to_string(static_cast<int>(options_.start_timeout_s)) +
                      " s; start them (dream agent --robots ...) on the same LCM URL " + lcm_.url() +
                      ", or, if they were started and are still starting (many Python agents on few cores), "
                      "raise world.start_timeout_s");
  }
  return std::nullopt;
}

bool SimNode::ReadyForNextStep(Clock::time_point now, Clock::time_point next_realtime_step) {
  if (options_.mode == config::WorldMode::kLockstep) {
    if (!AllLiveAnswered() && SecondsBetween(step_published_, now) > options_.agent_timeout_s) {
      DrainArrived();  // what has arrived counts before a robot is called silent
      MarkSilentRobotsLost(now);
    }
    return AllLiveAnswered() && (options_.pace <= 0.0 || now >= next_realtime_step);
  }
  const bool ready = now >= next_realtime_step;
  if (ready) MarkSilentRobotsLost(now);
  return ready;
}

std::optional<RunOutcome> SimNode::TakeStep() {
  if (options_.script_ends_run && robot_faults_.size() == robots_.size()) {  // before this step: the script's end
    return Finish(RunOutcome::End::kFinished, "the script failed at " + robot_faults_.begin()->second);
  }
  if (options_.script_ends_run && AllDone()) return Finish(RunOutcome::End::kFinished, "every robot reported done");
  AdvanceWorld();
  const bool all_done = AllDone();
  const bool world_ended = world_.step() >= world_.last_step();
  if (world_.step() >= options_.max_steps || all_done || world_ended) {
    PublishStep(true);
    return Finish(RunOutcome::End::kFinished, all_done      ? "every robot reported done"
                                              : world_ended ? "the world has no more steps (end of the recording)"
                                                            : "reached the step limit");
  }
  PublishStep(true);
  step_published_ = last_resend_ = clock_.now();
  if (progress_ != nullptr) progress_->Update(world_.step(), step_published_);
  // With every robot lost nothing holds a lockstep world back, but what
  // has arrived is still read each step (the in-process agents' answers
  // to this step included): late faults are recorded, and an agent that
  // speaks again rejoins (it would never be heard otherwise).
  if (options_.mode == config::WorldMode::kLockstep && AllRobotsLost()) DrainArrived();
  return std::nullopt;
}

void SimNode::ResendStepAndListen(Clock::time_point now, Clock::time_point next_realtime_step) {
  const bool lockstep = options_.mode == config::WorldMode::kLockstep;
  // While waiting for answers, publish the step again: a datagram may have
  // been lost, or agents started after the world. Agents answer idempotently.
  const bool waiting = lockstep || state_ == run_status_t::WAITING_FOR_AGENTS;
  if (waiting && SecondsBetween(last_resend_, now) > options_.resend_interval_s) {
    PublishStep(false);
    last_resend_ = now;
  }
  int timeout_ms = 10;
  const bool paced = !lockstep || options_.pace > 0.0;
  if (paced && state_ == run_status_t::RUNNING && (!lockstep || AllLiveAnswered())) {
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(next_realtime_step - clock_.now());
    timeout_ms = static_cast<int>(std::max<int64_t>(0, std::min<int64_t>(wait.count(), 10)));
  }
  lcm_.HandleSubscriptions(timeout_ms);
}

RunOutcome SimNode::Run(const std::atomic<bool>& stop) {
  run_start_ = clock_.now();
  state_ = run_status_t::WAITING_FOR_AGENTS;
  PublishStep(true);
  step_published_ = last_resend_ = clock_.now();
  // Real time: one world step per time step of wall time (over the pace).
  // Lockstep with a pace: no step sooner than that, to watch the run.
  const bool lockstep = options_.mode == config::WorldMode::kLockstep;
  const double pace = options_.pace > 0.0 ? options_.pace : 1.0;
  const auto step_period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(world_.time_step_s() / pace));
  Clock::time_point next_realtime_step;

  while (true) {
    if (RecorderFailed()) return Finish(RunOutcome::End::kFailed, RecorderFailureReason());
    if (stop.load()) return Finish(RunOutcome::End::kInterrupted, "interrupted (Ctrl-C or SIGTERM)");
    const auto now = clock_.now();
    if (state_ == run_status_t::WAITING_FOR_AGENTS) {
      if (std::optional<RunOutcome> timed_out = StartWhenAllAnswered(now, &next_realtime_step))
        return std::move(*timed_out);
    }
    if (state_ == run_status_t::RUNNING && ReadyForNextStep(now, next_realtime_step)) {
      next_realtime_step += step_period;
      // Paced lockstep behind its pace (slow agents): no burst to catch up.
      if (lockstep && next_realtime_step < now) next_realtime_step = now;
      if (std::optional<RunOutcome> finished = TakeStep()) return std::move(*finished);
      continue;
    }
    ResendStepAndListen(now, next_realtime_step);
  }
}

}  // namespace dream::node
