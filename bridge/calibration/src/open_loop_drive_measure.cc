#include "dream/calibration/open_loop_drive_measure.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dream/world/realistic_world.h"
#include "dream/world/world_params.h"

namespace dream::calibration {
namespace {

constexpr size_t kHalfWindow = 4;  // a centred 9-step average
constexpr size_t kLineFrom = 60;
constexpr size_t kLineTo = 200;
constexpr size_t kTurnFrom = 100;

// Least squares line y = a + b t: its slope and intercept.
void Line(const std::vector<double>& t, const std::vector<double>& y, double* slope, double* intercept) {
  const auto n = static_cast<double>(t.size());
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (size_t k = 0; k < t.size(); ++k) {
    st += t[k];
    sy += y[k];
    stt += t[k] * t[k];
    sty += t[k] * y[k];
  }
  const double denominator = n * stt - st * st;
  *slope = denominator != 0.0 ? (n * sty - st * sy) / denominator : 0.0;
  *intercept = (sy - *slope * st) / n;
}

}  // namespace

double OpenLoopDriveMeasure::EffectiveDelay(const std::vector<world::Pose2>& poses, const std::vector<double>& time_s) {
  if (poses.size() < kLineTo + kHalfWindow + 1 || time_s.size() != poses.size()) {
    throw std::invalid_argument("OpenLoopDriveMeasure: an effective delay needs " +
                                std::to_string(kLineTo + kHalfWindow + 1) + " poses");
  }
  // Smoothed where the whole window exists; the ends keep the shorter window.
  std::vector<double> x(poses.size()), y(poses.size());
  for (size_t k = 0; k < poses.size(); ++k) {
    const size_t from = k >= kHalfWindow ? k - kHalfWindow : 0;
    const size_t to = std::min(poses.size() - 1, k + kHalfWindow);
    double sx = 0, sy = 0;
    for (size_t j = from; j <= to; ++j) {
      sx += poses[j].x_m;
      sy += poses[j].y_m;
    }
    x[k] = sx / static_cast<double>(to - from + 1);
    y[k] = sy / static_cast<double>(to - from + 1);
  }
  std::vector<double> t, s;
  double length = 0;
  for (size_t k = 1; k <= kLineTo; ++k) {
    length += std::hypot(x[k] - x[k - 1], y[k] - y[k - 1]);
    if (k < kLineFrom) continue;
    t.push_back(time_s[k] - time_s[0]);
    s.push_back(length);
  }
  double slope = 0, intercept = 0;
  Line(t, s, &slope, &intercept);
  return slope > 0.0 ? -intercept / slope : 0.0;
}

double OpenLoopDriveMeasure::TurningRatio(const std::vector<world::Pose2>& poses, const std::vector<double>& time_s,
                                          double w_radps) {
  if (poses.size() < 2 * kTurnFrom || time_s.size() != poses.size() || w_radps == 0.0) {
    throw std::invalid_argument("OpenLoopDriveMeasure: a turning ratio needs " + std::to_string(2 * kTurnFrom) +
                                " poses and a commanded turn");
  }
  std::vector<double> t, heading;
  double unwrapped = poses[kTurnFrom].theta_rad;
  for (size_t k = kTurnFrom; k < poses.size(); ++k) {
    if (k > kTurnFrom) unwrapped += std::remainder(poses[k].theta_rad - poses[k - 1].theta_rad, 2 * M_PI);
    t.push_back(time_s[k] - time_s[0]);
    heading.push_back(unwrapped);
  }
  double slope = 0, intercept = 0;
  Line(t, heading, &slope, &intercept);
  return slope / w_radps;
}

OpenLoopDriveMeasure::Drive OpenLoopDriveMeasure::Simulate(const world::RealismParams& realism, uint64_t seed,
                                                           int robots, int steps, world::UnicycleCommand command) {
  // Side by side, 0.3 m apart, facing +x: lines from the left so none meets
  // a wall within 2.8 m, circles from the middle.
  std::vector<world::Pose2> start;
  const double x = command.w_radps == 0.0 ? -1.4 : 0.0;
  for (int i = 0; i < robots; ++i) start.push_back({x, -0.9 + 0.3 * (i % 7), 0.0});
  world::RealisticWorld world(world::WorldParams{}, realism, seed, start);
  Drive drive;
  drive.poses.resize(static_cast<size_t>(robots));
  double time_s = 0;
  for (int k = 0; k < steps; ++k) {
    drive.time_s.push_back(time_s);
    for (int i = 0; i < robots; ++i) {
      drive.poses[static_cast<size_t>(i)].push_back(world.poses()[static_cast<size_t>(i)]);
      world.SetCommand(i, command);
    }
    world.Step();
    time_s += world::WorldParams{}.time_step_s + world.last_late_s();
  }
  return drive;
}

}  // namespace dream::calibration
