#pragma once

#include <vector>

#include "dream/kind_api/agent_parts_config.h"
#include "dream/agents/fields/field_names.h"
#include "dream/kind_api/experiment_builder.h"
#include "dream/voronoi_coverage/voronoi_coverage_metrics.h"
#include "dream/voronoi_coverage/voronoi_coverage_robot.h"
#include "dream/config/config_node.h"

namespace dream::voronoi_coverage {

/// `kind: voronoi_coverage` (thesis section 3.3): every robot heads for the
/// centroid of its buffered Voronoi cell (VoronoiCoverageRobot).
///     disc_radius_m: 1.0  disc_sides: 64  wall_margin_m: 0.06
///     robot_buffer_m: 0.1  obstacle_buffer_m: 0.12
///     gain: 1.0  max_speed_mps: 0.15  tolerance_m: 0.03
///     done_after_still_steps: 30  radio_rounds_before_moving: 2
///     coverage_sample_steps: 10  still_speed_mps: 0.005  still_window_steps: 30
class VoronoiCoverageBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "voronoi_coverage";
  /// The kind's section: the robots' and the metrics' keys, each named once.
  struct Section {
    VoronoiCoverageParams robot;
    VoronoiCoverageMetricsParams metrics;
    template <typename Fields>
    void ListFields(Fields& fields) {
      robot.ListFields(fields);
      metrics.ListFields(fields);
    }
  };
  /// Keys of this kind besides the common ones.
  static std::vector<std::string> Keys() { return agents::KeysOf<Section>(); }
  /// The thesis's parts: odometry and obstacle sensor (1 m) every step, a
  /// range radio every 3 steps reaching 2 m (= twice the disc radius: any
  /// robot that can cut a 1 m disc is heard), the control law every step
  /// (its one-step safety check assumes it).
  static kind_api::AgentPartsConfig DefaultParts(int num_robots);

  VoronoiCoverageBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;

 private:
  VoronoiCoverageParams params_;
  VoronoiCoverageMetricsParams metrics_;
};

}  // namespace dream::voronoi_coverage
