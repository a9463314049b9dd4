#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dream/agents/framework/robot.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/geometry/voronoi_cell.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::voronoi_coverage {

/// Parameters of VoronoiCoverageRobot.
struct VoronoiCoverageParams {
  agents::VoronoiCellParams cell;
  double gain = 1.0;            ///< proportional gain towards the centroid, 1/s; > 0
  double max_speed_mps = 0.15;  ///< cap on the planar velocity, also assumed of neighbours; (0, 0.2]
  double tolerance_m = 0.03;    ///< at the centroid within this distance the robot holds still (thesis: 0.02-0.05); > 0
  double step_s = robotarium::RobotariumConstants::kTimeStepSeconds;  ///< the world's time step; > 0
  int done_after_still_steps = 30;  ///< done after this many consecutive updates holding still; >= 1
  int radio_rounds_before_moving =
      2;  ///< hold still until the radio ran this often (it has heard its neighbours); >= 0

  /// The config keys (`controller:` of kind voronoi_coverage, with the cell's).
  template <typename Fields>
  void ListFields(Fields& fields) {
    cell.ListFields(fields);
    fields.Number("gain", gain, agents::FieldRule::Positive(), "proportional gain towards the goal, 1/s");
    fields.Number("max_speed_mps", max_speed_mps, agents::FieldRule::RobotSpeed(),
                  "cap on the planar velocity, also assumed of neighbours, m/s");
    fields.Number("tolerance_m", tolerance_m, agents::FieldRule::Positive(),
                  "within this distance of its goal a robot holds still (thesis: 0.02-0.05), m");
    fields.Whole("done_after_still_steps", done_after_still_steps, agents::FieldRule::AtLeast(1),
                 "a robot reports done after holding still this many updates");
    fields.Whole("radio_rounds_before_moving", radio_rounds_before_moving, agents::FieldRule::AtLeast(0),
                 "hold still until the radio ran this often (heard the neighbours)");
  }

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

/// The thesis's Voronoi coverage robot (section 3.3, Algorithm 1), a plain
/// Robot without HRVO: the partition itself keeps robots apart.
///
/// Radio: broadcasts its own position (PositionMessage) and keeps the latest
/// position heard from each neighbour in range; a malformed payload is
/// counted and dropped (the neighbour's previous position stays). It holds
/// still until its radio has run radio_rounds_before_moving times, so it
/// never moves before it has heard its neighbours.
///
/// Update (every step by default): builds its VoronoiCell from its odometry,
/// the neighbours' positions (each bisector moved further in by
/// max_speed x (age of the news + time until the next update), as the
/// neighbour may move meanwhile), the obstacles' closest points (virtual
/// agents) and rectangles; heads for the cell's goal -- the point of the cell
/// closest to the coverage centroid -- with dxi = gain (goal - p) capped at
/// max_speed, mapped by the thesis's dxi_to_dxu and limited to what the
/// wheels can do. Within tolerance_m of the goal it holds still (done after
/// done_after_still_steps such updates). Then the forward speed is cut:
///   - SafeSpeed: the step (x += dt v (cos th, sin th), as the world
///     integrates) keeps every constraint of the cell, and does not go
///     further out of one already violated; turning is always allowed;
///   - DescentSpeed (when inside the cell): the step does not end farther
///     from the coverage centroid, which is what keeps the coverage cost from
///     rising (see VoronoiCell).
/// Outside its cell (a moving obstacle came closer) it heads back in at full
/// speed, without the tolerance. With an empty cell it heads back across the
/// constraints it violates. The one-step checks are exact for a robot period
/// of 1 step; longer periods use the same straight-line prediction.
class VoronoiCoverageRobot final : public agents::Robot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  VoronoiCoverageRobot(int id, const agents::RobotParams& robot_params, const VoronoiCoverageParams& params);

  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<agents::RadioMessage>& heard) override;
  agents::UnicycleCommand Update(int64_t step) override;
  bool done() const override { return still_updates_ >= params_.done_after_still_steps; }

  /// The goal of the last update (its cell's centroid); the own position before.
  const Eigen::Vector2d& goal_m() const { return goal_m_; }
  /// Neighbours whose position the robot knows.
  size_t known_neighbours() const { return neighbours_.size(); }

  /// The forward speed closest to `v_mps` (towards zero) with which one step
  /// of `step_s` from `position` along `heading_rad` keeps every constraint,
  /// or does not worsen one already violated. Always allows 0.
  static double SafeSpeed(double v_mps, const std::vector<agents::HalfPlane>& constraints,
                          const Eigen::Vector2d& position_m, double heading_rad, double step_s);
  /// The forward speed closest to `v_mps` (towards zero) with which one step
  /// does not take the robot farther from `centroid_m`: what keeps every
  /// robot's share of the coverage cost from rising. Always allows 0.
  static double DescentSpeed(double v_mps, const Eigen::Vector2d& centroid_m, const Eigen::Vector2d& position_m,
                             double heading_rad, double step_s);

 private:
  struct Known {
    Eigen::Vector2d position_m;
    int64_t sent_step = 0;
  };

  VoronoiCoverageParams params_;
  std::map<int, Known> neighbours_;
  int radio_rounds_ = 0;
  int still_updates_ = 0;
  int64_t last_update_step_ = -1;
  Eigen::Vector2d goal_m_ = Eigen::Vector2d::Zero();
};

}  // namespace dream::voronoi_coverage
