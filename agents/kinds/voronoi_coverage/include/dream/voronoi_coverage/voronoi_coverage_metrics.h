#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "dream/voronoi_coverage/coverage_cost.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/framework/experiment_metrics.h"
#include "dream/agents/geometry/robotarium_arena.h"

namespace dream::voronoi_coverage {

struct VoronoiCoverageMetricsParams {
  Eigen::Vector2d arena_min_m = agents::RobotariumArenaMin();  ///< the region to cover (minus obstacles)
  Eigen::Vector2d arena_max_m = agents::RobotariumArenaMax();
  int sample_steps = 10;  ///< the cost series keeps every this many steps; >= 1
  /// Time per step, to turn pose changes into speeds; > 0.
  double step_s = robotarium::RobotariumConstants::kTimeStepSeconds;
  double still_speed_mps = 0.005;  ///< a robot slower than this is still; > 0
  int still_window_steps = 30;     ///< robots have settled once all were still this many steps; >= 1
  /// Robotarium: the collision disc sits this far ahead of the centre.
  double collision_offset_m = robotarium::RobotariumConstants::kCollisionOffsetMeters;
  /// Robotarium: half the collision distance.
  double collision_radius_m = robotarium::RobotariumConstants::kCollisionDiameterMeters / 2.0;

  /// The config keys of the coverage metrics (in `controller:` of kind voronoi_coverage).
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Whole("coverage_sample_steps", sample_steps, agents::FieldRule::AtLeast(1),
                 "the metrics' cost series keeps every this many steps");
    fields.Number("still_speed_mps", still_speed_mps, agents::FieldRule::Positive(),
                  "metrics: a robot slower than this is still, m/s");
    fields.Whole("still_window_steps", still_window_steps, agents::FieldRule::AtLeast(1),
                 "metrics: settled once every robot was still this long, steps");
  }

  bool IsValid(std::string* error) const;
};

/// The Voronoi experiment's outcome, from poses and obstacles only:
///   coverage_cost_m4 (series, every sample_steps and the last step),
///   coverage_cost_initial_m4, coverage_cost_final_m4,
///   coverage_cost_max_rise_m4 / _step: the largest rise of the cost between
///     two consecutive observed steps (0 when it never rose), evaluated every
///     step, not only at the samples,
///   settled_step: the step from which every robot stayed still until the
///     end, if that lasted at least still_window_steps; else -1,
///   still_steps_at_end: how long that final still stretch was,
///   min_obstacle_clearance_m / _step: the least distance from a robot
///     centre to an obstacle rectangle (obstacles are the thesis's point),
///   obstacle_contact_steps: steps where a robot's collision disc (as the
///     Robotarium places it) touched an obstacle.
class VoronoiCoverageMetrics final : public agents::ExperimentMetrics {
 public:
  /// @throws std::invalid_argument when params are invalid.
  explicit VoronoiCoverageMetrics(const VoronoiCoverageMetricsParams& params);
  void Observe(const agents::WorldSnapshot& world) override;
  void Write(agents::MetricsReport* report) const override;
  std::optional<agents::GoalJudgement> JudgeGoal(const agents::MetricsReport& report) const override;

  const std::vector<std::pair<int64_t, double>>& cost_series() const { return series_; }
  double max_rise_m4() const { return max_rise_m4_; }
  int64_t settled_step() const;

 private:
  VoronoiCoverageMetricsParams params_;
  CoverageCost cost_;
  std::vector<std::pair<int64_t, double>> series_;
  std::vector<Eigen::Vector2d> previous_positions_;
  int64_t previous_step_ = -1;
  double previous_cost_ = std::numeric_limits<double>::quiet_NaN();
  double initial_cost_ = std::numeric_limits<double>::quiet_NaN();
  int64_t last_step_ = -1;
  double max_rise_m4_ = 0.0;
  int64_t max_rise_step_ = -1;
  int64_t still_since_step_ = -1;  ///< first step of the current still stretch
  int64_t still_steps_ = 0;
  double min_clearance_m_ = std::numeric_limits<double>::infinity();
  int64_t min_clearance_step_ = -1;
  int64_t contact_steps_ = 0;
};

}  // namespace dream::voronoi_coverage
