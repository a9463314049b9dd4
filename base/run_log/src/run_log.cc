#include "dream/run_log/run_log.h"

#include <algorithm>
#include <limits>

#include "dream/drawing_t.hpp"
#include "dream/lcm/channels.h"
#include "dream/lcm/drawing_shapes.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/radio_message_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "dream/run_log/worlds_heard.h"

namespace dream::run_log {
namespace {

constexpr size_t kNone = std::numeric_limits<size_t>::max();

RecordedCommand RecordedOf(const velocity_command_t& command) {
  return {command.step, command.robot_id, command.agent_id, command.v, command.w, command.done != 0};
}

/// What agents sent (radio, faults, commands) and the world applied (DREAM_APPLIED), as a log
/// holds it, kept until the run's id and steps are known: another run's, a robot not of the run or
/// not its channel's, a step the log has no poses for, are no part of this run (the world refuses
/// them; older logs and recordings of the bus may hold them). Each message kept took at least its
/// own bytes of the file, so what is held is bounded by the file.
class AgentMessagesHeard {
 public:
  /// Takes `record` when it is on one of those channels and decodes.
  void Take(const lcm::LogRecord& record) {
    const uint8_t* data = record.data.data();
    const int size = static_cast<int>(record.data.size());
    if (const std::optional<int> sender = lcm::RobotIdFromChannel(record.channel, lcm::kRadioChannelPrefix)) {
      if (lcm::Decode(data, size, &radio_)) {
        radio_heard_.push_back({*sender, radio_.run_id, radio_.step, radio_.sender_id});
      }
    } else if (const std::optional<int> id = lcm::RobotIdFromChannel(record.channel, lcm::kFaultChannelPrefix)) {
      if (lcm::Decode(data, size, &fault_)) {
        faults_heard_.push_back({{*id, fault_.run_id, fault_.step, fault_.robot_id}, std::move(fault_.detail)});
      }
    } else if (const std::optional<int> robot = lcm::RobotIdFromCommandChannel(record.channel)) {
      if (lcm::Decode(data, size, &command_)) {
        commands_heard_.push_back({*robot, command_.run_id, RecordedOf(command_)});
      }
    } else if (const std::optional<int> lab = lcm::RobotIdFromChannel(record.channel, lcm::kLabCommandChannelPrefix)) {
      if (lcm::Decode(data, size, &command_)) lab_heard_.push_back({*lab, command_.run_id, RecordedOf(command_)});
    } else if (record.channel == lcm::kAppliedChannel) {
      if (lcm::Decode(data, size, &applied_)) applied_heard_.push_back(std::move(applied_));
    } else if (const std::optional<int> drawer = lcm::RobotIdFromChannel(record.channel, lcm::kDrawChannelPrefix)) {
      // A fresh message each time: lcm-gen's decoder leaves an array whose count is 0 as it was.
      drawing_ = drawing_t();
      if (lcm::Decode(data, size, &drawing_) && lcm::DrawingShapes::Problem(drawing_).empty()) {
        drawings_heard_.push_back(
            {{*drawer, drawing_.run_id, drawing_.step, drawing_.robot_id},
             {drawing_.step, drawing_.robot_id, drawing_.clipped, lcm::DrawingShapes::Of(drawing_)}});
      }
    }
  }

  /// RunLog::drawings(): the run's, by step then robot, the last heard of each robot and step.
  std::vector<RecordedDrawing> DrawingsOf(const RunLog& log) {
    std::vector<RecordedDrawing> kept;
    for (HeardDrawing& heard : drawings_heard_) {
      if (OfRun(heard.heard, log) && InSteps(heard.heard.step, log)) kept.push_back(std::move(heard.drawing));
    }
    std::stable_sort(kept.begin(), kept.end(), [](const RecordedDrawing& a, const RecordedDrawing& b) {
      return a.step != b.step ? a.step < b.step : a.robot_id < b.robot_id;
    });
    std::vector<RecordedDrawing> last;
    for (RecordedDrawing& drawing : kept) {
      if (!last.empty() && last.back().step == drawing.step && last.back().robot_id == drawing.robot_id) {
        last.back() = std::move(drawing);
      } else {
        last.push_back(std::move(drawing));
      }
    }
    return last;
  }

