#include "calibration_tracker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/printf_text.h"

namespace dream::calibration {
namespace {

using robotarium::RobotariumConstants;
constexpr double kZ95 = 1.959963984540054;

// A robot counts as commanded to rest (or to one steady command) when its
// commands of the last kSettledSteps steps agree: by then the wheels have
// settled, whatever the delay and lag.
constexpr size_t kSettledSteps = 25;
// A step longer than this is late (a stall); measurements this many steps
// around it are left out of the fits of motion and noise.
constexpr double kLateStepS = 1.5 * RobotariumConstants::kTimeStepSeconds;
constexpr size_t kLateMargin = 4;
// The most samples kept for a histogram.
constexpr size_t kMaxSamples = 20000;

bool Settled(const CalibrationSeries& series, size_t k, bool rest) {
  if (k < kSettledSteps) return false;
  const world::UnicycleCommand& now = series.commands[k];
  for (size_t j = k - kSettledSteps; j <= k; ++j) {
    const world::UnicycleCommand& then = series.commands[j];
    if (rest ? !IsRestCommand(then)
             : std::abs(then.v_mps - now.v_mps) > 1e-3 || std::abs(then.w_radps - now.w_radps) > 1e-2) {
      return false;
    }
  }
  return true;
}

// A standard deviation's 95 % interval from n (effective) samples.
FittedKey SigmaKey(const char* key, double sigma, double n, const std::string& support) {
  const double half = kZ95 / std::sqrt(2.0 * std::max(n, 1.0));
  return FittedKey{key, sigma, sigma * std::max(0.0, 1.0 - half), sigma * (1.0 + half), true, support};
}

// A proportion's Wilson 95 % interval.
FittedKey ProportionKey(const char* key, double hits, double n, const std::string& support) {
  const double p = hits / n;
  const double z2 = kZ95 * kZ95;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = kZ95 * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / (1 + z2 / n);
  return FittedKey{key, p, std::max(0.0, centre - half), std::min(1.0, centre + half), true, support};
}

std::string Count(double n) { return world::PrintfText("%.0f", n); }

}  // namespace

double WrappedAngle(double radians) { return std::atan2(std::sin(radians), std::cos(radians)); }

std::vector<CalibrationSeries> CalibrationSeries::Of(const std::vector<CalibrationRun>& runs) {
  std::vector<CalibrationSeries> all;
  for (const CalibrationRun& run : runs) {
    const bridge::RunTrack& track = run.track;
    const auto steps = track.utime.size();
    for (int robot = 0; robot < track.num_robots; ++robot) {
      CalibrationSeries& series = all.emplace_back();
      series.run = run.name;
      series.robot = robot;
      series.timed = run.timed;
      series.poses.reserve(steps);
      series.commands.reserve(steps);
      for (size_t k = 0; k < steps; ++k) {
        series.poses.push_back(track.pose(static_cast<int64_t>(k), robot));
        series.commands.push_back(track.command(static_cast<int64_t>(k), robot));
      }
      series.step_s.reserve(steps);
      for (size_t k = 0; k + 1 < steps; ++k) {
        series.step_s.push_back(static_cast<double>(track.utime[k + 1] - track.utime[k]) * 1e-6);
      }
      series.near_late.assign(steps, false);
      for (size_t k = 0; k + 1 < steps; ++k) {
        if (series.step_s[k] <= kLateStepS) continue;
        const size_t from = k >= kLateMargin ? k - kLateMargin : 0;
        for (size_t j = from; j < steps && j <= k + kLateMargin; ++j) series.near_late[j] = true;
      }
      series.stale.assign(steps, false);
      for (size_t k = 1; k < steps; ++k) {
        const world::Pose2& a = series.poses[k - 1];
        const world::Pose2& b = series.poses[k];
        series.stale[k] = a.x_m == b.x_m && a.y_m == b.y_m && a.theta_rad == b.theta_rad;
      }
    }
  }
  return all;
}

FittedKey KeptKey(const world::RealismParams& base, const char* key, const std::string& why) {
  const double value = RealismValue(base, key);
  return FittedKey{key, value, value, value, false, why};
}

double RealismValue(const world::RealismParams& params, const std::string& key) {
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
    if (key == field.key) {
      return field.number != nullptr ? params.*field.number : static_cast<double>(params.*field.steps);
    }
  }
  throw std::logic_error("no realism key " + key);
}

