#pragma once

#include <cstdint>

#include "dream/world/step_events.h"

namespace dream::world {

// Cumulative rule violations of a run, counted the way the Robotarium V2
// simulator counts them (see UnicycleWorld::Step).
struct ViolationCounts {
  // Steps at which at least one robot was strictly outside the arena.
  int64_t boundary_errors = 0;
  // Sum over steps of the number of colliding robot pairs.
  int64_t collision_errors = 0;
  // Steps at which at least one commanded wheel speed exceeded the limit.
  int64_t actuator_errors = 0;
  // Sum over steps of the number of (robot, virtual obstacle) overlaps. Not a
  // Robotarium rule (it has no virtual obstacles); we treat it as a hard error.
  int64_t obstacle_collisions = 0;

  // Errors that make the Robotarium reject a run (plus obstacle overlaps).
  int64_t hard_errors() const { return boundary_errors + collision_errors + obstacle_collisions; }

  // Counts one step's events: a step with robots outside the arena (or over
  // the wheel-speed limit) is one error, every colliding pair and every
  // robot-obstacle overlap one each.
  void Add(const StepEvents& events) {
    if (!events.out_of_bounds_robot_ids.empty()) ++boundary_errors;
    collision_errors += static_cast<int64_t>(events.colliding_pairs.size());
    if (!events.actuator_limited_robot_ids.empty()) ++actuator_errors;
    obstacle_collisions += static_cast<int64_t>(events.obstacle_contacts.size());
  }

  // Adds `other`'s counts (a sweep's totals over its runs).
  ViolationCounts& operator+=(const ViolationCounts& other) {
    boundary_errors += other.boundary_errors;
    collision_errors += other.collision_errors;
    actuator_errors += other.actuator_errors;
    obstacle_collisions += other.obstacle_collisions;
    return *this;
  }

  friend bool operator==(const ViolationCounts& a, const ViolationCounts& b) {
    return a.boundary_errors == b.boundary_errors && a.collision_errors == b.collision_errors &&
           a.actuator_errors == b.actuator_errors && a.obstacle_collisions == b.obstacle_collisions;
  }
  friend bool operator!=(const ViolationCounts& a, const ViolationCounts& b) { return !(a == b); }
};

}  // namespace dream::world