  /// RunLog::radio_sends() (before Index orders them).
  std::vector<RadioSend> RadioOf(const RunLog& log) const {
    std::vector<RadioSend> sends;
    for (const Heard& heard : radio_heard_) {
      if (OfRun(heard, log)) sends.push_back({heard.step, heard.robot_id});
    }
    return sends;
  }
  /// The first fault of each robot of the run: id -> "step k: detail" (bounded by lcm::Decode).
  std::map<int, std::string> FaultsOf(const RunLog& log) const {
    std::map<int, std::string> faults;
    for (const HeardFault& fault : faults_heard_) {
      const Heard& heard = fault.heard;
      if (OfRun(heard, log) && faults.count(heard.robot_id) == 0) {
        faults[heard.robot_id] = "step " + std::to_string(heard.step) + ": " + fault.detail;
      }
    }
    return faults;
  }
  /// RunLog::commands() (`lab`: lab_commands(), whose run id 0 is the run's too).
  std::vector<RecordedCommand> CommandsOf(const RunLog& log, bool lab) const {
    std::vector<RecordedCommand> kept;
    for (const HeardCommand& h : lab ? lab_heard_ : commands_heard_) {
      const bool run = h.run_id == log.run_id() || (lab && h.run_id == 0);
      if (run && h.command.robot_id == h.channel_id && h.command.robot_id < log.num_robots() &&
          InSteps(h.command.step, log)) {
        kept.push_back(h.command);
      }
    }
    // By step, then robot; the first heard of each robot and step stays.
    std::stable_sort(kept.begin(), kept.end(), [](const RecordedCommand& a, const RecordedCommand& b) {
      return a.step != b.step ? a.step < b.step : a.robot_id < b.robot_id;
    });
    kept.erase(std::unique(kept.begin(), kept.end(),
                           [](const RecordedCommand& a, const RecordedCommand& b) {
                             return a.step == b.step && a.robot_id == b.robot_id;
                           }),
               kept.end());
    return kept;
  }
  /// RunLog::applied(): the run's, for its robots and steps, the first of each step.
  std::vector<applied_commands_t> AppliedOf(const RunLog& log) {
    std::vector<applied_commands_t> kept;
    for (applied_commands_t& applied : applied_heard_) {
      if (applied.run_id == log.run_id() && applied.num_robots == log.num_robots() && InSteps(applied.step, log)) {
        kept.push_back(std::move(applied));
      }
    }
    std::stable_sort(kept.begin(), kept.end(),
                     [](const applied_commands_t& a, const applied_commands_t& b) { return a.step < b.step; });
    kept.erase(std::unique(kept.begin(), kept.end(),
                           [](const applied_commands_t& a, const applied_commands_t& b) { return a.step == b.step; }),
               kept.end());
    return kept;
  }

 private:
  struct Heard {
    int channel_id;
    int64_t run_id;
    int64_t step;
    int32_t robot_id;
  };
  struct HeardFault {
    Heard heard;
    std::string detail;
  };
  struct HeardDrawing {
    Heard heard;
    RecordedDrawing drawing;
  };
  struct HeardCommand {
    int channel_id;
    int64_t run_id;
    RecordedCommand command;
  };

  static bool OfRun(const Heard& heard, const RunLog& log) {
    return heard.run_id == log.run_id() && heard.robot_id == heard.channel_id && heard.robot_id < log.num_robots();
  }
  /// A step the log has poses for (none without poses).
  static bool InSteps(int64_t step, const RunLog& log) {
    return !log.poses().empty() && step >= log.first_step() && step <= log.last_step();
  }

