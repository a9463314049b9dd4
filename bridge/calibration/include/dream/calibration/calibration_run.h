#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dream/bridge/run_track.h"

namespace dream::calibration {

/// One lab run as `dream calibrate` fits it: every step's measured poses,
/// the commands the script sent, and when each step was taken.
struct CalibrationRun {
  std::string name;        ///< the file or folder it came from, for messages
  bridge::RunTrack track;  ///< poses as measured (what get_poses() returned), commands as sent
  /// track.utime is a real clock (a lab run's wall time, or a time vector);
  /// false when it is only the nominal step (then step timing cannot be fitted).
  bool timed = false;
  /// What was taken differently from the file as it came (a time vector
  /// that is not a clock), for the report.
  std::vector<std::string> notes;
};

/// Where `dream calibrate` finds poses, commands and time in an array file.
struct CalibrationInputOptions {
  std::string poses_name = "poses";        ///< 3 x N x T: x, y, theta of every robot and step
  std::string commands_name = "commands";  ///< 2 x N x T: v, w sent at each step (the scripts' dxu)
  std::string time_name = "t";             ///< optional: T times in seconds (else step_period_s)
  double step_period_s = 0.0;              ///< the step period when there is no time vector; 0 = 0.033 s
  int64_t max_values = int64_t{1} << 26;   ///< the most values an array may declare
};

/// Reads one input of `dream calibrate`:
/// - a folder made by `dream import` or `dream run` (its run.lcmlog: the
///   measured poses, DREAM_MEASURED_POSES when the run had realism, and the
///   commands sent, DREAM_APPLIED or DREAM_CMD_<id>);
/// - a .npz (numpy.savez) or .mat file with the arrays named in `options`;
/// - a .npy file holding one 5 x N x T array (x, y, theta, v, w).
/// Arrays may be in C or Fortran order (as scipy.io.loadmat gives them), and
/// of one robot also 3 x T (2 x T, 5 x T). A time vector that is not a
/// clock (it does not increase, and its values are per-step times under a
/// second, e.g. compute times of 1e-5 s) is ignored with a note, and the
/// steps are the step period apart.
/// Refuses, with the file, the array and what is wrong: shapes that
/// disagree, NaN or infinite values, fewer than kMinSteps steps, time that
/// does not increase. A clock whose steps average under half the nominal
/// 33 ms (a simulator not in real time, as in dream check-submission) is
/// replaced by nominal steps, and the run is then not `timed`.
/// @throws std::runtime_error.
CalibrationRun ReadCalibrationRun(const std::string& path, const CalibrationInputOptions& options);

/// The fewest steps a run needs (3 s): anything shorter holds no step response.
inline constexpr int64_t kMinCalibrationSteps = 90;

/// Checks a run's values (finite poses, commands and times, increasing time,
/// at least kMinCalibrationSteps): the same checks for every source.
/// @throws std::runtime_error naming run.name.
void CheckCalibrationRun(const CalibrationRun& run);

}  // namespace dream::calibration
