#pragma once

#include <cstdint>
#include <vector>

namespace dream::world {

// What UnicycleWorld::Step found at one step, so a caller can log warnings.
// Everything here refers to the poses and velocities validated at the start
// of that step (the poses of step index `step`, before they were advanced).
struct StepEvents {
  struct RobotPair {
    int first_robot_id = 0;   // the smaller id
    int second_robot_id = 0;  // the larger id
    friend bool operator==(const RobotPair& a, const RobotPair& b) {
      return a.first_robot_id == b.first_robot_id && a.second_robot_id == b.second_robot_id;
    }
  };
  struct RobotObstacleContact {
    int robot_id = 0;
    int obstacle_id = 0;  // RectangleObstacleSpec::id
  };

  // Index of the validated step (poses at time step * dt); -1 before any step.
  int64_t step = -1;
  // Robots stopped at this step because their last command was too old.
  std::vector<int> timed_out_robot_ids;
  // Robots strictly outside the arena (ascending).
  std::vector<int> out_of_bounds_robot_ids;
  // Colliding pairs, sorted by (first, second).
  std::vector<RobotPair> colliding_pairs;
  // Robots whose velocity exceeded the wheel-speed limit and was saturated.
  std::vector<int> actuator_limited_robot_ids;
  // Robot-obstacle overlaps, sorted by robot id then obstacle order.
  std::vector<RobotObstacleContact> obstacle_contacts;

  // Clears the lists but keeps their capacity (no allocation per step).
  void Reset(int64_t step_index) {
    step = step_index;
    timed_out_robot_ids.clear();
    out_of_bounds_robot_ids.clear();
    colliding_pairs.clear();
    actuator_limited_robot_ids.clear();
    obstacle_contacts.clear();
  }
};

}  // namespace dream::world