void SetRealismValue(world::RealismParams* params, const std::string& key, double value) {
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
    if (key != field.key) continue;
    if (field.number != nullptr) {
      params->*field.number = value;
    } else {
      params->*field.steps = static_cast<int>(std::lround(value));
    }
    return;
  }
  throw std::logic_error("no realism key " + key);
}

void AddKey(CalibrationReport* report, FittedKey key) {
  if (key.determined) SetRealismValue(&report->params, key.key, key.value);
  report->keys.push_back(std::move(key));
}

CalibrationTracker::CalibrationTracker(const std::vector<CalibrationSeries>& series,
                                       const std::vector<std::vector<bool>>& moving, const world::RealismParams& base)
    : series_(series), moving_(moving), base_(base) {}

void CalibrationTracker::RestNoise(const std::vector<CalibrationSeries>& series, double* position_sigma_m,
                                   double* heading_sigma_rad) {
  double position_sum = 0, heading_sum = 0;
  double n = 0;
  for (const CalibrationSeries& s : series) {
    for (size_t k = 1; k < s.steps(); ++k) {
      if (s.stale[k] || s.stale[k - 1] || s.near_late[k] || !Settled(s, k, true)) continue;
      const double dx = s.poses[k].x_m - s.poses[k - 1].x_m;
      const double dy = s.poses[k].y_m - s.poses[k - 1].y_m;
      position_sum += dx * dx + dy * dy;
      heading_sum += std::pow(WrappedAngle(s.poses[k].theta_rad - s.poses[k - 1].theta_rad), 2);
      n += 1;
    }
  }
  *position_sigma_m = n > 0 ? std::sqrt(position_sum / (4 * n)) : 0.0;
  *heading_sigma_rad = n > 0 ? std::sqrt(heading_sum / (2 * n)) : 0.0;
}

void CalibrationTracker::Fit(CalibrationReport* report) const {
  FitNoise(report);
  FitQuanta(report);
  FitDropouts(report);
  FitTiming(report);
}

void CalibrationTracker::FitNoise(CalibrationReport* report) const {
  // At rest: consecutive fresh measurements differ by two noises.
  double rest_pos = 0, rest_head = 0, rest_n = 0;
  // Moving steadily: the second difference of three fresh measurements is
  // four noises (1, -2, 1) and next to no motion.
  double move_pos = 0, move_head = 0, move_n = 0;
  for (size_t r = 0; r < series_.size(); ++r) {
    const CalibrationSeries& s = series_[r];
    for (size_t k = 1; k < s.steps(); ++k) {
      if (s.stale[k] || s.stale[k - 1] || s.near_late[k]) continue;
      const world::Pose2& b = s.poses[k];
      const world::Pose2& a = s.poses[k - 1];
      if (!moving_[r][k] && !moving_[r][k - 1] && Settled(s, k, true)) {
        const double dx = b.x_m - a.x_m;
        const double dy = b.y_m - a.y_m;
        rest_pos += dx * dx + dy * dy;
        rest_head += std::pow(WrappedAngle(b.theta_rad - a.theta_rad), 2);
        rest_n += 1;
        if (report->rest_noise_m.size() < kMaxSamples) report->rest_noise_m.push_back(dx / std::sqrt(2.0));
      }
      if (k + 1 < s.steps() && !s.stale[k + 1] && moving_[r][k - 1] && moving_[r][k] && moving_[r][k + 1] &&
          Settled(s, k + 1, false) && std::abs(s.commands[k].w_radps) < 0.05) {
        const world::Pose2& c = s.poses[k + 1];
        // Steps of unequal length move the robot unequally: take that out
        // (at the commanded speed) before reading noise from the difference.
        const double uneven_m = s.commands[k].v_mps * (s.step_s[k] - s.step_s[k - 1]);
        const double ddx = c.x_m - 2 * b.x_m + a.x_m - uneven_m * std::cos(b.theta_rad);
        const double ddy = c.y_m - 2 * b.y_m + a.y_m - uneven_m * std::sin(b.theta_rad);
        const double ddt = WrappedAngle(c.theta_rad - b.theta_rad) - WrappedAngle(b.theta_rad - a.theta_rad);
        move_pos += ddx * ddx + ddy * ddy;
        move_head += ddt * ddt;
        move_n += 1;
        if (report->moving_noise_m.size() < kMaxSamples) report->moving_noise_m.push_back(ddx / std::sqrt(6.0));
      }
    }
  }
  if (rest_n >= 50) {
    const double sigma = std::sqrt(rest_pos / (4 * rest_n));
    const double heading = std::sqrt(rest_head / (2 * rest_n));
    // Neighbouring differences share a measurement: about half as many independent ones.
    AddKey(report, SigmaKey("pose_noise_m", sigma, rest_n, Count(rest_n) + " pairs of measurements at rest"));
    AddKey(report, SigmaKey("pose_noise_rad", heading, rest_n, Count(rest_n) + " pairs of measurements at rest"));
    if (sigma <= 0.0) {
      // Poses without noise at rest (a simulator's): no ratio to take.
      AddKey(report, KeptKey(base_, "pose_noise_moving_factor",
                             "no position noise at rest (exact poses, as a simulator gives), so no ratio to it"));
    } else if (move_n >= 50) {
      const double moving = std::sqrt(move_pos / (12 * move_n));
      const double factor = std::max(1.0, moving / sigma);
      const double relative = kZ95 * std::sqrt(1.0 / (2 * rest_n) + 1.0 / (2 * move_n));
      const double heading_moving = std::sqrt(move_head / (6 * move_n));
      AddKey(report, FittedKey{"pose_noise_moving_factor", factor, std::max(1.0, factor * (1 - relative)),
                               std::max(1.0, factor * (1 + relative)), true,
                               Count(move_n) + " steady moving triples: " + world::PrintfText("%.2f mm", moving * 1e3) +
                                   " and " + world::PrintfText("%.4f rad", heading_moving) + " moving"});
    } else {
      AddKey(report, KeptKey(base_, "pose_noise_moving_factor",
                             "too few steady moving measurements (" + Count(move_n) + "; 50 needed)"));
    }
  } else {
    const std::string why = "too few measurements of robots at rest (" + Count(rest_n) + "; 50 needed)";
    AddKey(report, KeptKey(base_, "pose_noise_m", why));
    AddKey(report, KeptKey(base_, "pose_noise_rad", why));
    AddKey(report, KeptKey(base_, "pose_noise_moving_factor", why));
  }
}

