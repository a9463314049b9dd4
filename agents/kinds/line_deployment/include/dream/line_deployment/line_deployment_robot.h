#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dream/agents/fields/field_rule.h"
#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/line_deployment/line_consensus.h"
#include "dream/agents/geometry/robotarium_arena.h"

namespace dream::line_deployment {

/// Parameters of LineDeploymentRobot.
struct LineDeploymentParams {
  double spacing_m = 0.4;      ///< d of eq. 3.7: distance between consecutive ids on the line; > 0
  double gain = 2.0;           ///< preferred velocity = gain * (target - position), 1/s; > 0
  double max_speed_mps = 0.2;  ///< cap on the preferred speed; (0, 0.2]
  /// Hysteresis against dithering: a moving robot stops once closer than
  /// tolerance_m to its target; a still one starts again only when the
  /// target is farther than resume_m (its neighbours moved). The spread of
  /// the final line grows with these (residuals add up along the graph).
  double tolerance_m = 0.0015;  ///< > 0
  double resume_m = 0.003;      ///< >= tolerance_m
  /// A robot holding still avoids only neighbours closer than this (centre
  /// to centre). The movement sensor reports the velocity of a point 0.05 m
  /// ahead of each neighbour, so a neighbour turning on the spot to correct
  /// a few millimetres looks like one driving at up to 0.18 m/s; without
  /// this, settled robots 0.4 m apart kept pushing each other off the line.
  /// Moving robots avoid everyone they see. >= 0 (0: a still robot avoids no one).
  double hold_avoid_range_m = 0.3;
  /// Done after this many consecutive control updates holding still (long
  /// enough that every neighbour has broadcast its settled position); >= 1.
  int settle_updates = 20;
  /// Targets are clamped this far inside the arena: eq. 3.7 places the line
  /// wherever the start positions put it, possibly past a wall, and a robot
  /// centre outside the arena gets the run rejected. A robot held at the
  /// margin anchors the line (the others reach consensus with it), so the
  /// line still forms, shifted. >= 0, and the arena must stay non-empty.
  double arena_margin_m = 0.15;
  Eigen::Vector2d arena_min_m = agents::RobotariumArenaMin();  ///< Robotarium arena, world frame
  Eigen::Vector2d arena_max_m = agents::RobotariumArenaMax();

  /// The config keys (`controller:` of kind line_deployment), once for reading, checking and the docs.
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("spacing_m", spacing_m, agents::FieldRule::Positive(),
                  "d of eq. 3.7: spacing between consecutive ids, m (6 robots then span 2 m)");
    fields.Number("gain", gain, agents::FieldRule::Positive(), "preferred velocity = gain x (target - position), 1/s");
    fields.Number("max_speed_mps", max_speed_mps, agents::FieldRule::RobotSpeed(), "cap on the preferred speed, m/s");
    fields.Number("tolerance_m", tolerance_m, agents::FieldRule::Positive(),
                  "a moving robot stops this close to its target, m ...");
    fields.Number("resume_m", resume_m, agents::FieldRule::Finite(),
                  "... and a still one moves again when its target is farther than this, m, >= `tolerance_m`");
    fields.Number("hold_avoid_range_m", hold_avoid_range_m, agents::FieldRule::NonNegative(),
                  "a still robot's HRVO considers only neighbours closer than this, m");
    fields.Whole("settle_updates", settle_updates, agents::FieldRule::Within(1, 100000),
                 "done after this many control updates in a row holding still");
    fields.Number("arena_margin_m", arena_margin_m, agents::FieldRule::NonNegative(),
                  "targets are clamped this far inside the arena (a clamped robot anchors the line), m");
  }
  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

/// The thesis's line deployment robot (section 3.2): broadcasts (id, x, y)
/// from its odometry over a graph radio, keeps each neighbour's latest
/// position, and drives through HRVO towards the eq. 3.7 consensus target
/// (LineConsensusTarget). A neighbour's malformed payload (wrong size,
/// non-finite value, id not the sender's) is counted and dropped; its last
/// good position is kept. Holds still until it has heard from a neighbour.
class LineDeploymentRobot final : public agents::HrvoRobot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  LineDeploymentRobot(int id, const agents::RobotParams& robot_params, const agents::HrvoRobotParams& hrvo_params,
                      const LineDeploymentParams& params);

  void OnMovement(const agents::MovementReading& reading) override;
  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<agents::RadioMessage>& heard) override;
  agents::UnicycleCommand Update(int64_t step) override;
  bool done() const override { return settled_updates_ >= params_.settle_updates; }

  /// The eq. 3.7 target from the neighbours heard so far, clamped into the
  /// arena less arena_margin_m.
  std::optional<Eigen::Vector2d> Target() const;
  /// Neighbours' positions by id, from their radio payloads (PositionMessage).
  const std::map<int, Eigen::Vector2d>& neighbour_positions() const { return neighbours_; }

 private:
  LineDeploymentParams params_;
  std::map<int, Eigen::Vector2d> neighbours_;  // by id: latest good position
  bool moving_ = true;
  agents::MovementReading near_;  // scratch: the neighbours a still robot avoids
  int settled_updates_ = 0;
};

}  // namespace dream::line_deployment
