#include "dream/affine_formation/affine_formation_metrics.h"
#include "dream/agents/fields/field_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dream/agents/framework/params_check.h"
#include "dream/agents/geometry/affine_transform.h"

namespace dream::affine_formation {
namespace {

// Distance from a point to an axis-aligned rectangle (0 inside).
double DistanceToRectangle(const Eigen::Vector2d& p, const agents::ObstacleView& o) {
  const Eigen::Vector2d gap = ((p - o.center_m).cwiseAbs() - o.size_m / 2.0).cwiseMax(0.0);
  return gap.norm();
}

const agents::ObstacleView* FindObstacle(const agents::WorldSnapshot& world, int id) {
  for (const agents::ObstacleView& o : world.obstacles) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

}  // namespace

bool AffineFormationMetricsParams::IsValid(std::string* error) const {
  std::vector<Eigen::Vector2d> leader_points;
  for (int id : leaders) {
    if (id < 0 || size_t(id) >= nominal_m.size())
      return agents::FailParams(error, "leaders: id " + std::to_string(id) + " is not a robot");
    leader_points.push_back(nominal_m[size_t(id)]);
  }
  if (!agents::AffineTransform::Fit(leader_points, leader_points)) {
    return agents::FailParams(error, "leaders: need at least 3 leaders whose nominal points are not collinear");
  }
  if (!agents::CheckFields(*this, error)) return false;
  for (const auto& pair : obstacle_pairs) {
    if (pair[0] < 0 || pair[1] < 0) return agents::FailParams(error, "obstacle_pairs: obstacle ids must be >= 0");
  }
  if (!(collision_diameter_m > 0.0) || !(collision_offset_m >= 0.0)) {
    return agents::FailParams(error, "collision_diameter_m must be > 0 and collision_offset_m >= 0");
  }
  return true;
}

AffineFormationMetrics::AffineFormationMetrics(AffineFormationMetricsParams params) : params_(std::move(params)) {
  std::string error;
  if (!params_.IsValid(&error)) throw std::invalid_argument(error);
  for (int i = 0; i < static_cast<int>(params_.nominal_m.size()); ++i) {
    if (std::find(params_.leaders.begin(), params_.leaders.end(), i) == params_.leaders.end()) followers_.push_back(i);
  }
  pairs_.resize(params_.obstacle_pairs.size());
}

void AffineFormationMetrics::Observe(const agents::WorldSnapshot& world) {
  if (world.poses.size() < params_.nominal_m.size()) return;
  std::vector<Eigen::Vector2d> from;
  std::vector<Eigen::Vector2d> to;
  for (int id : params_.leaders) {
    from.push_back(params_.nominal_m[size_t(id)]);
    to.push_back(world.poses[size_t(id)].head<2>());
  }
  const std::optional<agents::AffineTransform> map = agents::AffineTransform::Fit(from, to);
  if (!map) {
    ++fit_failures_;
  } else {
    double worst = 0.0;
    for (int f : followers_) {
      worst = std::max(worst, (map->Apply(params_.nominal_m[size_t(f)]) - world.poses[size_t(f)].head<2>()).norm());
    }
    last_max_m_ = worst;
    if (world.step % params_.series_every_steps == 0) series_.emplace_back(world.step, worst);
    if (world.step >= params_.converged_from_step) {
      max_after_m_ = std::max(max_after_m_, worst);
      sum_after_m_ += worst;
      ++steps_after_;
    }
    if (worst > params_.tolerance_m) {
      settled_step_ = -1;
    } else if (settled_step_ < 0) {
      settled_step_ = world.step;
    }
  }

  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < params_.nominal_m.size(); ++i) centroid += world.poses[i].head<2>();
  centroid /= static_cast<double>(params_.nominal_m.size());
  const double radius_m = params_.collision_diameter_m / 2.0;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    PairStats& stats = pairs_[k];
    const agents::ObstacleView* a = FindObstacle(world, params_.obstacle_pairs[k][0]);
    const agents::ObstacleView* b = FindObstacle(world, params_.obstacle_pairs[k][1]);
    if (a == nullptr || b == nullptr) continue;
    bool contact = false;
    for (size_t i = 0; i < params_.nominal_m.size(); ++i) {
      const Eigen::Vector3d& pose = world.poses[i];
      const Eigen::Vector2d disc =
          pose.head<2>() + params_.collision_offset_m * Eigen::Vector2d(std::cos(pose.z()), std::sin(pose.z()));
      const double clearance = std::min(DistanceToRectangle(disc, *a), DistanceToRectangle(disc, *b)) - radius_m;
      if (clearance < stats.min_clearance_m) {
        stats.min_clearance_m = clearance;
        stats.min_clearance_step = world.step;
      }
      contact = contact || clearance <= 0.0;
      stats.min_distance_m = std::min(
          {stats.min_distance_m, DistanceToRectangle(pose.head<2>(), *a), DistanceToRectangle(pose.head<2>(), *b)});
    }
    if (contact) ++stats.contact_steps;
    const double offset = (a->center_m.x() + b->center_m.x()) / 2.0 - centroid.x();
    const int side = offset > 0.0 ? 1 : (offset < 0.0 ? -1 : 0);
    if (stats.side == 0) {
      stats.side = side;
    } else if (stats.passage_step < 0 && side != 0 && side != stats.side) {
      stats.passage_step = world.step;
    }
  }
}

