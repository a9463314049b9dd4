#pragma once

#include <cstdint>

namespace dream::robotarium {

// Physical constants of the Georgia Tech Robotarium, as the V2.0.0 Python
// simulator (rps/robotarium_abc.py) defines them. Derived values use the same
// expressions as the official simulator so they round to the same doubles.
// The one home of these numbers: the world checks runs against them and the
// agents' defaults (limits, arena, time step) are taken from them.
struct RobotariumConstants {
  static constexpr double kTimeStepSeconds = 0.033;

  static constexpr double kArenaXMinMeters = -1.6;
  static constexpr double kArenaXMaxMeters = 1.6;
  static constexpr double kArenaYMinMeters = -1.0;
  static constexpr double kArenaYMaxMeters = 1.0;

  static constexpr double kRobotDiameterMeters = 0.11;
  static constexpr double kWheelRadiusMeters = 0.016;
  // Distance between the wheels (older releases used 0.105).
  static constexpr double kBaseLengthMeters = 0.11;

  static constexpr double kMaxLinearVelocityMps = 0.2;
  static constexpr double kMaxWheelVelocityRadps = kMaxLinearVelocityMps / kWheelRadiusMeters;
  // The official simulator uses the robot diameter here, not the base length.
  static constexpr double kMaxAngularVelocityRadps =
      2.0 * (kWheelRadiusMeters / kRobotDiameterMeters) * (kMaxLinearVelocityMps / kWheelRadiusMeters);

  // Two robots collide when their centres, each moved kCollisionOffsetMeters
  // forward along its heading, are at most kCollisionDiameterMeters apart.
  static constexpr double kCollisionDiameterMeters = 0.135;
  static constexpr double kCollisionOffsetMeters = 0.025;

  // On hardware a robot stops when it has had no command for this long.
  static constexpr double kCommandTimeoutSeconds = 0.5;

  static constexpr int kMaxRobotsInSimulation = 50;
  static constexpr int kMaxRobotsOnHardware = 20;
  // The lab's cap on one experiment (15 minutes).
  static constexpr double kMaxExperimentSeconds = 900.0;
};

}  // namespace dream::robotarium
