#include "dream/calibration/lab_calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>

#include "calibration_dynamics.h"
#include "calibration_evidence.h"
#include "calibration_series.h"
#include "calibration_tracker.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/printf_text.h"
#include "dream/world/realistic_world.h"

namespace dream::calibration {
namespace {

using robotarium::RobotariumConstants;
constexpr double kDt = RobotariumConstants::kTimeStepSeconds;
constexpr double kZ95 = 1.959963984540054;
constexpr int kMaxDelaySteps = 30;  // 1 s: the real robots answer in under half of it
constexpr double kMaxLagS = 1.0;
constexpr double kMaxStartupM = 0.1;
// Start-up is fitted from this many starts from rest at this speed or slower.
constexpr double kSlowStartMps = 0.1;
constexpr int kMinSlowStarts = 3;

// Minimises f over [lo, hi] by golden-section search (f unimodal enough there).
template <typename F>
double GoldenMinimum(F f, double lo, double hi, int evaluations) {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = lo, b = hi;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < evaluations; ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = f(d);
    }
  }
  return fc < fd ? c : d;
}

// Where f crosses `level` between `inside` (f below it) and `outside`, by bisection.
template <typename F>
double Crossing(F f, double inside, double outside, double level, int evaluations) {
  for (int i = 0; i < evaluations; ++i) {
    const double middle = 0.5 * (inside + outside);
    (f(middle) <= level ? inside : outside) = middle;
  }
  return 0.5 * (inside + outside);
}

bool AnyMotionCommanded(const std::vector<CalibrationSeries>& series) {
  for (const CalibrationSeries& s : series) {
    for (const world::UnicycleCommand& c : s.commands) {
      if (std::abs(c.v_mps) > 0.01 || std::abs(c.w_radps) > 0.1) return true;
    }
  }
  return false;
}

// How far a robot's poses spread (noise alone walks too: the net extent, not the path length).
double Extent(const CalibrationSeries& s) {
  double min_x = s.poses[0].x_m, max_x = min_x, min_y = s.poses[0].y_m, max_y = min_y;
  for (const world::Pose2& p : s.poses) {
    min_x = std::min(min_x, p.x_m);
    max_x = std::max(max_x, p.x_m);
    min_y = std::min(min_y, p.y_m);
    max_y = std::max(max_y, p.y_m);
  }
  return std::hypot(max_x - min_x, max_y - min_y);
}

double LargestExtent(const std::vector<CalibrationSeries>& series) {
  double longest = 0;
  for (const CalibrationSeries& s : series) longest = std::max(longest, Extent(s));
  return longest;
}

// Student's t 97.5 % quantile for `dof` degrees of freedom (Cornish-Fisher,
// within 2 % from 3 on; 10 % at 2), so a mean over few robots is not
// given a normal interval.
double T975(double dof) {
  const double z = kZ95;
  const double z3 = z * z * z, z5 = z3 * z * z;
  return z + (z3 + z) / (4 * dof) + (5 * z5 + 16 * z3 + 3 * z) / (96 * dof * dof);
}

// Mean and spread of per-robot values, and their 95 % intervals. The spread
// is what is left of the values' variance after their own estimation error.
// With fewer than 3 robots there is no spread to see: the mean's interval
// takes the base's spread between robots (a robot or two are not the lab).
struct Population {
  double mean = 0, mean_half = 0, spread = 0, spread_low = 0, spread_high = 0;
  int n = 0;
};

Population PopulationOf(const std::vector<double>& values, const std::vector<double>& errors, double prior_spread) {
  Population p;
  p.n = static_cast<int>(values.size());
  if (p.n == 0) return p;
  double sum = 0, error_sq = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    sum += values[i];
    error_sq += errors[i] * errors[i];
  }
  p.mean = sum / p.n;
  double sq = 0;
  for (double v : values) sq += (v - p.mean) * (v - p.mean);
  const double variance = p.n > 1 ? sq / (p.n - 1) : 0.0;
  p.spread = std::sqrt(std::max(0.0, variance - error_sq / p.n));
  if (p.n >= 3) {
    p.mean_half = T975(p.n - 1) * std::sqrt(std::max(variance, error_sq / p.n) / p.n);
    // Wilson-Hilferty chi-square quantiles for n - 1 degrees of freedom.
    const double k = p.n - 1;
    auto chi2 = [k](double z) { return k * std::pow(1 - 2 / (9 * k) + z * std::sqrt(2 / (9 * k)), 3); };
    const double spread_sq = p.spread * p.spread;
    p.spread_low = std::sqrt(spread_sq * k / chi2(kZ95));
    p.spread_high = std::sqrt(std::max(spread_sq, error_sq / p.n) * k / chi2(-kZ95));
  } else {
    p.mean_half = kZ95 * std::sqrt(std::max(variance, error_sq / p.n + prior_spread * prior_spread) / p.n);
  }
  return p;
}

