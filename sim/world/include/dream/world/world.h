#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "dream/world/obstacle_state.h"
#include "dream/world/pose2.h"
#include "dream/world/unicycle_command.h"
#include "dream/world/violation_counts.h"

namespace dream::world {

// What the sim node needs from a world: poses, velocities, obstacles and
// violation counts out; velocity commands in; one step at a time. The
// in-tree simulator (UnicycleWorld) and the bridge's replay of a lab run
// (bridge::LabReplayWorld) implement it, so agents on the bus cannot tell
// which one runs. Calls are per step, never per robot in a hot loop, so the
// virtual dispatch costs nothing measurable.
class World {
 public:
  virtual ~World() = default;

  virtual int num_robots() const = 0;
  // Steps taken so far; the poses are those of this step.
  virtual int64_t step() const = 0;
  // Time of the current step, microseconds since step 0: what the world
  // publishes as utime (simulated time, or the lab's clock for a replay).
  virtual int64_t utime() const = 0;
  virtual double time_step_s() const = 0;
  virtual const std::vector<Pose2>& poses() const = 0;
  // The velocities the robots drove with during the step that led here (the
  // held velocities after the last Step()).
  virtual const std::vector<UnicycleCommand>& velocities() const = 0;
  // Replaces *states with the obstacles at the current step (keeps capacity).
  virtual void GetObstacleStates(std::vector<ObstacleState>* states) const = 0;
  virtual const ViolationCounts& violations() const = 0;

  // The robot's command from now on. Throws std::out_of_range for a bad id,
  // std::invalid_argument if not finite.
  virtual void SetCommand(int robot_id, const UnicycleCommand& command) = 0;
  // The robot has no command (its agent is lost or silent). Throws
  // std::out_of_range for a bad id.
  virtual void StopRobot(int robot_id) = 0;
  virtual void Step() = 0;

  // How many steps this world can take in all: unbounded for the simulator,
  // the length of the recording for a replay.
  virtual int64_t last_step() const { return std::numeric_limits<int64_t>::max(); }

  double time_s() const { return static_cast<double>(step()) * time_step_s(); }

 protected:
  World() = default;
  World(const World&) = default;
  World(World&&) = default;
  World& operator=(const World&) = default;
  World& operator=(World&&) = default;
};

}  // namespace dream::world
