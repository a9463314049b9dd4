// Controller plugins for controller_plugin_test, one per TEST_PLUGIN_VARIANT:
//   good:     adds `test_still` (robots hold still)
//   twin:     adds `test_still` too, so it clashes with good
//   clash:    adds `test_first`, then the built-in `go_to_goal`: fails half way
//   old_api:  entry points of plugin API 0
//   no_entry: no entry points at all
//   foreign:  good, but with its own ControllerRegistry::BuiltIns(), as if it
//             linked another copy of the dream libraries
//   robot:    adds `test_parked`, a Robot subclass alone, with no keys
//             (DREAM_REGISTER_ROBOT)
#include <memory>
#include <optional>
#include <vector>

#include "dream/agent_host/controller_plugin.h"

namespace {

using dream::agents::ExperimentMetrics;
using dream::agents::MetricsReport;
using dream::agents::WorldSnapshot;

class StillRobot final : public dream::agents::Robot {
 public:
  using Robot::Robot;
  dream::agents::UnicycleCommand Update(int64_t) override { return {}; }
};

class NoMetrics final : public ExperimentMetrics {
 public:
  void Observe(const WorldSnapshot&) override {}
  void Write(MetricsReport* report) const override { report->values["still"] = 1.0; }
  // The kind's own success rule, as a built-in kind's: summary.json's metrics.goal.
  std::optional<dream::agents::GoalJudgement> JudgeGoal(const MetricsReport& report) const override {
    const auto still = report.values.find("still");
    dream::agents::GoalJudgement goal;
    goal.met = still != report.values.end() && still->second == 1.0;
    goal.detail = goal.met ? "held still" : "moved";
    return goal;
  }
};

class StillBuilder final : public dream::kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "test_still";
  static std::vector<const char*> Keys() { return {"patience_s"}; }
  StillBuilder(const dream::config::ConfigNode& section, int) { section.GetDouble("patience_s", 1.0); }
  std::unique_ptr<dream::agents::Robot> MakeRobot(int id, const dream::agents::RobotParams& params) const override {
    return std::make_unique<StillRobot>(id, params);
  }
  std::unique_ptr<ExperimentMetrics> MakeMetrics() const override { return std::make_unique<NoMetrics>(); }
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const override { return {{Eigen::Vector2d(0.25, -0.5)}}; }
};

[[maybe_unused]] dream::kind_api::ControllerKind Named(const char* name) {
  dream::kind_api::ControllerKind kind = dream::kind_api::ControllerKind::Of<StillBuilder>();
  kind.name = name;
  return kind;
}

}  // namespace

#if defined(TEST_PLUGIN_GOOD) || defined(TEST_PLUGIN_TWIN)
DREAM_REGISTER_CONTROLLER(StillBuilder)
#elif defined(TEST_PLUGIN_FOREIGN)
namespace dream::agent_host {
__attribute__((visibility("default"))) const ControllerRegistry& ControllerRegistry::BuiltIns() {
  static const ControllerRegistry registry;
  return registry;
}
}  // namespace dream::agent_host
DREAM_REGISTER_CONTROLLER(StillBuilder)
#elif defined(TEST_PLUGIN_ROBOT)
DREAM_REGISTER_ROBOT("test_parked", StillRobot, {})
#elif defined(TEST_PLUGIN_CLASH)
DREAM_CONTROLLER_PLUGIN(registry) {
  registry->Add(Named("test_first"));
  registry->Add(Named("go_to_goal"));
}
#elif defined(TEST_PLUGIN_OLD_API)
DREAM_PLUGIN_EXPORT int dream_plugin_api_version() { return 0; }
DREAM_PLUGIN_EXPORT void dream_register_controllers(dream::agent_host::ControllerRegistry* registry) {
  registry->Add(Named("test_old"));
}
#elif defined(TEST_PLUGIN_NO_ENTRY)
DREAM_PLUGIN_EXPORT int dream_something_else() { return Named("test_none").keys.size() > 0 ? 1 : 0; }
#else
#error "define one TEST_PLUGIN_<VARIANT>"
#endif