// The 95 % interval of one wheel key over robots: the cost of each series at
// `points` values in [lo, hi], summed over resamples of the series (robots
// of runs) with replacement, each resample's minimum (a parabola through
// the grid's lowest three). Pose pairs of one robot are not independent
// (the same wheels, the same noise), so an interval over pairs is too tight
// to hold what another half of the same lab gives; one over robots is not.
template <typename EvaluateAt>
void BootstrapOverRobots(EvaluateAt evaluate_at, double lo, double hi, const std::vector<bool>& used, double* low,
                         double* high) {
  constexpr int kPoints = 21;
  constexpr int kResamples = 400;
  std::vector<size_t> robots;
  for (size_t r = 0; r < used.size(); ++r) {
    if (used[r]) robots.push_back(r);
  }
  if (robots.size() < 2) return;
  std::vector<double> grid(kPoints);
  std::vector<std::vector<double>> cost(kPoints);
  for (int g = 0; g < kPoints; ++g) {
    grid[static_cast<size_t>(g)] = lo + (hi - lo) * g / (kPoints - 1);
    cost[static_cast<size_t>(g)] = evaluate_at(grid[static_cast<size_t>(g)]).series_cost;
  }
  std::mt19937_64 random(20260322);  // fixed: the same runs give the same report
  std::uniform_int_distribution<size_t> pick(0, robots.size() - 1);
  std::vector<double> minima;
  std::vector<int> count(used.size());
  std::vector<double> total(kPoints);
  for (int b = 0; b < kResamples; ++b) {
    std::fill(count.begin(), count.end(), 0);
    for (size_t i = 0; i < robots.size(); ++i) ++count[robots[pick(random)]];
    for (int g = 0; g < kPoints; ++g) {
      double sum = 0;
      for (size_t r : robots) sum += count[r] * cost[static_cast<size_t>(g)][r];
      total[static_cast<size_t>(g)] = sum;
    }
    const auto g = static_cast<size_t>(std::min_element(total.begin(), total.end()) - total.begin());
    double at = grid[g];
    if (g > 0 && g + 1 < grid.size()) {
      const double curvature = total[g - 1] - 2 * total[g] + total[g + 1];
      if (curvature > 0) at += 0.5 * (total[g - 1] - total[g + 1]) / curvature * (grid[1] - grid[0]);
    }
    minima.push_back(at);
  }
  std::sort(minima.begin(), minima.end());
  *low = std::min(*low, minima[static_cast<size_t>(0.025 * kResamples)]);
  *high = std::max(*high, minima[static_cast<size_t>(0.975 * kResamples) - 1]);
}

// The delay, then the wheels' lag and start-up around it, and their 95 %
// intervals: where the cost, scaled by its residual variance, rises by
// chi-square(1) = 3.84 with the other keys held at the fit.
struct DynamicsFit {
  DynamicsParams best;
  DynamicsEvaluation evaluation;
  int delay_low = 0, delay_high = 0;
  double lag_low = 0, lag_high = 0, startup_low = 0, startup_high = 0;
};

// The cost of every delay at `best`'s lag and start-up; `best` takes the cheapest.
std::map<int, double> ScanDelays(const CalibrationDynamics& dynamics, DynamicsParams* best, double* best_cost) {
  std::map<int, double> delay_cost;
  for (int delay = 0; delay <= kMaxDelaySteps; ++delay) {
    const double cost = dynamics.Evaluate({delay, best->lag_s, best->startup_m}).cost;
    delay_cost[delay] = cost;
    if (cost < *best_cost) {
      *best_cost = cost;
      best->delay_steps = delay;
    }
  }
  return delay_cost;
}

