#include "dream/calibration/calibration_run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "dream/applied_commands_t.hpp"
#include "dream/formats/mat_file.h"
#include "dream/formats/npz_file.h"
#include "dream/robot_poses_t.hpp"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/run_log/run_log.h"
#include "dream/world/printf_text.h"

namespace dream::calibration {
namespace {

namespace fs = std::filesystem;
// A lab run is read into the bridge's RunTrack from the file formats' arrays.
using bridge::ReadRunTrack;
using bridge::RunTrack;
using bridge::RunTrackOf;
using formats::NpyArray;
using formats::NpzFile;
using formats::ReadMatArray;
using formats::ReadNpyFile;
constexpr double kNominalStepS = robotarium::RobotariumConstants::kTimeStepSeconds;

std::string ShapeText(const NpyArray& array) {
  std::string text;
  for (int64_t extent : array.shape) text += (text.empty() ? "" : " x ") + std::to_string(extent);
  return text.empty() ? "a scalar" : text;
}

// The arrays of one run, whatever file they came from.
struct Arrays {
  NpyArray poses;     // 3 x N x T (or 5 x N x T with the commands)
  NpyArray commands;  // 2 x N x T; empty when in poses
  std::optional<NpyArray> time;
  std::string poses_name;
  std::string commands_name;
  std::string time_name;
};

// A one-robot array rows x T as rows x 1 x T (the same values in C order).
void AsOneRobot(NpyArray* array, int64_t rows) {
  if (array->shape.size() == 2 && array->shape[0] == rows) array->shape = {rows, 1, array->shape[1]};
}

// The median of `values` (a copy).
double Median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

// Robots and steps of a (rows x N x T) array named `name`, or an error.
void CheckLayout(const std::string& file, const std::string& name, const NpyArray& array, int64_t rows,
                 const char* meaning) {
  if (array.shape.size() != 3 || array.shape[0] != rows) {
    throw std::runtime_error(file + ": array '" + name + "' is " + ShapeText(array) + "; expected " +
                             std::to_string(rows) + " x N x T (" + meaning + " of N robots over T steps; " +
                             std::to_string(rows) + " x T for one robot)");
  }
}

// Whether `arrays`' time vector is a clock: refuses a damaged one (naming
// the file and the array); a per-step one (not increasing, values under a
// second) is not a clock, and `notes` says so.
bool IsClock(const std::string& file, const Arrays& arrays, int64_t steps, double step_period_s,
             std::vector<std::string>* notes) {
  const auto t = static_cast<size_t>(steps);
  const NpyArray& time = *arrays.time;
  const std::string time_array = "the time vector '" + arrays.time_name + "'";
  if (time.size() != steps || time.shape.size() > 2) {
    throw std::runtime_error(file + ": " + time_array + " is " + ShapeText(time) + "; expected " +
                             std::to_string(steps) + " times, one per step of '" + arrays.poses_name + "'");
  }
  for (size_t k = 0; k < t; ++k) {
    // Seconds since 1970 are a clock too; a run lasts under 30 years.
    if (!std::isfinite(time.values[k]) || std::abs(time.values[k]) > 1e11 ||
        std::abs(time.values[k] - time.values[0]) > 1e9) {
      throw std::runtime_error(file + ": " + time_array + " at step " + std::to_string(k) + " is " +
                               std::to_string(time.values[k]) + ", not a finite number of seconds");
    }
  }
  // A clock increases. Per-step times (what a script measured each step:
  // its compute time, or the step's length) do not, and lie under a second.
  size_t back = 0;
  for (size_t k = 1; k < t && back == 0; ++k) back = time.values[k] <= time.values[k - 1] ? k : 0;
  const auto [low, high] = std::minmax_element(time.values.begin(), time.values.end());
  if (back != 0 && *low >= 0.0 && *high < 1.0) {
    const double median = Median(time.values);
    const bool step_lengths = median >= 0.5 * kNominalStepS && median <= 3.0 * kNominalStepS;
    notes->push_back(file + ": " + time_array + " is not a clock: it does not increase (step " + std::to_string(back) +
                     ") and its values lie in [" + world::PrintfText("%.3g", *low) + ", " +
                     world::PrintfText("%.3g", *high) + "] s, median " + world::PrintfText("%.3g", median) + " s: " +
                     (step_lengths ? "per-step durations, it seems (give their cumulative sum as the clock to fit "
                                     "step timing)"
                                   : "per-step times far below a step period (compute times?), not a step "
                                     "period") +
                     "; ignored, the steps are taken as " +
                     world::PrintfText("%g", step_period_s > 0.0 ? step_period_s : kNominalStepS) + " s apart");
    return false;
  }
  if (back != 0) {
    throw std::runtime_error(file + ": " + time_array + " does not increase at step " + std::to_string(back) + " (" +
                             world::PrintfText("%.9g", time.values[back - 1]) + " s then " +
                             world::PrintfText("%.9g", time.values[back]) +
                             " s); calibrate needs a clock (or no time vector: give --step-period)");
  }
  return true;
}

RunTrack TrackOfArrays(const std::string& file, Arrays arrays, double step_period_s, bool* timed,
                       std::vector<std::string>* notes) {
  const bool stacked = arrays.commands.shape.empty();
  AsOneRobot(&arrays.poses, stacked ? 5 : 3);
  if (!stacked) AsOneRobot(&arrays.commands, 2);
  CheckLayout(file, arrays.poses_name, arrays.poses, stacked ? 5 : 3, stacked ? "x, y, theta, v, w" : "x, y, theta");
  const int64_t robots = arrays.poses.shape[1];
  const int64_t steps = arrays.poses.shape[2];
  if (!stacked) {
    CheckLayout(file, arrays.commands_name, arrays.commands, 2, "v, w");
    if (arrays.commands.shape[1] != robots || arrays.commands.shape[2] != steps) {
      throw std::runtime_error(file + ": the shapes disagree: '" + arrays.poses_name + "' is " +
                               ShapeText(arrays.poses) + " but '" + arrays.commands_name + "' is " +
                               ShapeText(arrays.commands) + " (the same N robots and T steps are needed)");
    }
  }
  if (robots < 1 || robots > 1000) {
    throw std::runtime_error(file + ": " + std::to_string(robots) + " robots in '" + arrays.poses_name +
                             "'; expected 1 to 1000");
  }
  RunTrack track;
  track.num_robots = static_cast<int>(robots);
  const auto n = static_cast<size_t>(robots);
  const auto t = static_cast<size_t>(steps);
  auto pose_value = [&](size_t row, size_t robot, size_t step) {
    return arrays.poses.values[(row * n + robot) * t + step];
  };
  auto command_value = [&](size_t row, size_t robot, size_t step) {
    return stacked ? pose_value(3 + row, robot, step) : arrays.commands.values[(row * n + robot) * t + step];
  };
  track.poses.reserve(n * t);
  track.commands.reserve(n * t);
  for (size_t k = 0; k < t; ++k) {
    for (size_t i = 0; i < n; ++i) {
      track.poses.push_back({pose_value(0, i, k), pose_value(1, i, k), pose_value(2, i, k)});
      track.commands.push_back({command_value(0, i, k), command_value(1, i, k)});
    }
  }
  track.obstacles.resize(t);
  track.utime.resize(t);
  if (arrays.time && !IsClock(file, arrays, steps, step_period_s, notes)) arrays.time.reset();
  *timed = arrays.time.has_value();
  if (arrays.time) {
    const NpyArray& time = *arrays.time;
    for (size_t k = 0; k < t; ++k) track.utime[k] = std::llround((time.values[k] - time.values[0]) * 1e6);
  } else {
    const double period = step_period_s > 0.0 ? step_period_s : kNominalStepS;
    for (size_t k = 0; k < t; ++k) track.utime[k] = std::llround(static_cast<double>(k) * period * 1e6);
  }
  return track;
}

Arrays ReadNpz(const std::string& path, const CalibrationInputOptions& options) {
  const NpzFile npz(path);
  const int64_t max_bytes = options.max_values * 8 + 4096;
  auto required = [&](const std::string& name, const char* option) {
    std::optional<NpyArray> array = npz.Read(name, max_bytes);
    if (!array) {
      std::string names;
      for (const std::string& held : npz.Names()) names += (names.empty() ? "" : ", ") + held;
      throw std::runtime_error(path + ": no array '" + name + "' (it holds: " + names + "); name it with " + option);
    }
    return *array;
  };
  Arrays arrays;
  arrays.poses_name = options.poses_name;
  arrays.commands_name = options.commands_name;
  arrays.poses = required(options.poses_name, "--poses");
  arrays.commands = required(options.commands_name, "--commands");
  arrays.time_name = options.time_name;
  arrays.time = npz.Read(options.time_name, max_bytes);
  return arrays;
}

Arrays ReadMat(const std::string& path, const CalibrationInputOptions& options) {
  Arrays arrays;
  arrays.poses_name = options.poses_name;
  arrays.commands_name = options.commands_name;
  arrays.poses = ReadMatArray(path, options.poses_name, options.max_values, 3);
  arrays.commands = ReadMatArray(path, options.commands_name, options.max_values, 3);
  arrays.time_name = options.time_name;
  try {
    arrays.time = ReadMatArray(path, options.time_name, options.max_values, 2);
  } catch (const std::runtime_error& error) {
    // Only a missing time vector is fine: a damaged one is not.
    if (std::string(error.what()).find("has no variable") == std::string::npos) throw;
  }
  return arrays;
}

// A run folder's log: the poses the agents were sent and the commands applied.
RunTrack TrackOfLog(const std::string& log_path, bool* timed) {
  const run_log::RunLog log = run_log::RunLog::Read(log_path);
  RunTrack track = RunTrackOf(log);
  const size_t steps = track.utime.size();
  const auto n = static_cast<size_t>(track.num_robots);
  std::vector<bool> applied(steps, false);
  std::vector<world::UnicycleCommand> sent(steps * n);
  std::vector<bool> sent_seen(steps * n, false);
  // Steps and robot counts come from the file: each is checked before it indexes.
  auto step_index = [steps](int64_t step) { return step >= 0 && static_cast<size_t>(step) < steps; };
  for (const robot_poses_t& poses : log.measured_poses()) {
    if (!step_index(poses.step) || static_cast<size_t>(poses.num_robots) != n) continue;
    const auto k = static_cast<size_t>(poses.step);
    for (size_t i = 0; i < n; ++i) track.poses[k * n + i] = world::Pose2{poses.x[i], poses.y[i], poses.theta[i]};
  }
  for (const applied_commands_t& commands : log.applied()) {  // the run's robots, one per step (RunLog)
    if (!step_index(commands.step)) continue;
    const auto k = static_cast<size_t>(commands.step);
    for (size_t i = 0; i < n; ++i) track.commands[k * n + i] = {commands.commanded_v[i], commands.commanded_w[i]};
    applied[k] = true;
  }
  for (const run_log::RecordedCommand& command : log.commands()) {  // the run's robots and steps (RunLog)
    if (!step_index(command.step)) continue;
    const size_t at = static_cast<size_t>(command.step) * n + static_cast<size_t>(command.robot_id);
    sent[at] = {command.v_mps, command.w_radps};
    sent_seen[at] = true;
  }
  // Commands: DREAM_APPLIED (a simulated run) where there is one, else the
  // DREAM_CMD_<id> of the step (an imported lab run writes those).
  for (size_t k = 0; k + 1 < steps; ++k) {
    if (applied[k]) continue;
    for (size_t i = 0; i < n; ++i) {
      if (sent_seen[k * n + i]) track.commands[k * n + i] = sent[k * n + i];
    }
  }
  // A real clock shows in steps that are not exactly the nominal period.
  const auto nominal_us = std::llround(kNominalStepS * 1e6);
  *timed = false;
  for (size_t k = 1; k < steps; ++k) {
    if (track.utime[k] - track.utime[k - 1] != nominal_us) *timed = true;
  }
  return track;
}

}  // namespace

void CheckCalibrationRun(const CalibrationRun& run) {
  const RunTrack& track = run.track;
  const auto steps = static_cast<int64_t>(track.utime.size());
  if (steps < kMinCalibrationSteps) {
    throw std::runtime_error(run.name + ": too short to calibrate: " + std::to_string(steps) + " steps; at least " +
                             std::to_string(kMinCalibrationSteps) +
                             " (3 s) are needed to see a robot answer a command");
  }
  const auto n = static_cast<size_t>(track.num_robots);
  for (size_t at = 0; at < track.poses.size(); ++at) {
    const world::Pose2& pose = track.poses[at];
    const world::UnicycleCommand& command = track.commands[at];
    const char* what = !std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad) ? "pose"
                       : !std::isfinite(command.v_mps) || !std::isfinite(command.w_radps) ? "command"
                                                                                          : nullptr;
    if (what != nullptr) {
      throw std::runtime_error(run.name + ": the " + what + " of robot " + std::to_string(at % n) + " at step " +
                               std::to_string(at / n) + " is not a finite number (NaN or inf); calibrate needs " +
                               "every step: cut the run before it, or drop that robot");
    }
  }
  for (size_t k = 1; k < track.utime.size(); ++k) {
    if (track.utime[k] <= track.utime[k - 1]) {
      throw std::runtime_error(run.name + ": time does not increase at step " + std::to_string(k) + " (" +
                               std::to_string(static_cast<double>(track.utime[k - 1]) * 1e-6) + " s then " +
                               std::to_string(static_cast<double>(track.utime[k]) * 1e-6) + " s)");
    }
  }
}

