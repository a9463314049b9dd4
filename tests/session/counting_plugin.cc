// A controller plugin for run_session_test: kind `session_test_drive`, every
// robot driving straight ahead at speed_mps (0: holding still), whose builder
// counts how often it is built, that is how many ControllerFactory objects
// were made for a config naming it (session_test_factories_built()), and how
// many robots it made, that is how many agents were started
// (session_test_robots_made()).
#include <memory>
#include <vector>

#include "dream/agent_host/controller_plugin.h"

namespace {

int factories_built = 0;
int robots_made = 0;

class DriveRobot final : public dream::agents::Robot {
 public:
  DriveRobot(int id, const dream::agents::RobotParams& params, double speed_mps)
      : Robot(id, params), speed_mps_(speed_mps) {}
  dream::agents::UnicycleCommand Update(int64_t) override { return {speed_mps_, 0.0}; }

 private:
  double speed_mps_;
};

class DriveBuilder final : public dream::kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "session_test_drive";
  static std::vector<const char*> Keys() { return {"speed_mps"}; }
  DriveBuilder(const dream::config::ConfigNode& section, int) : speed_mps_(section.GetDouble("speed_mps", 0.0)) {
    ++factories_built;
  }
  std::unique_ptr<dream::agents::Robot> MakeRobot(int id, const dream::agents::RobotParams& params) const override {
    ++robots_made;
    return std::make_unique<DriveRobot>(id, params, speed_mps_);
  }

 private:
  double speed_mps_;
};

}  // namespace

DREAM_PLUGIN_EXPORT int session_test_factories_built() { return factories_built; }
DREAM_PLUGIN_EXPORT int session_test_robots_made() { return robots_made; }

DREAM_REGISTER_CONTROLLER(DriveBuilder)
