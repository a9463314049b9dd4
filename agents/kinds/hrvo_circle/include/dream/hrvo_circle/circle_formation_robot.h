#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dream/hrvo_circle/formation_progress.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/hrvo/hrvo_robot.h"

namespace dream::hrvo_circle {

/// Parameters of CircleFormationRobot.
struct CircleFormationParams {
  /// This robot's point in each formation, in order (the thesis: its circle
  /// point, the diametrically opposite one, its circle point again).
  std::vector<Eigen::Vector2d> goals_m;
  int num_robots = 10;         ///< robots taking part (size of the progress vector); >= 1
  double tolerance_m = 0.05;   ///< a point counts as reached within this distance (the thesis's 0.05); > 0
  double max_speed_mps = 0.2;  ///< preferred speed towards the point (the thesis's v_max); (0, 0.2]
  /// Preferred speed = min(max_speed_mps, gain * distance to the point), 1/s; > 0.
  /// The thesis drove at max_speed_mps until within tolerance_m, which any
  /// gain >= max_speed_mps / tolerance_m (4/s) reproduces exactly. A robot
  /// that stops only when it measures itself inside the tolerance overshoots
  /// by its speed times the loop delay T (pose to motion); slowing in
  /// proportion to the distance does not overshoot while gain * T <= 1/e
  /// (x' = -gain x(t - T) has no oscillating solution then). The default
  /// is 1/(e T) for the lab's T ~ 0.45 s (docs/experiments.md#robustness-ideal-vs-lab).
  double gain = 0.8;
  /// Counted reached within tolerance_m, a robot drives on until within
  /// stop_m and holds there until pushed out of tolerance_m: it settles
  /// tolerance_m - stop_m inside the line the goal is judged by, not on it,
  /// so noise, a stale pose or HRVO's nudge does not take it out while it
  /// reports done. (0, tolerance_m]; = tolerance_m is the thesis's hold.
  double stop_m = 0.025;

  /// The config keys (`controller:` of kind hrvo_circle), once for reading, checking and the docs.
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("tolerance_m", tolerance_m, agents::FieldRule::Positive(),
                  "a point counts as reached within this distance (also the metrics' test), m");
    fields.Number("max_speed_mps", max_speed_mps, agents::FieldRule::RobotSpeed(),
                  "preferred speed towards the point (the thesis's `v_max`), m/s");
    fields.Number("gain", gain, agents::FieldRule::Positive(),
                  "preferred speed = min(`max_speed_mps`, `gain` x distance to the point), 1/s. 0.8 = 1/(e T) for the "
                  "lab's loop delay T ~ 0.45 s (pose to motion): no overshoot while `gain` T <= 1/e. >= "
                  "`max_speed_mps` / `tolerance_m` drives at full speed up to the tolerance (the thesis)");
    fields.Number("stop_m", stop_m, agents::FieldRule::Finite(),
                  "a robot that reached its point (within `tolerance_m`) drives on until within `stop_m`, then holds "
                  "until pushed out of `tolerance_m`; done only from `stop_m` on, so it settles inside the line the "
                  "goal is judged by, m, > 0 and <= `tolerance_m`");
  }
  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

/// The thesis's Robot_c (Appendix B): drive to the current formation point
/// through HRVO (slowing down before it: gain, stop_m), count it reached
/// within tolerance, and move on to the next point only once the radio has
/// brought news (possibly over several hops) that every robot has reached
/// the current one.
///
/// Radio: merges every neighbour's FormationProgress (malformed payloads are
/// counted and dropped), records its own state, and rebroadcasts the whole
/// vector. One deliberate change: the thesis advanced when every known state
/// *equalled* its own, which deadlocks if a faster robot has already reached
/// the next point; here every known state must be *at least* its own.
/// Done while it holds its last point: reached, came within stop_m, and not
/// out of tolerance_m by any update since. HRVO may make a robot that has
/// arrived step aside for a passing one; it then drives back and is not done
/// meanwhile, so a run that stops when every robot is done stops with the
/// whole formation in place (the thesis's Robot_c stayed done once it had
/// arrived). Done only from stop_m, not from the tolerance_m line itself: a
/// last robot creeping over that line would report done by a pose that is
/// off by noise or age, and the run could stop with it just outside.
class CircleFormationRobot final : public agents::HrvoRobot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  CircleFormationRobot(int id, const agents::RobotParams& robot_params, const agents::HrvoRobotParams& hrvo_params,
                       const CircleFormationParams& params);

  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<agents::RadioMessage>& heard) override;
  agents::UnicycleCommand Update(int64_t step) override;
  bool done() const override { return reached_ == static_cast<int>(params_.goals_m.size()) && holding_; }

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
  bool holding_ = false;  ///< came within stop_m and has not left tolerance_m since
};

}  // namespace dream::hrvo_circle