DynamicsFit FitDynamics(const CalibrationDynamics& dynamics, const world::RealismParams& base, bool fit_startup) {
  DynamicsFit fit;
  DynamicsParams& best = fit.best;
  best = {base.pose_delay_steps + base.command_latency_steps, base.motor_lag_s, base.motor_startup_m};
  double best_cost = std::numeric_limits<double>::infinity();
  std::map<int, double> delay_cost = ScanDelays(dynamics, &best, &best_cost);
  const int coarse_delay = best.delay_steps;
  for (int delay = std::max(0, coarse_delay - 1); delay <= std::min(kMaxDelaySteps, coarse_delay + 1); ++delay) {
    DynamicsParams trial{delay, best.lag_s, best.startup_m};
    for (int round = 0; round < (fit_startup ? 2 : 1); ++round) {
      trial.lag_s = GoldenMinimum(
          [&](double lag) {
            return dynamics.Evaluate({delay, lag, trial.startup_m}).cost;
          },
          0.0, kMaxLagS, 22);
      if (!fit_startup) break;
      trial.startup_m = GoldenMinimum(
          [&](double startup) {
            return dynamics.Evaluate({delay, trial.lag_s, startup}).cost;
          },
          0.0, kMaxStartupM, 22);
    }
    const double cost = dynamics.Evaluate(trial).cost;
    delay_cost[delay] = std::min(delay_cost[delay], cost);
    if (cost < best_cost) {
      best_cost = cost;
      best = trial;
    }
  }
  fit.evaluation = dynamics.Evaluate(best);
  const double scale = best_cost / std::max<double>(1.0, 2.0 * static_cast<double>(fit.evaluation.transitions) - 3.0);
  const double level = best_cost + 3.84 * scale;
  auto interval = [&](auto cost_at, double value, double lo, double hi, double* low, double* high) {
    *low = cost_at(lo) <= level ? lo : Crossing(cost_at, value, lo, level, 18);
    *high = cost_at(hi) <= level ? hi : Crossing(cost_at, value, hi, level, 18);
  };
  interval(
      [&](double lag) {
        return dynamics.Evaluate({best.delay_steps, lag, best.startup_m}).cost;
      },
      best.lag_s, 0.0, kMaxLagS, &fit.lag_low, &fit.lag_high);
  if (fit_startup) {
    interval(
        [&](double s) {
          return dynamics.Evaluate({best.delay_steps, best.lag_s, s}).cost;
        },
        best.startup_m, 0.0, kMaxStartupM, &fit.startup_low, &fit.startup_high);
  }
  // Over robots, too: the wider of the two.
  std::vector<bool> used(fit.evaluation.gains.size());
  for (size_t r = 0; r < used.size(); ++r) used[r] = fit.evaluation.gains[r].linear_seen;
  BootstrapOverRobots(
      [&](double lag) {
        return dynamics.Evaluate({best.delay_steps, lag, best.startup_m});
      },
      std::max(0.0, best.lag_s - 0.2), std::min(kMaxLagS, best.lag_s + 0.2), used, &fit.lag_low, &fit.lag_high);
  if (fit_startup) {
    BootstrapOverRobots(
        [&](double s) {
          return dynamics.Evaluate({best.delay_steps, best.lag_s, s});
        },
        std::max(0.0, best.startup_m - 0.03), std::min(kMaxStartupM, best.startup_m + 0.03), used, &fit.startup_low,
        &fit.startup_high);
  }
  fit.delay_low = fit.delay_high = best.delay_steps;
  for (const auto& [delay, cost] : delay_cost) {
    if (cost <= level) {
      fit.delay_low = std::min(fit.delay_low, delay);
      fit.delay_high = std::max(fit.delay_high, delay);
    }
  }
  return fit;
}

// The delay and wheel keys of `fit`. Poses and commands show only the total
// delay: the base's pose delay is kept, unless the total is shorter.
void AddDynamicsKeys(const DynamicsFit& fit, const world::RealismParams& base, const std::string& startup_kept,
                     CalibrationReport* report) {
  const DynamicsParams& best = fit.best;
  const std::string transitions = world::PrintfText("%lld", static_cast<long long>(fit.evaluation.transitions));
  const int pose_delay = std::min(base.pose_delay_steps, best.delay_steps);
  if (pose_delay < base.pose_delay_steps) {
    AddKey(report, FittedKey{"pose_delay_steps", static_cast<double>(pose_delay), static_cast<double>(pose_delay),
                             static_cast<double>(pose_delay), true,
                             "the total delay is below the base's pose delay, so it is all pose delay"});
  } else {
    AddKey(report, KeptKey(base, "pose_delay_steps",
                           "poses and commands show only the sum with command_latency_steps; kept the base's"));
  }
  AddKey(report,
         FittedKey{"command_latency_steps", static_cast<double>(best.delay_steps - pose_delay),
                   static_cast<double>(std::max(0, fit.delay_low - pose_delay)),
                   static_cast<double>(std::max(0, fit.delay_high - pose_delay)), true,
                   "total delay " + std::to_string(best.delay_steps) + " steps, from " + transitions + " pose pairs"});
  AddKey(report,
         FittedKey{"motor_lag_s", best.lag_s, fit.lag_low, fit.lag_high, true, "from " + transitions + " pose pairs"});
  if (startup_kept.empty()) {
    AddKey(report, FittedKey{"motor_startup_m", best.startup_m, fit.startup_low, fit.startup_high, true,
                             "from starts from rest at the speeds the runs commanded"});
  } else {
    AddKey(report, KeptKey(base, "motor_startup_m", startup_kept));
  }
  AddKey(report, KeptKey(base, "wheel_accel_limit_radps2", "the lag models the wheels; kept the base's"));
}

