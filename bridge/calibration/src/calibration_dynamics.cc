#include "calibration_dynamics.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/robot_response.h"

namespace dream::calibration {
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

// Least squares of y (the turn) on a (the commanded turn) with b (the time
// the wheels turned) times a known drift taken out first.
struct Sums2 {
  double yy = 0, ya = 0, yb = 0, aa = 0, ab = 0, bb = 0;
  int64_t n = 0;
};

// Straight driving: the turn over each unbroken stretch of it (the pose
// differences telescope, so a stretch's turn carries two measurements'
// noise), its time, and the stretches' count.
struct Straight {
  double turned = 0, seconds = 0;
  int stretches = 0;
  bool open = false;  // the last pair compared was straight
};

// Every pair of fresh poses of `series` up to kMaxGapSteps apart, away from
// late steps: the forward motion and turn measured against what the model
// drove, and the straight driving among them.
void ComparePosePairs(const CalibrationSeries& series, const std::vector<world::UnicycleCommand>& driven,
                      const std::vector<double>& motion_s, double base_gain, Sums1* forward, Sums2* turn,
                      Straight* straight) {
  size_t from = 0;
  while (from < series.steps() && series.stale[from]) ++from;
  for (size_t to = from + 1; to < series.steps(); ++to) {
    if (series.stale[to]) continue;
    bool is_straight = false;
    if (to - from <= kMaxGapSteps && !series.near_late[from] && !series.near_late[to]) {
      double v_sum = 0, w_sum = 0, moving_sum = 0;
      is_straight = true;
      for (size_t k = from; k < to; ++k) {
        v_sum += driven[k].v_mps * motion_s[k];
        w_sum += driven[k].w_radps * motion_s[k];
        if (driven[k].v_mps != 0.0 || driven[k].w_radps != 0.0) moving_sum += motion_s[k];
        is_straight =
            is_straight && std::abs(driven[k].w_radps) < kStraightTurnRadps && std::abs(driven[k].v_mps) >= 0.01;
      }
      const world::Pose2& a = series.poses[from];
      const world::Pose2& b = series.poses[to];
      const double f = (b.x_m - a.x_m) * std::cos(a.theta_rad) + (b.y_m - a.y_m) * std::sin(a.theta_rad);
      // Headings may wrap anywhere and come in [-pi, pi) or [0, 2 pi): a
      // pair's difference, wrapped, is the turn (far under pi in 3 steps).
      const double turned = WrappedAngle(b.theta_rad - a.theta_rad);
      forward->yy += f * f;
      forward->xy += f * v_sum;
      forward->xx += v_sum * v_sum;
      ++forward->n;
      turn->yy += turned * turned;
      turn->ya += turned * w_sum;
      turn->yb += turned * moving_sum;
      turn->aa += w_sum * w_sum;
      turn->ab += w_sum * moving_sum;
      turn->bb += moving_sum * moving_sum;
      ++turn->n;
      if (is_straight) {
        // What the command's small turn explains is taken out at the base's gain.
        straight->turned += turned - base_gain * w_sum;
        straight->seconds += moving_sum;
        if (!straight->open) ++straight->stretches;
      }
    }
    straight->open = is_straight;
    from = to;
  }
}

}  // namespace

CalibrationDynamics::CalibrationDynamics(const std::vector<CalibrationSeries>& series, const world::RealismParams& base,
                                         double position_sigma_m, double heading_sigma_rad, files::StopToken stop)
    : series_(series),
      base_(base),
      heading_sigma_rad_(std::max(heading_sigma_rad, 1e-4)),
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
    const world::UnicycleCommand target =
        delayed >= 0 ? series.commands[static_cast<size_t>(delayed)] : world::UnicycleCommand{};
    const double step_s = series.step_s[k];
    (*driven)[k] = response.Drive(target, step_s);
    // Through a late step the robot drives on until its brake.
    (*motion_s)[k] =
        brake_s > 0.0 ? std::min(step_s, std::max(brake_s, RobotariumConstants::kTimeStepSeconds)) : step_s;
  }
}

DynamicsEvaluation CalibrationDynamics::Evaluate(const DynamicsParams& params) const {
  DynamicsEvaluation evaluation;
  evaluation.gains.resize(series_.size());
  evaluation.series_cost.assign(series_.size(), 0.0);
  std::vector<Sums2> turns(series_.size());
  std::vector<double> forward_costs(series_.size(), 0.0);
  std::vector<world::UnicycleCommand> driven;
  std::vector<double> motion_s;
  double drift_sum = 0, drift_weight = 0;
  for (size_t r = 0; r < series_.size(); ++r) {
    stop_.ThrowIfRequested();
    const CalibrationSeries& series = series_[r];
    if (series.stuck) continue;
    Predict(series, params, &driven, &motion_s);
    Sums1 forward;
    Sums2& turn = turns[r];
    Straight straight;
    ComparePosePairs(series, driven, motion_s, base_.angular_gain_mean, &forward, &turn, &straight);
    RobotGains& gains = evaluation.gains[r];
    double forward_rss = forward.yy;
    if (forward.xx > 0.0) {
      gains.linear = forward.xy / forward.xx;
      forward_rss = std::max(0.0, forward.yy - gains.linear * forward.xy);
      const double variance = forward.n > 1 ? forward_rss / static_cast<double>(forward.n - 1) : 0.0;
      gains.linear_se = std::sqrt(variance / forward.xx);
      gains.linear_seen = forward.xx > 1e-4;  // at least about 1 cm of commanded travel
    }
    forward_costs[r] = forward_rss * position_weight_;
    gains.straight_s = straight.seconds;
    if (straight.seconds >= kMinStraightS) {
      gains.drift_seen = true;
      gains.drift_radps = straight.turned / straight.seconds;
      // Each stretch's turn holds two measurements' heading noise.
      gains.drift_se = heading_sigma_rad_ * std::sqrt(2.0 * straight.stretches) / straight.seconds;
      const double weight = 1.0 / (gains.drift_se * gains.drift_se + 1e-8);
      drift_sum += weight * gains.drift_radps;
      drift_weight += weight;
      ++evaluation.drift_robots;
    }
    evaluation.transitions += forward.n;
  }
  evaluation.drift_prior_radps = drift_weight > 0 ? drift_sum / drift_weight : base_.heading_drift_mean_radps;
  for (size_t r = 0; r < series_.size(); ++r) {
    if (series_[r].stuck) continue;
    RobotGains& gains = evaluation.gains[r];
    const Sums2& turn = turns[r];
    if (!gains.drift_seen) gains.drift_radps = evaluation.drift_prior_radps;
    // The turn less the drift, on the commanded turn: the angular gain.
    const double d = gains.drift_radps;
    const double yy = turn.yy - 2 * d * turn.yb + d * d * turn.bb;
    const double ya = turn.ya - d * turn.ab;
    double turn_rss = std::max(0.0, yy);
    if (turn.aa > 0.0) {
      gains.angular = ya / turn.aa;
      turn_rss = std::max(0.0, yy - gains.angular * ya);
      const double variance = turn.n > 1 ? turn_rss / static_cast<double>(turn.n - 1) : 0.0;
      gains.angular_se = std::sqrt(variance / turn.aa);
      gains.angular_seen = turn.aa > 1e-2;  // at least about 0.1 rad of commanded turning
    }
    evaluation.series_cost[r] = forward_costs[r] + turn_rss * heading_weight_;
    evaluation.cost += evaluation.series_cost[r];
  }
  return evaluation;
}

}  // namespace dream::calibration
