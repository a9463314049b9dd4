#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dream::hrvo_circle {

/// What one robot knows of everybody's progress through a sequence of
/// formations (the thesis's Robot_c.robot_states): per robot, the highest
/// number of formation points it is known to have reached. Robots rebroadcast
/// the whole vector, so news travels several hops, one per radio period.
///
/// Payload: int32 num_robots, then num_robots int32 states, each in
/// [0, num_formations]. Anything else is malformed and dropped whole.
class FormationProgress {
 public:
  /// @throws std::invalid_argument unless num_robots >= 1 and num_formations >= 1.
  FormationProgress(int num_robots, int num_formations);

  /// Takes the element-wise maximum with a neighbour's payload. Returns false,
  /// changing nothing, when the payload is malformed (wrong size, state out
  /// of range, trailing bytes).
  bool Merge(const std::vector<uint8_t>& payload);

  /// Sets what is known of `robot_id` (a robot knows its own state best).
  /// @throws std::out_of_range for a bad id or state.
  void Set(int robot_id, int state);

  /// The lowest known state: every robot has reached at least this many points.
  int MinState() const;
  int state(int robot_id) const { return states_.at(static_cast<size_t>(robot_id)); }
  const std::vector<int>& states() const { return states_; }

  std::vector<uint8_t> Encode() const;

 private:
  int num_formations_;
  std::vector<int> states_;
  std::vector<int> scratch_;
};

}  // namespace dream::hrvo_circle