// A mean and spread key pair from per-robot values (and their errors).
void AddPopulationKeys(const char* mean_key, const char* spread_key, const std::vector<double>& values,
                       const std::vector<double>& errors, const std::string& what, const world::RealismParams& base,
                       CalibrationReport* report, const std::string& how = "") {
  const Population p = PopulationOf(values, errors, RealismValue(base, spread_key));
  if (p.n == 0) {
    AddKey(report, KeptKey(base, mean_key, "no robot " + what));
    AddKey(report, KeptKey(base, spread_key, "no robot " + what));
    return;
  }
  const std::string robots = std::to_string(p.n) + (p.n == 1 ? " robot" : " robots");
  AddKey(report,
         FittedKey{mean_key, p.mean, p.mean - p.mean_half, p.mean + p.mean_half, true,
                   robots + how +
                       (p.n < 3 ? "; the interval holds the base's spread between robots (too few to see it)" : "")});
  if (p.n >= 3) {
    AddKey(report, FittedKey{spread_key, p.spread, p.spread_low, p.spread_high, true, "between " + robots});
  } else {
    AddKey(report, KeptKey(base, spread_key, "a spread between robots needs 3 robots or more (" + robots + ")"));
  }
}

// The gains of the robots that drove (turned) far enough to tell, and the
// drift of those that drove straight long enough: only there does it show
// apart from the angular gain.
void AddGainKeys(const DynamicsEvaluation& fitted, const world::RealismParams& base, CalibrationReport* report) {
  std::vector<double> linear, linear_se, angular, angular_se, drift, drift_se;
  int turned_only = 0;
  for (const RobotGains& g : fitted.gains) {
    if (g.linear_seen) {
      linear.push_back(g.linear);
      linear_se.push_back(g.linear_se);
    }
    if (g.angular_seen) {
      angular.push_back(g.angular);
      angular_se.push_back(g.angular_se);
      turned_only += g.drift_seen ? 0 : 1;
    }
    if (g.drift_seen) {
      drift.push_back(g.drift_radps);
      drift_se.push_back(g.drift_se);
    }
  }
  AddPopulationKeys("linear_gain_mean", "linear_gain_spread", linear, linear_se, "drove far enough", base, report);
  const std::string prior =
      turned_only == 0 ? ""
                       : "; " + std::to_string(turned_only) + " of them never drove straight: their drift taken as " +
                             world::PrintfText("%.4g rad/s", fitted.drift_prior_radps) +
                             (fitted.drift_robots > 0 ? " (the straight drivers' mean)" : " (the base's)");
  AddPopulationKeys("angular_gain_mean", "angular_gain_spread", angular, angular_se, "turned far enough", base, report,
                    prior);
  const std::string straight = world::PrintfText(
      "drove straight (|w| < %.2f rad/s) for %.0f s or more; drift shows only there (turning cannot tell it from "
      "the angular gain)",
      kStraightTurnRadps, kMinStraightS);
  AddPopulationKeys("heading_drift_mean_radps", "heading_drift_spread_radps", drift, drift_se, straight, base, report,
                    " driving straight");
}

// Who was moving at each measurement, as the world decides it (the velocity
// of the step the measurement shows).
std::vector<std::vector<bool>> MovingAtEachMeasurement(const std::vector<CalibrationSeries>& series,
                                                       const CalibrationDynamics& dynamics,
                                                       const DynamicsParams& params) {
  std::vector<std::vector<bool>> moving(series.size());
  std::vector<world::UnicycleCommand> driven;
  std::vector<double> motion_s;
  for (size_t r = 0; r < series.size(); ++r) {
    dynamics.Predict(series[r], params, &driven, &motion_s);
    moving[r].assign(series[r].steps(), false);
    if (series[r].stuck) continue;  // it did not move, whatever it was told
    for (size_t k = 1; k < series[r].steps(); ++k) moving[r][k] = world::RealisticWorld::IsMoving(driven[k - 1]);
  }
  return moving;
}

