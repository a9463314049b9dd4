#include "dream/voronoi_coverage/voronoi_coverage_metrics.h"
#include "dream/agents/fields/field_check.h"

#include <cstdio>
#include <cmath>

#include "dream/agents/framework/params_check.h"

namespace dream::voronoi_coverage {

bool VoronoiCoverageMetricsParams::IsValid(std::string* error) const {
  if (!agents::CheckArena(error, arena_min_m, arena_max_m) || !agents::CheckFields(*this, error) ||
      !agents::CheckPositive(error, "step_s", step_s)) {
    return false;
  }
  if (!(std::isfinite(collision_offset_m) && collision_offset_m >= 0.0) ||
      !(std::isfinite(collision_radius_m) && collision_radius_m >= 0.0)) {
    return agents::FailParams(error, "collision_offset_m and collision_radius_m must be >= 0");
  }
  return true;
}

VoronoiCoverageMetrics::VoronoiCoverageMetrics(const VoronoiCoverageMetricsParams& params)
    : params_(agents::CheckedParams(params)), cost_(params.arena_min_m, params.arena_max_m) {}

void VoronoiCoverageMetrics::Observe(const agents::WorldSnapshot& world) {
  std::vector<Eigen::Vector2d> positions;
  positions.reserve(world.poses.size());
  for (const Eigen::Vector3d& pose : world.poses) positions.push_back(pose.head<2>());
  const double cost = cost_.Evaluate(positions, world.obstacles);

  if (std::isnan(initial_cost_)) initial_cost_ = cost;
  if (!std::isnan(previous_cost_) && cost - previous_cost_ > max_rise_m4_) {
    max_rise_m4_ = cost - previous_cost_;
    max_rise_step_ = world.step;
  }
  // Keep every sample_steps-th step; the last step is added by Write.
  if (series_.empty() || world.step % params_.sample_steps == 0) series_.emplace_back(world.step, cost);

  bool contact = false;
  for (const Eigen::Vector3d& pose : world.poses) {
    const Eigen::Vector2d centre = pose.head<2>();
    const Eigen::Vector2d heading(std::cos(pose.z()), std::sin(pose.z()));
    const Eigen::Vector2d disc = centre + params_.collision_offset_m * heading;
    for (const agents::ObstacleView& obstacle : world.obstacles) {
      const Eigen::Vector2d half = obstacle.size_m / 2.0;
      const Eigen::Vector2d lo = obstacle.center_m - half;
      const Eigen::Vector2d hi = obstacle.center_m + half;
      const double clearance = (centre - centre.cwiseMax(lo).cwiseMin(hi)).norm();
      if (clearance < min_clearance_m_) {
        min_clearance_m_ = clearance;
        min_clearance_step_ = world.step;
      }
      contact = contact || (disc - disc.cwiseMax(lo).cwiseMin(hi)).norm() <= params_.collision_radius_m;
    }
  }
  if (contact) ++contact_steps_;

  // Stillness from pose changes (a lab log has no trustworthy velocities).
  if (previous_step_ >= 0 && world.step > previous_step_ && positions.size() == previous_positions_.size()) {
    const double dt = static_cast<double>(world.step - previous_step_) * params_.step_s;
    bool still = true;
    for (size_t i = 0; i < positions.size() && still; ++i) {
      still = (positions[i] - previous_positions_[i]).norm() / dt < params_.still_speed_mps;
    }
    if (still) {
      if (still_since_step_ < 0) still_since_step_ = previous_step_;
      still_steps_ = world.step - still_since_step_;
    } else {
      still_since_step_ = -1;
      still_steps_ = 0;
    }
  }
  previous_positions_ = std::move(positions);
  previous_step_ = world.step;
  previous_cost_ = cost;
  last_step_ = world.step;
}

int64_t VoronoiCoverageMetrics::settled_step() const {
  return still_steps_ >= params_.still_window_steps ? still_since_step_ : -1;
}

void VoronoiCoverageMetrics::Write(agents::MetricsReport* report) const {
  if (series_.empty()) return;
  std::vector<std::pair<int64_t, double>> series = series_;
  if (series.back().first != last_step_) series.emplace_back(last_step_, previous_cost_);
  report->series["coverage_cost_m4"] = series;
  report->values["coverage_cost_initial_m4"] = initial_cost_;
  report->values["coverage_cost_final_m4"] = previous_cost_;
  report->values["coverage_cost_max_rise_m4"] = max_rise_m4_;
  report->values["coverage_cost_max_rise_step"] = static_cast<double>(max_rise_step_);
  report->values["settled_step"] = static_cast<double>(settled_step());
  report->values["still_steps_at_end"] = static_cast<double>(still_steps_);
  if (std::isfinite(min_clearance_m_)) {
    report->values["min_obstacle_clearance_m"] = min_clearance_m_;
    report->values["min_obstacle_clearance_step"] = static_cast<double>(min_clearance_step_);
  }
  report->values["obstacle_contact_steps"] = static_cast<double>(contact_steps_);
}

// Goal: settled (every robot still for the last 30+ steps); or, where blocks
// move to the last step and keep the robots giving way, covering: the cost
// fell to half or less and never rose by more than 1 %.
std::optional<agents::GoalJudgement> VoronoiCoverageMetrics::JudgeGoal(const agents::MetricsReport& report) const {
  agents::GoalJudgement goal;
  goal.completion_step = static_cast<int64_t>(report.Value("settled_step"));
  goal.met = goal.completion_step >= 0;
  goal.detail = "settled";
  if (!goal.met) {
    const double initial = report.Value("coverage_cost_initial_m4");
    const double final_cost = report.Value("coverage_cost_final_m4");
    const double rise = report.Value("coverage_cost_max_rise_m4");
    char text[96];
    std::snprintf(text, sizeof(text), "cost %.3g -> %.3g m^4, largest rise %.2g", initial, final_cost, rise);
    goal.met =
        initial > 0.0 && final_cost >= 0.0 && rise >= 0.0 && final_cost <= 0.5 * initial && rise <= 0.01 * initial;
    goal.detail = std::string(goal.met ? "covering, not settled: " : "not settled: ") + text;
  }
  return goal;
}

}  // namespace dream::voronoi_coverage
