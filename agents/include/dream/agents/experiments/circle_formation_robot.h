#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dream/agents/experiments/formation_progress.h"
#include "dream/agents/hrvo/hrvo_robot.h"

namespace dream::agents {

/// Parameters of CircleFormationRobot.
struct CircleFormationParams {
  /// This robot's point in each formation, in order (the thesis: its circle
  /// point, the diametrically opposite one, its circle point again).
  std::vector<Eigen::Vector2d> goals_m;
  int num_robots = 10;          ///< robots taking part (size of the progress vector); >= 1
  double tolerance_m = 0.05;    ///< a point counts as reached within this distance (the thesis's 0.05); > 0
  double max_speed_mps = 0.2;   ///< preferred speed towards the point (the thesis's v_max); (0, 0.2]

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

/// The thesis's Robot_c (Appendix B): drive at full speed to the current
/// formation point through HRVO, count it reached within tolerance, and move
/// on to the next point only once the radio has brought news (possibly over
/// several hops) that every robot has reached the current one.
///
/// Radio: merges every neighbour's FormationProgress (malformed payloads are
/// counted and dropped), records its own state, and rebroadcasts the whole
/// vector. One deliberate change: the thesis advanced when every known state
/// *equalled* its own, which deadlocks if a faster robot has already reached
/// the next point; here every known state must be *at least* its own.
/// Done while it holds its last point: reached, and within tolerance_m by its
/// latest update. HRVO may make a robot that has arrived step aside for a
/// passing one; it then drives back and is not done meanwhile, so a run that
/// stops when every robot is done stops with the whole formation in place
/// (the thesis's Robot_c stayed done once it had arrived).
class CircleFormationRobot final : public HrvoRobot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  CircleFormationRobot(int id, const RobotParams& robot_params, const HrvoRobotParams& hrvo_params,
                       const CircleFormationParams& params);

  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<RadioMessage>& heard) override;
  UnicycleCommand Update(int64_t step) override;
  bool done() const override { return reached_ == static_cast<int>(params_.goals_m.size()) && at_goal_; }

  /// How many formation points this robot has reached (the thesis's state).
  int reached() const { return reached_; }
  /// Index of the point it is heading for (or holding).
  int goal_index() const { return goal_index_; }
  const FormationProgress& progress() const { return progress_; }

 private:
  CircleFormationParams params_;
  FormationProgress progress_;
  int reached_ = 0;
  int goal_index_ = 0;
  bool at_goal_ = false;  ///< within tolerance_m of the current point at the latest Update
};

}  // namespace dream::agents