// Refuses runs that hold nothing to fit.
void CheckSomethingMoved(const std::vector<CalibrationRun>& runs, const std::vector<CalibrationSeries>& series) {
  if (!AnyMotionCommanded(series)) {
    throw std::runtime_error("no motion: no robot of " + runs.front().name +
                             (runs.size() > 1 ? " (or the other runs)" : "") +
                             " was ever commanded to move (|v| > 0.01 m/s or |w| > 0.1 rad/s); calibrate needs "
                             "steps in v and w (dream export --calibration writes a run that has them)");
  }
  if (LargestExtent(series) < 0.02) {
    throw std::runtime_error(
        "no motion: the poses never move more than 2 cm although commands were sent; are the "
        "poses and commands of the same run, and the poses not all the same?");
  }
}

// Robots commanded to move that never moved 2 cm (off, held, or another
// robot's poses) are left out of the fits of motion, and the report says so.
void MarkStuckRobots(std::vector<CalibrationSeries>* series, CalibrationReport* report) {
  for (CalibrationSeries& s : *series) {
    bool commanded = false;
    for (const world::UnicycleCommand& c : s.commands) commanded = commanded || !IsRestCommand(c);
    if (!commanded || Extent(s) >= 0.02) continue;
    s.stuck = true;
    report->notes.push_back(s.run + ": robot " + std::to_string(s.robot) +
                            " was commanded to move but never moved 2 cm: left out of the fits of motion");
  }
}

}  // namespace

CalibrationReport LabCalibration::Fit(const std::vector<CalibrationRun>& runs) const {
  if (runs.empty()) throw std::runtime_error("nothing to calibrate: give at least one lab run");
  for (const CalibrationRun& run : runs) CheckCalibrationRun(run);
  stop_.ThrowIfRequested();
  std::vector<CalibrationSeries> series = CalibrationSeries::Of(runs);
  CheckSomethingMoved(runs, series);
  stop_.ThrowIfRequested();

  CalibrationReport report;
  report.params = base_;
  MarkStuckRobots(&series, &report);
  for (const CalibrationRun& run : runs) {
    report.notes.insert(report.notes.end(), run.notes.begin(), run.notes.end());
    report.sources.push_back(run.name);
    report.robots += run.track.num_robots;
    report.robot_steps += static_cast<int64_t>(run.track.utime.size()) * run.track.num_robots;
  }

  double position_sigma = 0, heading_sigma = 0;
  CalibrationTracker::RestNoise(series, &position_sigma, &heading_sigma);
  if (position_sigma == 0.0) position_sigma = base_.pose_noise_m;
  if (heading_sigma == 0.0) heading_sigma = base_.pose_noise_rad;
  stop_.ThrowIfRequested();
  const CalibrationDynamics dynamics(series, base_, position_sigma, heading_sigma, stop_);
  // Start-up shows apart from the lag only in starts from rest at low speed
  // (it adds motor_startup_m / speed to the lag): without them, closed-loop
  // runs fit it to whatever else the model misses.
  int speeds = 0;
  const int slow_starts = StartsFromRestAtOrBelow(series, kSlowStartMps, &speeds);
  std::string startup_kept;
  if (slow_starts < kMinSlowStarts || speeds < 2) {
    startup_kept = world::PrintfText(
        "start-up shows only in starts from rest at low speed: %d at or below %.2f m/s (%d needed), at %d speed(s) "
        "(2 needed); kept the base's, and the lag fitted with it",
        slow_starts, kSlowStartMps, kMinSlowStarts, speeds);
    report.notes.push_back("motor_startup_m kept: " + startup_kept);
  }
  const DynamicsFit fit = FitDynamics(dynamics, base_, startup_kept.empty());
  AddDynamicsKeys(fit, base_, startup_kept, &report);
  AddGainKeys(fit.evaluation, base_, &report);
  const std::vector<std::vector<bool>> moving = MovingAtEachMeasurement(series, dynamics, fit.best);
  stop_.ThrowIfRequested();
  CalibrationTracker(series, moving, base_).Fit(&report);
  stop_.ThrowIfRequested();
  FillCalibrationEvidence(series, dynamics, fit.best, fit.evaluation, &report);
  stop_.ThrowIfRequested();

  // Keys nothing here fits keep the base's, and every key appears once, in
  // RealismParams::Fields() order.
  std::vector<FittedKey> ordered;
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
    const FittedKey* found = report.Find(field.key);
    ordered.push_back(
        found != nullptr ? *found : KeptKey(base_, field.key, "not visible in poses and commands; kept the base's"));
  }
  report.keys = std::move(ordered);
  std::string error;
  if (!report.params.IsValid(&error)) throw std::runtime_error("the fitted lab model is not valid: " + error);
  return report;
}

}  // namespace dream::calibration
