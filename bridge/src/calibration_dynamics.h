#pragma once

#include <cstdint>
#include <vector>

#include "calibration_series.h"
#include "dream/files/stop_token.h"
#include "dream/world/realism_params.h"
#include "dream/world/unicycle_command.h"

namespace dream::bridge {

// The continuous and discrete keys of the robots' response that the fit
// searches; gains and drift are solved for each robot in closed form.
struct DynamicsParams {
  int delay_steps = 0;  // pose_delay_steps + command_latency_steps: the data show only the sum
  double lag_s = 0.0;
  double startup_m = 0.0;
};

// One robot's gains and drift, with their standard errors.
struct RobotGains {
  double linear = 1.0;
  double angular = 1.0;
  double drift_radps = 0.0;
  double linear_se = 0.0;
  double angular_se = 0.0;
  double drift_se = 0.0;
  bool linear_seen = false;   // enough forward motion to tell
  bool angular_seen = false;  // enough turning to tell
};

struct DynamicsEvaluation {
  double cost = 0.0;           // weighted residual sum of squares
  int64_t transitions = 0;     // pose pairs compared
  std::vector<RobotGains> gains;  // per series
};

// The world's robot model (world::RobotResponse) run on each series' commands,
// against the motion its measured poses show.
class CalibrationDynamics {
 public:
  // `stop` is polled once per robot of every evaluation (the fit runs
  // hundreds): asked to stop, Evaluate throws files::Stopped.
  CalibrationDynamics(const std::vector<CalibrationSeries>& series, const world::RealismParams& base,
                      double position_sigma_m, double heading_sigma_rad, files::StopToken stop = {});

  DynamicsEvaluation Evaluate(const DynamicsParams& params) const;

  // What robot `series` drives in each step (unit gains, no drift) and for
  // how long, under `params`.
  void Predict(const CalibrationSeries& series, const DynamicsParams& params,
               std::vector<world::UnicycleCommand>* driven, std::vector<double>* motion_s) const;

 private:
  const std::vector<CalibrationSeries>& series_;
  world::RealismParams base_;
  double position_weight_;
  double heading_weight_;
  files::StopToken stop_;
};

}  // namespace dream::bridge