void CalibrationTracker::FitQuanta(CalibrationReport* report) const {
  // The largest of these that every fresh value is a multiple of.
  auto quantum = [this](auto value_of, double* checked) {
    for (double q : {0.01, 0.001, 0.0001}) {
      double n = 0, on = 0;
      for (const CalibrationSeries& s : series_) {
        for (size_t k = 0; k < s.steps(); ++k) {
          if (s.stale[k]) continue;
          const double units = value_of(s.poses[k]) / q;
          on += std::abs(units - std::round(units)) < 1e-6 * std::max(1.0, std::abs(units)) ? 1 : 0;
          n += 1;
        }
      }
      *checked = n;
      if (n > 0 && on / n >= 0.999) return q;
    }
    return 0.0;
  };
  double n = 0;
  const double heading_q = quantum([](const world::Pose2& p) { return p.theta_rad; }, &n);
  AddKey(report, FittedKey{"pose_quantum_rad", heading_q, heading_q, heading_q, true,
                           heading_q > 0 ? "every one of " + Count(n) + " headings is a multiple of it"
                                         : "the " + Count(n) + " headings are not rounded to 0.1 mrad or coarser"});
  const double position_q = quantum([](const world::Pose2& p) { return p.x_m; }, &n);
  AddKey(report, FittedKey{"pose_quantum_m", position_q, position_q, position_q, true,
                           position_q > 0 ? "every one of " + Count(n) + " x values is a multiple of it"
                                          : "the " + Count(n) + " x values are not rounded to 0.1 mm or coarser"});
}

