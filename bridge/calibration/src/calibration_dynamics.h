#pragma once

#include <cstdint>
#include <vector>

#include "calibration_series.h"
#include "dream/files/stop_token.h"
#include "dream/world/realism_params.h"
#include "dream/world/unicycle_command.h"

namespace dream::calibration {

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
  // The drift shows apart from the angular gain only while the robot drives
  // straight (|w| near 0): turning at one rate cannot tell a gain from a
  // drift (an open-loop circle gave a gain of -28), and closed-loop turning
  // lets the drift absorb what the model misses. Seen: the robot drove
  // straight long enough; else its drift is the prior (DynamicsEvaluation).
  bool drift_seen = false;
  double straight_s = 0.0;  // time driven straight, moving
};

struct DynamicsEvaluation {
  double cost = 0.0;              // weighted residual sum of squares
  int64_t transitions = 0;        // pose pairs compared
  std::vector<RobotGains> gains;  // per series
  // The drift of robots that did not drive straight: the mean of those that
  // did, else the base's mean.
  double drift_prior_radps = 0.0;
  int drift_robots = 0;             // robots whose drift was seen
  std::vector<double> series_cost;  // each series' part of cost (for intervals over robots)
};

// Below this commanded rate (after the delay and the wheels' response) a
// robot drives straight: what it turns is drift.
inline constexpr double kStraightTurnRadps = 0.02;
// Driving straight for this long (in all) shows a robot's drift.
inline constexpr double kMinStraightS = 2.0;

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
  double heading_sigma_rad_;
  double position_weight_;
  double heading_weight_;
  files::StopToken stop_;
};

}  // namespace dream::calibration
