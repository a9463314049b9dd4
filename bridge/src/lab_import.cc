#include "dream/bridge/lab_import.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dream/bridge/controller_module_copy.h"
#include "dream/bridge/lab_replay_world.h"
#include "dream/formats/mat_file.h"
#include "dream/bridge/pre_validation.h"
#include "dream/files/file_text.h"
#include "dream/files/output_folder.h"
#include "dream/files/output_folder_lock.h"
#include "dream/files/regular_file.h"
#include "dream/bridge/submission_format.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/message_limits.h"
#include "dream/lcm/run_id.h"
#include "dream/lcm/wire_text.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/world/rectangle_obstacle.h"
#include "dream/node/run_judge.h"
#include "dream/node/run_outcome.h"
#include "dream/node/run_recorder.h"
#include "dream/node/world_messages.h"
#include "dream/velocity_command_t.hpp"

namespace dream::bridge {
namespace {

namespace fs = std::filesystem;

/// The largest |x|, |y| (m) and |theta| (rad), and |v|, |w|, an imported
/// result may hold: far beyond any arena and any robot.
constexpr double kMaxAbsPose = 1000.0;
constexpr double kMaxAbsCommand = 1e6;

/// "x of robot 3" for a result column.
std::string ColumnMeaning(int64_t column, int num_robots) {
  switch (column) {
    case ResultLayout::kPhaseColumn:
      return "the phase column";
    case ResultLayout::kStepColumn:
      return "the step column";
    case ResultLayout::kWallTimeColumn:
      return "the wall-clock column";
    default:
      break;
  }
  static const char* kNames[] = {"x", "y", "theta", "v", "w"};
  const int64_t index = column - ResultLayout::kFixedColumns;
  return std::string(kNames[index / num_robots]) + " of robot " + std::to_string(index % num_robots);
}

std::vector<std::vector<world::ObstacleState>> ObstaclesPerStep(const std::vector<world::RectangleObstacleSpec>& specs,
                                                                int64_t last_step, double time_step_s) {
  std::vector<world::RectangleObstacle> obstacles(specs.begin(), specs.end());
  std::vector<std::vector<world::ObstacleState>> states(static_cast<size_t>(last_step + 1));
  for (auto& step_states : states) {
    for (world::RectangleObstacle& o : obstacles) {
      step_states.push_back(o.State());
      o.Advance(time_step_s);
    }
  }
  return states;
}

template <typename Message>
void WriteMessage(node::RunRecorder& recorder, const std::string& channel, int64_t utime, const Message& message,
                  std::vector<uint8_t>* buffer) {
  buffer->resize(static_cast<size_t>(message.getEncodedSize()));
  message.encode(buffer->data(), 0, static_cast<int>(buffer->size()));
  recorder.Write(channel, utime, buffer->data(), static_cast<int>(buffer->size()));
}

void WriteStatus(node::RunRecorder& recorder, const world::World& world, int64_t run_id, int8_t state,
                 const std::string& detail, std::vector<uint8_t>* buffer) {
  run_status_t status;
  status.utime = world.utime();
  status.run_id = run_id;
  status.state = state;
  node::WorldMessages::Fill(world, &status);
  status.rejected_commands = 0;
  status.command_conflicts = 0;
  status.num_lost = 0;
  status.detail = lcm::WireText::Of(detail, lcm::MessageLimits::kDetailBytes);
  WriteMessage(recorder, lcm::kStatusChannel, world.utime(), status, buffer);
}

/// An imported lab run's id: derived from its poses (FNV-1a), so importing the
/// same lab data twice (from .npy or .mat) writes the same log; never 0.
int64_t ImportedRunId(const RunTrack& track) {
  uint64_t hash = 1469598103934665603ULL;
  auto mix = [&hash](const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ULL;
  };
  mix(&track.num_robots, sizeof(track.num_robots));
  for (const world::Pose2& pose : track.poses) mix(&pose, sizeof(pose));
  return hash == 0 ? 1 : static_cast<int64_t>(hash);
}

/// Writes the log and returns the world stepped to the end (for the summary).
LabReplayWorld WriteLog(const RunTrack& track, const world::WorldParams& params, int8_t end_state,
                        const std::string& detail, const std::string& log_path, int64_t* events = nullptr) {
  LabReplayWorld world(track, params);
  node::RunRecorder recorder(log_path, 4096);
  std::vector<uint8_t> buffer;
  std::vector<world::ObstacleState> states;
  obstacles_t obstacles;
  robot_poses_t poses;
  velocity_command_t command;
  const int64_t run_id = ImportedRunId(track);
  obstacles.run_id = run_id;
  poses.run_id = run_id;
  command.run_id = run_id;
  command.agent_id = 0;
  command.done = false;
  const int n = track.num_robots;
  std::vector<std::string> command_channels;
  for (int i = 0; i < n; ++i) command_channels.push_back(lcm::CommandChannel(i));
  while (true) {
    const int64_t k = world.step();
    const int64_t utime = world.utime();
    // The messages SimNode would send on this world (velocities zero at step 0).
    node::WorldMessages::Fill(world, &states, &obstacles);
    obstacles.utime = utime;
    WriteMessage(recorder, lcm::kObstaclesChannel, utime, obstacles, &buffer);
    WriteStatus(recorder, world, run_id, run_status_t::RUNNING, "lab run", &buffer);
    node::WorldMessages::Fill(world, &poses);
    poses.utime = utime;
    WriteMessage(recorder, lcm::kPosesChannel, utime, poses, &buffer);
    if (k == world.last_step()) break;
    command.utime = utime;
    command.step = k;
    for (int i = 0; i < n; ++i) {
      const world::UnicycleCommand& sent = track.command(k, i);
      command.robot_id = i;
      command.v = sent.v_mps;
      command.w = sent.w_radps;
      WriteMessage(recorder, command_channels[static_cast<size_t>(i)], utime, command, &buffer);
    }
    world.Step();
  }
  WriteStatus(recorder, world, run_id, end_state, detail, &buffer);
  recorder.Close();
  if (events != nullptr) *events = recorder.events_written();
  return world;
}

}  // namespace

formats::NpyArray ReadResultFile(const std::string& path, int64_t max_values) {
  char head[8] = {};
  ssize_t got = 0;
  {
    const files::RegularFile file(path);  // a FIFO or device is refused, not waited on
    got = ::pread(file.descriptor(), head, sizeof(head), 0);
    if (got < 0) throw std::runtime_error(path + ": cannot read the file: " + std::strerror(errno));
  }
  if (got >= 6 && std::memcmp(head, "\x93NUMPY", 6) == 0) return formats::ReadNpyFile(path);
  // MATLAB v5/v7.3 files start with a text header ("MATLAB 5.0 MAT-file"); v4 has none.
  const std::string extension = fs::path(path).extension().string();
  if ((got >= 6 && std::memcmp(head, "MATLAB", 6) == 0) || extension == ".mat") {
    return formats::ReadMatMatrix(path, SubmissionFiles::kResultMatVariable, max_values);
  }
  throw std::runtime_error(path + ": neither a .npy file nor a MATLAB .mat file; pass the " + SubmissionFiles::kResult +
                           " the submission saved");
}

namespace {

/// Throws "<file>: <problem>" for a result file's problem.
struct ResultFileError {
  const std::string& name;
  [[noreturn]] void operator()(const std::string& problem) const { throw std::runtime_error(name + ": " + problem); }
};

/// The array's shape for `n` robots, and every value finite and within reach.
void CheckResultValues(const formats::NpyArray& rows, int n, const ResultFileError& fail) {
  if (rows.shape.size() != 2) {
    fail("has " + std::to_string(rows.shape.size()) + " dimensions; a result is a 2-D array (rows x " +
         std::to_string(ResultLayout::Columns(n)) + " columns)");
  }
  const int64_t row_count = rows.shape[0];
  const int64_t columns = rows.shape[1];
  if (columns != ResultLayout::Columns(n)) {
    const int64_t robots = (columns - ResultLayout::kFixedColumns) / 5;
    const bool other_run = columns > ResultLayout::kFixedColumns && (columns - ResultLayout::kFixedColumns) % 5 == 0;
    fail("has " + std::to_string(columns) + " columns" +
         (other_run ? ", as a result of a " + std::to_string(robots) + "-robot run;" : ";") + " this export has " +
         std::to_string(n) + " robots, whose results have " + std::to_string(ResultLayout::Columns(n)) + " (3 + 5 x " +
         std::to_string(n) + "): is it the result of another export?");
  }
  if (row_count == 0) fail("holds no rows: the script stopped before its first step (see the lab's output)");
  for (int64_t r = 0; r < row_count; ++r) {
    for (int64_t c = 0; c < columns; ++c) {
      const double value = rows.values[static_cast<size_t>(r * columns + c)];
      if (!std::isfinite(value)) {
        fail("row " + std::to_string(r) + ": " + ColumnMeaning(c, n) + " is " + std::to_string(value) +
             "; every value must be finite");
      }
      // No tracker reports a robot a kilometre away: such a value is a broken
      // file, and its square would overflow the comparisons.
      const bool pose = c >= ResultLayout::kFixedColumns && c < ResultLayout::kFixedColumns + 3 * int64_t{n};
      const double limit = pose ? kMaxAbsPose : kMaxAbsCommand;
      if (c >= ResultLayout::kFixedColumns && std::abs(value) > limit) {
        char shown[32];
        std::snprintf(shown, sizeof(shown), "%g", value);
        fail("row " + std::to_string(r) + ": " + ColumnMeaning(c, n) + " is " + shown + "; beyond " +
             std::to_string(static_cast<int64_t>(limit)) + " in magnitude no lab value is meant");
      }
    }
  }
}

/// Where a result's phases lie: settle rows, experiment rows, the final pose.
struct ResultPhases {
  int64_t settle = 0;
  int64_t first_experiment_row = 0;
  int64_t experiment = 0;
  bool final_row = false;
  int64_t pose_rows() const { return experiment + (final_row ? 1 : 0); }
};

/// Phases in order: settle 0..s-1, experiment 0..e-1, then the final pose.
ResultPhases FindPhases(const formats::NpyArray& rows, const SubmissionParams& params, const ResultFileError& fail) {
  const int64_t row_count = rows.shape[0];
  const int64_t columns = rows.shape[1];
  auto at = [&](int64_t r, int64_t c) { return rows.values[static_cast<size_t>(r * columns + c)]; };
  ResultPhases phases;
  int64_t r = 0;
  for (; r < row_count && at(r, ResultLayout::kPhaseColumn) == ResultLayout::kPhaseSettle; ++r, ++phases.settle) {
    if (at(r, ResultLayout::kStepColumn) != static_cast<double>(phases.settle)) {
      fail("row " + std::to_string(r) + ": settle step " + std::to_string(at(r, ResultLayout::kStepColumn)) +
           ", expected " + std::to_string(phases.settle) + " (rows must follow each other)");
    }
    if (phases.settle >= params.options.settle_max_steps) {
      fail("has more than the " + std::to_string(params.options.settle_max_steps) +
           " settle steps the export allows: not a result of this export");
    }
  }
  phases.first_experiment_row = r;
  int64_t& experiment = phases.experiment;
  for (; r < row_count && at(r, ResultLayout::kPhaseColumn) == ResultLayout::kPhaseExperiment; ++r, ++experiment) {
    if (at(r, ResultLayout::kStepColumn) != static_cast<double>(experiment)) {
      fail("row " + std::to_string(r) + ": experiment step " + std::to_string(at(r, ResultLayout::kStepColumn)) +
           ", expected " + std::to_string(experiment) + " (rows must follow each other)");
    }
    if (experiment >= params.steps) {
      fail("has more experiment steps than the " + std::to_string(params.steps) +
           " the export planned: it is not a result of this export");
    }
  }
  if (r < row_count && at(r, ResultLayout::kPhaseColumn) == ResultLayout::kPhaseFinal) {
    // The controller strategy may stop before its step limit, once every robot reports done.
    const bool early_end_allowed = params.options.strategy == Strategy::kController && params.stop_when_done;
    if ((experiment != params.steps && !early_end_allowed) ||
        at(r, ResultLayout::kStepColumn) != static_cast<double>(experiment)) {
      fail("row " + std::to_string(r) + ": a final pose after " + std::to_string(experiment) + " of " +
           std::to_string(params.steps) + " planned steps; the file is damaged");
    }
    phases.final_row = true;
    ++r;
  }
  if (r < row_count) {
    const double phase = at(r, ResultLayout::kPhaseColumn);
    fail(
        "row " + std::to_string(r) + ": phase " + std::to_string(phase) +
        (phase == 0 || phase == 1 || phase == 2 ? " out of order" : " is not 0 (settle), 1 (experiment) or 2 (final)") +
        "; the file is damaged or not a dream result");
  }
  if (phases.pose_rows() < 2) {
    fail("has " + std::to_string(phases.pose_rows()) + " experiment poses; at least 2 are needed (the lab run " +
         "stopped right at its start: see the lab's output)");
  }
  return phases;
}

/// The experiment rows as the track: poses, commands sent, the lab's clock
/// from step 0 (a stamp earlier than its predecessor held at it).
void FillTrack(const formats::NpyArray& rows, const ResultPhases& phases, int n, LabResult* result) {
  const int64_t columns = rows.shape[1];
  const int64_t pose_rows = phases.pose_rows();
  RunTrack& track = result->track;
  track.num_robots = n;
  const auto un = static_cast<size_t>(n);
  track.poses.resize(static_cast<size_t>(pose_rows) * un);
  track.commands.resize(track.poses.size());
  track.utime.resize(static_cast<size_t>(pose_rows));
  const double t0 =
      rows.values[static_cast<size_t>(phases.first_experiment_row * columns + ResultLayout::kWallTimeColumn)];
  int64_t previous_utime = 0;
  double previous_time = t0;
  for (int64_t k = 0; k < pose_rows; ++k) {
    const int64_t row = phases.first_experiment_row + k;
    const double* values = &rows.values[static_cast<size_t>(row * columns)];
    const double stamp = values[ResultLayout::kWallTimeColumn];
    result->max_step_s = std::max(result->max_step_s, stamp - previous_time);
    previous_time = stamp;
    auto utime = static_cast<int64_t>(std::llround((stamp - t0) * 1e6));
    if (utime < previous_utime) {
      ++result->clock_steps_back;
      utime = previous_utime;
    }
    previous_utime = utime;
    track.utime[static_cast<size_t>(k)] = utime;
    world::Pose2* step_poses = &track.poses[static_cast<size_t>(k) * un];
    world::UnicycleCommand* step_commands = &track.commands[static_cast<size_t>(k) * un];
    const bool last = k == pose_rows - 1;
    for (size_t i = 0; i < un; ++i) {
      const double* base = values + ResultLayout::kFixedColumns + i;
      step_poses[i] = world::Pose2{base[0], base[un], base[2 * un]};
      step_commands[i] = last ? world::UnicycleCommand{} : world::UnicycleCommand{base[3 * un], base[4 * un]};
    }
  }
  result->wall_duration_s = static_cast<double>(track.utime.back()) / 1e6;
}

}  // namespace

LabResult ParseLabResult(const formats::NpyArray& rows, const std::string& name, const ExportedSubmission& exported) {
  const ResultFileError fail{name};
  const SubmissionParams& params = exported.params;
  CheckResultValues(rows, params.num_robots, fail);
  const ResultPhases phases = FindPhases(rows, params, fail);
  LabResult result;
  result.settle_steps = phases.settle;
  result.planned_steps = params.steps;
  result.iterations =
      phases.settle + phases.experiment;  // the script calls step() after each settle and experiment row
  result.complete = phases.final_row;
  FillTrack(rows, phases, params.num_robots, &result);
  RunTrack& track = result.track;
  track.obstacles = ObstaclesPerStep(exported.config.obstacles, track.last_step(), exported.config.world.time_step_s);
  return result;
}

world::ViolationCounts WriteLabRunLog(const RunTrack& track, const world::WorldParams& world, int8_t end_state,
                                      const std::string& detail, const std::string& log_path) {
  return WriteLog(track, world, end_state, detail, log_path).violations();
}

std::vector<world::VerdictReason> LabVerifierReasons(const LabResult& lab, const world::WorldParams& world,
                                                     const world::LabVerifierRules::Declaration& declared) {
  world::LabVerifierRules rules;
  rules.time_step_s = world.time_step_s;
  world::LabVerifierRules::Counts counts = VerifierCounts(lab.track, world);
  counts.iterations = lab.iterations;  // the settle phase counts too: the verifier counts every step()
  return rules.Check(declared, counts);
}

namespace {

/// The final status's detail: how the lab run ended.
std::string EndDetail(const LabResult& lab) {
  const int64_t last = lab.track.last_step();
  if (lab.complete && last < lab.planned_steps) {
    return "every robot reported done after " + std::to_string(last) + " steps on the lab";
  }
  if (lab.complete) return "the lab run completed every planned step";
  return "the lab run stopped after " + std::to_string(last) + " of " + std::to_string(lab.planned_steps) +
         " planned steps";
}

/// summary.json's "lab" section.
nlohmann::ordered_json LabJson(const ImportedRun& imported, const ExportedSubmission& exported,
                               const std::string& result_path, bool declared_by_options) {
  const LabResult& lab = imported.lab;
  nlohmann::ordered_json json;
  json["result_file"] = fs::absolute(result_path).string();
  json["export"] = fs::absolute(exported.dir).string();
  json["source_run"] = exported.source_run;
  json["strategy"] = StrategyName(exported.params.options.strategy);
  json["barriers"] = exported.params.options.barriers;
  json["planned_steps"] = lab.planned_steps;
  json["steps"] = lab.track.last_step();
  json["complete"] = lab.complete;
  json["settle_steps"] = lab.settle_steps;
  json["iterations"] = lab.iterations;
  json["declared_robots"] = imported.declared.num_robots;
  json["declared_duration_s"] = imported.declared.duration_s;
  json["declared_from"] = declared_by_options ? "options" : "export";
  json["wall_duration_s"] = lab.wall_duration_s;
  json["max_step_s"] = lab.max_step_s;
  json["clock_steps_back"] = lab.clock_steps_back;
  return json;
}

}  // namespace

ImportedRun ImportLabRun(const std::string& result_path, const std::string& export_dir, const std::string& out_dir,
                         const std::optional<world::LabVerifierRules::Declaration>& declared) {
  return ImportLabRun(result_path, ExportedSubmission::Read(export_dir), out_dir, declared);
}

ImportedRun ImportLabRun(const std::string& result_path, const ExportedSubmission& exported, const std::string& out_dir,
                         const std::optional<world::LabVerifierRules::Declaration>& declared) {
  ImportedRun imported;
  imported.config = exported.config;
  imported.declared = declared.value_or(exported.UploadDeclaration());
  imported.lab = ParseLabResult(ReadResultFile(result_path, exported.MaxResultValues()), result_path, exported);
  const LabResult& lab = imported.lab;

  const files::OutputFolder out(out_dir);
  files::OutputFolderLock::HoldUntilExit(out.dir());  // a run writing the folder refuses the import, and back
  imported.log_path = out.PathOf("run.lcmlog");
  const std::string detail = EndDetail(lab);
  int64_t log_events = 0;
  auto world = std::make_shared<LabReplayWorld>(WriteLog(lab.track, exported.config.world,
                                                         lab.complete ? run_status_t::FINISHED : run_status_t::ABORTED,
                                                         detail, imported.log_path, &log_events));
  imported.violations = world->violations();
  out.WriteFile("config.yaml", exported.config_text);
  KeepControllerModule(exported.config, out);

  node::RunOutcome& outcome = imported.outcome;
  outcome.end = lab.complete ? node::RunOutcome::End::kFinished : node::RunOutcome::End::kInterrupted;
  outcome.reason = detail;
  outcome.steps = lab.track.last_step();
  outcome.wall_time_s = lab.wall_duration_s;
  outcome.log_events = log_events;
  outcome.run_id = ImportedRunId(lab.track);  // the log's, so its DREAM_VERDICT is this run's
  // Judged as a lab run: the verifier's rules on what the lab did against
  // what was declared (not JudgeRun's, which assumes the run is its own export).
  imported.judgement = world::RunJudgement(
      world::RunReport::FromViolations(world->step(), world->violations(), exported.config.world.time_step_s));
  imported.judgement.Add(LabVerifierReasons(lab, exported.config.world, imported.declared));
  imported.judgement.Add(node::OutcomeReasons(outcome));
  imported.lab_json = LabJson(imported, exported, result_path, declared.has_value());
  imported.world = std::move(world);
  return imported;
}

}  // namespace dream::bridge