void AffineFormationMetrics::Write(agents::MetricsReport* report) const {
  auto& v = report->values;
  v["follower_error_tolerance_m"] = params_.tolerance_m;
  v["convergence_window_start_step"] = static_cast<double>(params_.converged_from_step);
  v["max_follower_error_after_convergence_m"] = max_after_m_;
  v["mean_follower_error_after_convergence_m"] = steps_after_ > 0 ? sum_after_m_ / double(steps_after_) : 0.0;
  v["final_max_follower_error_m"] = last_max_m_;
  v["settled_step"] = static_cast<double>(settled_step_);
  v["leader_fit_failures"] = static_cast<double>(fit_failures_);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const std::string name = "obstacle_pair_" + std::to_string(k) + "_";
    const PairStats& stats = pairs_[k];
    if (std::isfinite(stats.min_clearance_m)) {
      v[name + "min_clearance_m"] = stats.min_clearance_m;
      v[name + "min_clearance_step"] = static_cast<double>(stats.min_clearance_step);
      v[name + "min_distance_m"] = stats.min_distance_m;
    }
    v[name + "passage_step"] = static_cast<double>(stats.passage_step);
    v[name + "contact_steps"] = static_cast<double>(stats.contact_steps);
  }
  report->series["max_follower_error_m"] = series_;
  const agents::MetricsReport::Threshold tolerance{
      params_.tolerance_m, "goal: within " + agents::GoalJudgement::Metres(params_.tolerance_m)};
  for (const char* name :
       {"max_follower_error_m", "final_max_follower_error_m", "max_follower_error_after_convergence_m"}) {
    report->thresholds[name] = tolerance;
  }
}

// Goal: after convergence every follower stays within the tolerance.
std::optional<agents::GoalJudgement> AffineFormationMetrics::JudgeGoal(const agents::MetricsReport& report) const {
  const double worst_m = report.Value("max_follower_error_after_convergence_m");
  const double tolerance_m = report.Value("follower_error_tolerance_m");
  agents::GoalJudgement goal;
  goal.met = worst_m >= 0.0 && tolerance_m > 0.0 && worst_m <= tolerance_m;
  goal.completion_step = static_cast<int64_t>(report.Value("settled_step"));
  goal.detail = "worst follower error " + agents::GoalJudgement::MetresApart(worst_m, tolerance_m) +
                (goal.met ? " <= " : " > ") + agents::GoalJudgement::Metres(tolerance_m);
  return goal;
}

}  // namespace dream::affine_formation