void CalibrationTracker::FitDropouts(CalibrationReport* report) const {
  double moving_starts = 0, moving_n = 0, rest_starts = 0, rest_n = 0;
  double burst_sum = 0, bursts = 0;
  for (size_t r = 0; r < series_.size(); ++r) {
    const CalibrationSeries& s = series_[r];
    int length = 0;
    for (size_t k = 1; k < s.steps(); ++k) {
      if (s.stale[k]) {
        ++length;
        if (!s.stale[k - 1]) {
          (moving_[r][k] ? moving_starts : rest_starts) += 1;
        }
      } else if (length > 0) {
        report->stale_bursts.push_back(length);
        burst_sum += length;
        bursts += 1;
        length = 0;
      }
      if (!s.stale[k - 1]) (moving_[r][k] ? moving_n : rest_n) += 1;
    }
  }
  if (moving_n < 1000) {
    const std::string why = "too few moving measurements (" + Count(moving_n) + "; 1000 needed)";
    AddKey(report, KeptKey(base_, "tracking_dropout_probability", why));
    AddKey(report, KeptKey(base_, "tracking_dropout_at_rest_factor", why));
    AddKey(report, KeptKey(base_, "tracking_dropout_mean_steps", why));
    return;
  }
  const FittedKey moving =
      ProportionKey("tracking_dropout_probability", moving_starts, moving_n,
                    Count(moving_starts) + " runs of repeated poses in " + Count(moving_n) + " moving measurements");
  AddKey(report, moving);
  if (rest_n >= 1000 && moving_starts > 0) {
    const FittedKey rest = ProportionKey("at rest", rest_starts, rest_n, "");
    const double factor = std::max(1.0, rest.value / moving.value);
    AddKey(report, FittedKey{"tracking_dropout_at_rest_factor", factor, std::max(1.0, rest.low / moving.high),
                             std::max(1.0, moving.low > 0 ? rest.high / moving.low : rest.high / moving.value), true,
                             Count(rest_starts) + " runs in " + Count(rest_n) + " measurements at rest"});
  } else {
    AddKey(report, KeptKey(base_, "tracking_dropout_at_rest_factor",
                           "too few measurements at rest (" + Count(rest_n) + "), or no repeated pose while moving"));
  }
  if (bursts >= 5) {
    double sq = 0;
    for (int length : report->stale_bursts) sq += std::pow(length - burst_sum / bursts, 2);
    const double mean = burst_sum / bursts;
    const double half = kZ95 * std::sqrt(sq / std::max(1.0, bursts - 1) / bursts);
    // Runs last mean_steps / (1 - p) on average (a new dropout extends one).
    const double p = moving.value;
    AddKey(report,
           FittedKey{"tracking_dropout_mean_steps", std::max(1.0, mean * (1 - p)),
                     std::max(1.0, (mean - half) * (1 - p)), std::max(1.0, (mean + half) * (1 - p)), true,
                     Count(bursts) + " runs of repeated poses, the longest " +
                         std::to_string(*std::max_element(report->stale_bursts.begin(), report->stale_bursts.end())) +
                         " steps"});
  } else {
    AddKey(report, KeptKey(base_, "tracking_dropout_mean_steps",
                           "fewer than 5 runs of repeated poses (" + Count(bursts) + ")"));
  }
}

void CalibrationTracker::FitTiming(CalibrationReport* report) const {
  const double dt = RobotariumConstants::kTimeStepSeconds;
  double overrun = 0, steps = 0, stalls = 0, longest = 0, sq = 0;
  for (const CalibrationSeries& s : series_) {
    if (!s.timed || s.robot != 0) continue;  // a run's robots share its clock
    for (double step_s : s.step_s) {
      const double late = step_s - dt;
      steps += 1;
      if (late >= world::RealismParams::kMinStallS) {
        stalls += 1;
        longest = std::max(longest, late);
      } else {
        overrun += late;
        sq += late * late;
      }
    }
  }
  if (steps < 100) {
    const std::string why = steps == 0 ? "no run has a real clock (the times are the nominal 33 ms steps)"
                                       : "too few timed steps (" + Count(steps) + ")";
    AddKey(report, KeptKey(base_, "step_overrun_mean_s", why));
    AddKey(report, KeptKey(base_, "loop_stall_probability", why));
    AddKey(report, KeptKey(base_, "loop_stall_max_s", why));
    return;
  }
  const double normal = steps - stalls;
  const double mean = overrun / normal;
  const double sd = std::sqrt(std::max(0.0, sq / normal - mean * mean));
  const double half = kZ95 * sd / std::sqrt(normal);
  AddKey(report,
         FittedKey{"step_overrun_mean_s", std::max(0.0, mean), std::max(0.0, mean - half), std::max(0.0, mean + half),
                   true, Count(normal) + " steps, mean period " + world::PrintfText("%.2f ms", (dt + mean) * 1e3)});
  AddKey(report, ProportionKey("loop_stall_probability", stalls, steps,
                               Count(stalls) + " stalls (steps over " +
                                   world::PrintfText("%.0f ms", (dt + world::RealismParams::kMinStallS) * 1e3) +
                                   ") in " + Count(steps) + " steps"));
  if (stalls > 0) {
    AddKey(report, FittedKey{"loop_stall_max_s", std::max(longest, world::RealismParams::kMinStallS),
                             std::max(longest, world::RealismParams::kMinStallS), world::RealismParams::kMaxStallS,
                             true, "the longest stall seen (a lower bound)"});
  } else {
    AddKey(report, KeptKey(base_, "loop_stall_max_s", "no stall seen"));
  }
}

}  // namespace dream::calibration
