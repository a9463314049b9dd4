#pragma once

#include <cstdint>
#include <string>

#include "dream/bridge/export_options.h"
#include "dream/formats/npy_file.h"

namespace dream::bridge {

/// Everything in dream_params.npy: the export's options, the size of the
/// plan and the robot constants the script needs for its wheel limiter.
struct SubmissionParams {
  int num_robots = 0;
  int64_t steps = 0;  ///< experiment steps K (reference poses for 0..K; the step limit for strategy controller)
  ExportOptions options;
  double wheel_radius_m = 0.0;
  double base_length_m = 0.0;
  double max_wheel_speed_radps = 0.0;
  /// Strategy controller: the script stops once every robot reports done, as
  /// the simulated run did (config `stop_when_done`); its result then ends
  /// with a final pose before step K.
  bool stop_when_done = false;
  /// Strategy controller: the simulator's limits on a command (SimNodeOptions).
  double max_abs_v_mps = 0.0;
  double max_abs_w_radps = 0.0;

  /// The ParamIndex::kParamCount float64 values.
  formats::NpyArray ToNpy() const;
  /// Parses and checks dream_params.npy (format 2, or format 1 of exports
  /// made before the controller strategy). @throws std::runtime_error
  /// "<name>: <problem>".
  static SubmissionParams FromNpy(const formats::NpyArray& array, const std::string& name);
};

}  // namespace dream::bridge