CalibrationRun ReadCalibrationRun(const std::string& path, const CalibrationInputOptions& options) {
  CalibrationRun run;
  run.name = path;
  std::error_code error;
  const std::string extension = fs::path(path).extension().string();
  if (fs::is_directory(path, error) || extension == ".lcmlog") {
    const std::string log = fs::is_directory(path, error) ? (fs::path(path) / "run.lcmlog").string() : path;
    if (!fs::exists(log, error)) {
      throw std::runtime_error(path +
                               ": no run.lcmlog in this folder (give a folder made by dream import or dream run)");
    }
    run.track = TrackOfLog(log, &run.timed);
  } else if (extension == ".npz") {
    run.track = TrackOfArrays(path, ReadNpz(path, options), options.step_period_s, &run.timed, &run.notes);
  } else if (extension == ".mat") {
    run.track = TrackOfArrays(path, ReadMat(path, options), options.step_period_s, &run.timed, &run.notes);
  } else if (extension == ".npy") {
    Arrays arrays;
    arrays.poses = ReadNpyFile(path, options.max_values * 8 + 4096);
    arrays.poses_name = "(the .npy's array)";
    run.track = TrackOfArrays(path, arrays, options.step_period_s, &run.timed, &run.notes);
  } else {
    throw std::runtime_error(path + ": not a run folder, .lcmlog, .npz, .mat or .npy file (what calibrate reads)");
  }
  CheckCalibrationRun(run);
  // A simulator that does not run in real time (dream check-submission's)
  // stamps its steps far faster than the lab's loop can run: that clock says
  // nothing about the lab's and would scale every speed and delay, so the
  // run counts nominal steps.
  const auto steps = static_cast<int64_t>(run.track.utime.size());
  if (run.timed && steps > 1 &&
      static_cast<double>(run.track.utime.back() - run.track.utime.front()) * 1e-6 <
          0.5 * kNominalStepS * static_cast<double>(steps - 1)) {
    run.notes.push_back(
        path + ": its clock's steps average " +
        world::PrintfText("%.3g ms", static_cast<double>(run.track.utime.back() - run.track.utime.front()) * 1e-3 /
                                         static_cast<double>(steps - 1)) +
        ", under half of 33 ms (a simulator not in real time): the steps are taken as 33 ms apart");
    for (int64_t k = 0; k < steps; ++k) {
      run.track.utime[static_cast<size_t>(k)] =
          run.track.utime.front() + std::llround(static_cast<double>(k) * kNominalStepS * 1e6);
    }
    run.timed = false;
  }
  return run;
}

}  // namespace dream::calibration
