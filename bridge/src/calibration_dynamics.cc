#include "calibration_dynamics.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/robot_response.h"

namespace dream::bridge {
namespace {

using robotarium::RobotariumConstants;

// Pose pairs further apart than this (a burst of repeated poses between
// them) are not compared: the heading has turned too far for one projection.
constexpr size_t kMaxGapSteps = 3;

// Least squares of y on one basis: the fitted coefficient and residual sum.
struct Sums1 {
  double yy = 0, xy = 0, xx = 0;
  int64_t n = 0;
};

// Least squares of y on two bases (angular gain and drift).
struct Sums2 {
  double yy = 0, ya = 0, yb = 0, aa = 0, ab = 0, bb = 0;
  int64_t n = 0;
};

}  // namespace

CalibrationDynamics::CalibrationDynamics(const std::vector<CalibrationSeries>& series, const world::RealismParams& base,
                                         double position_sigma_m, double heading_sigma_rad, files::StopToken stop)
    : series_(series),
      base_(base),
      position_weight_(1.0 / (2.0 * std::max(position_sigma_m, 1e-5) * std::max(position_sigma_m, 1e-5))),
      heading_weight_(1.0 / (2.0 * std::max(heading_sigma_rad, 1e-4) * std::max(heading_sigma_rad, 1e-4))),
      stop_(std::move(stop)) {}

void CalibrationDynamics::Predict(const CalibrationSeries& series, const DynamicsParams& params,
                                  std::vector<world::UnicycleCommand>* driven, std::vector<double>* motion_s) const {
  world::RealismParams model = base_;
  model.motor_lag_s = params.lag_s;
  model.motor_startup_m = params.startup_m;
  world::RobotResponse response(model, world::RobotTraits{}, RobotariumConstants::kWheelRadiusMeters,
                              RobotariumConstants::kMaxWheelVelocityRadps);
  const size_t transitions = series.steps() - 1;
  driven->resize(transitions);
  motion_s->resize(transitions);
  const double brake_s = base_.command_brake_s;
  for (size_t k = 0; k < transitions; ++k) {
    const auto delayed = static_cast<int64_t>(k) - params.delay_steps;
    const world::UnicycleCommand target = delayed >= 0 ? series.commands[static_cast<size_t>(delayed)] : world::UnicycleCommand{};
    const double step_s = series.step_s[k];
    (*driven)[k] = response.Drive(target, step_s);
    // Through a late step the robot drives on until its brake.
    (*motion_s)[k] = brake_s > 0.0 ? std::min(step_s, std::max(brake_s, RobotariumConstants::kTimeStepSeconds)) : step_s;
  }
}

DynamicsEvaluation CalibrationDynamics::Evaluate(const DynamicsParams& params) const {
  DynamicsEvaluation evaluation;
  evaluation.gains.resize(series_.size());
  std::vector<world::UnicycleCommand> driven;
  std::vector<double> motion_s;
  for (size_t r = 0; r < series_.size(); ++r) {
    stop_.ThrowIfRequested();
    const CalibrationSeries& series = series_[r];
    Predict(series, params, &driven, &motion_s);
    Sums1 forward;
    Sums2 turn;
    size_t from = 0;
    while (from < series.steps() && series.stale[from]) ++from;
    for (size_t to = from + 1; to < series.steps(); ++to) {
      if (series.stale[to]) continue;
      if (to - from <= kMaxGapSteps && !series.near_late[from] && !series.near_late[to]) {
        double v_sum = 0, w_sum = 0, moving_sum = 0;
        for (size_t k = from; k < to; ++k) {
          v_sum += driven[k].v_mps * motion_s[k];
          w_sum += driven[k].w_radps * motion_s[k];
          if (driven[k].v_mps != 0.0 || driven[k].w_radps != 0.0) moving_sum += motion_s[k];
        }
        const world::Pose2& a = series.poses[from];
        const world::Pose2& b = series.poses[to];
        const double f = (b.x_m - a.x_m) * std::cos(a.theta_rad) + (b.y_m - a.y_m) * std::sin(a.theta_rad);
        const double turned = WrappedAngle(b.theta_rad - a.theta_rad);
        forward.yy += f * f;
        forward.xy += f * v_sum;
        forward.xx += v_sum * v_sum;
        ++forward.n;
        turn.yy += turned * turned;
        turn.ya += turned * w_sum;
        turn.yb += turned * moving_sum;
        turn.aa += w_sum * w_sum;
        turn.ab += w_sum * moving_sum;
        turn.bb += moving_sum * moving_sum;
        ++turn.n;
      }
      from = to;
    }
    RobotGains& gains = evaluation.gains[r];
    double forward_rss = forward.yy;
    if (forward.xx > 0.0) {
      gains.linear = forward.xy / forward.xx;
      forward_rss = std::max(0.0, forward.yy - gains.linear * forward.xy);
      const double variance = forward.n > 1 ? forward_rss / static_cast<double>(forward.n - 1) : 0.0;
      gains.linear_se = std::sqrt(variance / forward.xx);
      gains.linear_seen = forward.xx > 1e-4;  // at least about 1 cm of commanded travel
    }
    double turn_rss = turn.yy;
    const double det = turn.aa * turn.bb - turn.ab * turn.ab;
    if (turn.aa > 0.0 && det > 1e-12 * turn.aa * turn.bb) {
      gains.angular = (turn.ya * turn.bb - turn.yb * turn.ab) / det;
      gains.drift_radps = (turn.aa * turn.yb - turn.ab * turn.ya) / det;
      turn_rss = std::max(0.0, turn.yy - gains.angular * turn.ya - gains.drift_radps * turn.yb);
      const double variance = turn.n > 2 ? turn_rss / static_cast<double>(turn.n - 2) : 0.0;
      gains.angular_se = std::sqrt(variance * turn.bb / det);
      gains.drift_se = std::sqrt(variance * turn.aa / det);
      gains.angular_seen = turn.aa > 1e-2;  // at least about 0.1 rad of commanded turning
    } else if (turn.bb > 0.0) {
      gains.drift_radps = turn.yb / turn.bb;
      turn_rss = std::max(0.0, turn.yy - gains.drift_radps * turn.yb);
    }
    evaluation.cost += forward_rss * position_weight_ + turn_rss * heading_weight_;
    evaluation.transitions += forward.n;
  }
  return evaluation;
}

}  // namespace dream::bridge