  radio_message_t radio_;
  robot_fault_t fault_;
  velocity_command_t command_;
  applied_commands_t applied_;
  drawing_t drawing_;
  std::vector<Heard> radio_heard_;
  std::vector<HeardDrawing> drawings_heard_;
  std::vector<HeardFault> faults_heard_;
  std::vector<HeardCommand> commands_heard_;
  std::vector<HeardCommand> lab_heard_;
  std::vector<applied_commands_t> applied_heard_;
};

}  // namespace

RunLog RunLog::Read(const std::string& path) {
  RunLog log;
  log.path_ = path;
  lcm::LogReader reader(path);
  lcm::LogRecord record;
  run_status_t status;
  AgentMessagesHeard heard;
  WorldsHeard worlds;
  std::vector<run_verdict_t> verdicts;  // at most one a run; bounded by the log's own bytes
  // A world message that does not decode: named by its event and byte offset.
  auto undecodable = [&](std::optional<Problem>* flaw, const std::string& problem) {
    if (*flaw) return;
    *flaw = Problem{reader.event_index(), path + ": event " + std::to_string(reader.event_index()) + " at byte " +
                                              std::to_string(reader.event_offset()) + ": a " + record.channel +
                                              " message cannot be decoded; in the message: " + problem};
  };
  while (reader.Next(&record)) {
    const uint8_t* data = record.data.data();
    const int size = static_cast<int>(record.data.size());
    if (record.channel == lcm::kPosesChannel) {
      robot_poses_t poses;
      if (auto problem = lcm::DecodeProblem(data, size, &poses)) {
        undecodable(&log.world_flaw_, *problem);
        continue;
      }
      worlds.AddPoses(std::move(poses), reader.event_index());
    } else if (record.channel == lcm::kMeasuredPosesChannel) {
      robot_poses_t measured;
      if (lcm::Decode(data, size, &measured)) worlds.AddMeasured(std::move(measured));  // else not the world's record
    } else if (record.channel == lcm::kObstaclesChannel) {
      obstacles_t& obstacles = log.obstacles_.emplace_back();
      if (auto problem = lcm::DecodeProblem(data, size, &obstacles)) {
        log.obstacles_.pop_back();
        undecodable(&log.world_flaw_, *problem);
      }
    } else if (record.channel == lcm::kStatusChannel) {
      if (auto problem = lcm::DecodeProblem(data, size, &status)) {
        undecodable(&log.status_flaw_, *problem);
      } else {
        worlds.AddStatus(std::move(status));
      }
    } else if (record.channel == lcm::kVerdictChannel) {
      if (run_verdict_t verdict; lcm::Decode(data, size, &verdict)) verdicts.push_back(std::move(verdict));
    } else {
      heard.Take(record);
    }
  }
  log.TakeRun(std::move(worlds));
  for (run_verdict_t& verdict : verdicts) {
    if (verdict.run_id == log.run_id_) log.verdict_ = std::move(verdict);  // another run's is no part of this one
  }
  log.radio_sends_ = heard.RadioOf(log);
  log.Index(heard.FaultsOf(log));
  log.commands_ = heard.CommandsOf(log, /*lab=*/false);
  log.lab_commands_ = heard.CommandsOf(log, /*lab=*/true);
  log.applied_ = heard.AppliedOf(log);
  log.drawings_ = heard.DrawingsOf(log);
  return log;
}

void RunLog::TakeRun(WorldsHeard worlds) {
  WorldsHeard::World* followed = worlds.Followed();
  if (followed == nullptr) return;
  run_id_ = followed->run_id;
  resends_ = followed->resends;
  for (const WorldsHeard::World& other : worlds.worlds()) {
    if (&other != followed) other_run_ids_.push_back(other.run_id);
  }
  poses_ = std::move(followed->poses);
  measured_poses_ = std::move(followed->measured);
  last_status_ = std::move(followed->last_status);
  for (const robot_poses_t& poses : poses_) num_robots_ = std::max(num_robots_, poses.num_robots);
  // A foreign world's obstacles are no part of this run's.
  obstacles_.erase(std::remove_if(obstacles_.begin(), obstacles_.end(),
                                  [this](const obstacles_t& o) { return o.run_id != run_id_; }),
                   obstacles_.end());
  CheckSequence(followed->events);
}

void RunLog::CheckSequence(const std::vector<int64_t>& events) {
  for (size_t i = 0; i < poses_.size(); ++i) {
    // The flaw that shows first in the log is the log's.
    if (world_flaw_ && world_flaw_->event_index < events[i]) return;
    const robot_poses_t& poses = poses_[i];
    // Whole so far, so the poses before this one are steps 0 .. expected - 1.
    const auto expected = static_cast<int64_t>(i);
    std::string problem;
    if (poses.step == expected - 1) {
      problem = "two different DREAM_POSES for step " + std::to_string(poses.step) +
                " of one run; a run log has every step once (a resend is the same message again)";
    } else if (poses.step != expected) {
      problem = "DREAM_POSES jumps from step " + std::to_string(expected - 1) + " to step " +
                std::to_string(poses.step) + "; a run log has every step once, in order";
    } else if (expected == 0 && poses.num_robots < 1) {
      problem = "DREAM_POSES at step 0 has no robots";
    } else if (poses.num_robots != poses_.front().num_robots) {
      problem = "DREAM_POSES at step " + std::to_string(poses.step) + " has " + std::to_string(poses.num_robots) +
                " robots, earlier steps " + std::to_string(poses_.front().num_robots);
    }
    if (!problem.empty()) {
      world_flaw_ = Problem{events[i], path_ + ": " + problem};
      return;
    }
  }
}

void RunLog::Index(const std::map<int, std::string>& faults) {
  // The world publishes a step's obstacles next to its poses, in either order:
  // match them by step, not by position in the log.
  std::stable_sort(obstacles_.begin(), obstacles_.end(),
                   [](const obstacles_t& a, const obstacles_t& b) { return a.step < b.step; });
  std::stable_sort(radio_sends_.begin(), radio_sends_.end(),
                   [](const RadioSend& a, const RadioSend& b) { return a.step < b.step; });
  obstacle_index_.reserve(poses_.size());
  size_t next = 0;  // obstacles_[0 .. next) are at or before the current pose's step
  for (const robot_poses_t& poses : poses_) {
    while (next < obstacles_.size() && obstacles_[next].step <= poses.step) ++next;
    obstacle_index_.push_back(next == 0 ? kNone : next - 1);
  }
  if (!last_status_) return;
  for (int id : last_status_->lost_robot_ids) {
    const auto fault = faults.find(id);
    if (fault != faults.end()) robot_faults_[id] = fault->second;
  }
}

size_t RunLog::PoseIndexAtStep(int64_t step) const {
  const auto after = std::upper_bound(poses_.begin(), poses_.end(), step,
                                      [](int64_t s, const robot_poses_t& poses) { return s < poses.step; });
  return after == poses_.begin() ? 0 : static_cast<size_t>(after - poses_.begin() - 1);
}

const obstacles_t& RunLog::obstacles_at(size_t pose_index) const {
  static const obstacles_t kNoObstacles{};
  const size_t index = obstacle_index_.at(pose_index);
  return index == kNone ? kNoObstacles : obstacles_[index];
}

std::optional<std::string> RunLog::Flaw(bool with_status) const {
  const Problem* first = world_flaw_ ? &*world_flaw_ : nullptr;
  if (with_status && status_flaw_ && (first == nullptr || status_flaw_->event_index < first->event_index)) {
    first = &*status_flaw_;
  }
  if (first != nullptr) return first->text;
  if (poses_.empty()) return path_ + ": the log holds no DREAM_POSES messages: it is not a run log";
  return std::nullopt;
}

}  // namespace dream::run_log
