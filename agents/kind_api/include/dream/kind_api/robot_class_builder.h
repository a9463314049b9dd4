#pragma once

#include <memory>
#include <type_traits>

#include "dream/kind_api/experiment_builder.h"
#include "dream/agents/framework/robot.h"
#include "dream/config/config_node.h"

namespace dream::kind_api {

/// The ExperimentBuilder of a kind that is nothing but a Robot subclass
/// (ControllerKind::OfRobot, DREAM_REGISTER_ROBOT): each robot is
/// `RobotClass(id, params, section)`, or `RobotClass(id, params)` when the
/// class reads no keys, and the kind has no metrics of its own (the factory
/// still adds SafetyMetrics).
///
/// The robot's constructor reads and checks its own keys of the
/// `controller:` section (ConfigNode errors name file, line and key). This
/// builder constructs one robot per id, with default RobotParams, as soon as
/// the config is read, so a bad value stops the tool before any agent runs;
/// keep the constructor free of side effects.
template <typename RobotClass>
class RobotClassBuilder final : public ExperimentBuilder {
 public:
  static_assert(std::is_base_of_v<agents::Robot, RobotClass>,
                "a controller kind's robot class derives from dream::agents::Robot");
  /// The constructor that also gets the `controller:` section.
  static constexpr bool kReadsSection =
      std::is_constructible_v<RobotClass, int, const agents::RobotParams&, const config::ConfigNode&>;
  static_assert(
      kReadsSection || std::is_constructible_v<RobotClass, int, const agents::RobotParams&>,
      "a controller kind's robot class needs a public constructor (int id, const agents::RobotParams& params, "
      "const dream::config::ConfigNode& section), or (int id, const agents::RobotParams& params) when it reads no "
      "keys");

  /// @throws config::ConfigError from the robots' constructors.
  RobotClassBuilder(const config::ConfigNode& section, int num_robots) : section_(section) {
    for (int id = 0; id < num_robots; ++id) MakeRobot(id, agents::RobotParams());
  }

  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override {
    if constexpr (kReadsSection) {
      return std::make_unique<RobotClass>(robot_id, params, section_);
    } else {
      return std::make_unique<RobotClass>(robot_id, params);
    }
  }

 private:
  config::ConfigNode section_;
};

}  // namespace dream::kind_api
