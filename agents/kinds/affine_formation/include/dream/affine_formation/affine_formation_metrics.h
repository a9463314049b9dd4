#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "dream/agents/framework/experiment_metrics.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::affine_formation {

/// Parameters of AffineFormationMetrics.
struct AffineFormationMetricsParams {
  std::vector<Eigen::Vector2d> nominal_m;  ///< the nominal configuration, one point per robot
  std::vector<int> leaders;                ///< at least 3, not collinear in nominal_m
  double tolerance_m = 0.05;               ///< a follower within this of its target tracks it; > 0
  /// The convergence window starts here: max_follower_error_after_convergence_m
  /// is the worst follower error from this step to the end of the run. >= 0.
  int64_t converged_from_step = 0;
  /// Obstacle ids (as the world numbers them: their order in the run config)
  /// that form a gate the formation passes through, two per pair.
  std::vector<std::array<int, 2>> obstacle_pairs;
  int series_every_steps = 10;  ///< formation error series resolution, >= 1
  /// The Robotarium's collision check...
  double collision_diameter_m = robotarium::RobotariumConstants::kCollisionDiameterMeters;
  /// ...around the point this far ahead of the centre.
  double collision_offset_m = robotarium::RobotariumConstants::kCollisionOffsetMeters;

  bool IsValid(std::string* error) const;

  /// The config keys of `metrics:` (kind affine_formation); `obstacle_pairs` is read by the builder.
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("tolerance_m", tolerance_m, agents::FieldRule::Positive(),
                  "a follower within this of its target tracks it, m");
    fields.Whole("converged_from_step", converged_from_step, agents::FieldRule::AtLeast(0),
                 "the convergence window starts here (worst follower error from here to the end)");
    fields.Custom(kObstaclePairsKey,
                  "`[[a, b], ...]`: obstacle ids (their order in `obstacles:`) forming a gate; clearance and passage "
                  "per pair (none by default)");
    fields.Whole("series_every_steps", series_every_steps, agents::FieldRule::AtLeast(1),
                 "resolution of the `max_follower_error_m` series, steps");
  }
  static constexpr const char* kObstaclePairsKey = "obstacle_pairs";
};

/// How well the affine formation did, from the world's poses and obstacles:
///  - follower error: each follower's distance to its target, the affine
///    image of its nominal point under the map that the leaders' actual
///    positions define (least squares over the leaders, exact for three), so
///    leaders' own tracking errors do not count against the followers;
///  - per obstacle pair: the smallest distance from any robot's centre to
///    either obstacle, the smallest clearance of any robot's collision disc
///    (<= 0 is a touch, as the Robotarium counts it), the steps with a touch,
///    and the step when the pair's centre crossed the formation's centroid.
class AffineFormationMetrics final : public agents::ExperimentMetrics {
 public:
  /// @throws std::invalid_argument when params are invalid.
  explicit AffineFormationMetrics(AffineFormationMetricsParams params);
  void Observe(const agents::WorldSnapshot& world) override;
  void Write(agents::MetricsReport* report) const override;
  std::optional<agents::GoalJudgement> JudgeGoal(const agents::MetricsReport& report) const override;

  double max_error_after_convergence_m() const { return max_after_m_; }
  /// First step from which the max follower error stays within tolerance to
  /// the end; -1 if it never does.
  int64_t settled_step() const { return settled_step_; }

 private:
  struct PairStats {
    double min_clearance_m = std::numeric_limits<double>::infinity();
    double min_distance_m = std::numeric_limits<double>::infinity();  // robot centre to rectangle
    int64_t min_clearance_step = -1;
    int64_t passage_step = -1;
    int64_t contact_steps = 0;
    int side = 0;  // sign of (pair centre x - formation centroid x) when first seen
  };

  AffineFormationMetricsParams params_;
  std::vector<int> followers_;
  std::vector<PairStats> pairs_;
  std::vector<std::pair<int64_t, double>> series_;
  double max_after_m_ = 0.0;
  double sum_after_m_ = 0.0;
  int64_t steps_after_ = 0;
  double last_max_m_ = 0.0;
  int64_t settled_step_ = -1;
  int64_t fit_failures_ = 0;
};

}  // namespace dream::affine_formation
