#pragma once

#include "dream/agents/framework/world_snapshot.h"

namespace dream::agents {

class Robot;

/// An accessory that turns the world into a reading for its robot. Sensors
/// are the only part of an agent that sees the world; each has its own period
/// (run by the Timer) and its own seeded noise.
class Sensor {
 public:
  virtual ~Sensor() = default;
  /// Takes a reading of `world` for robot `robot.id()` and hands it over.
  virtual void Sense(const WorldSnapshot& world, Robot& robot) = 0;
};

}  // namespace dream::agents
