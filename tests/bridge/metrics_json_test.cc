// MetricsJson asks the run's kind for the metrics it computes itself
// (ControllerKind::own_metrics) and never names a kind: a built-in kind given
// the hook here has it merged by the rules summary.json's readers rely on.
#include "dream/bridge/metrics_json.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "bridge_test_support.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/run_log/run_log.h"

namespace dream::bridge {
namespace {

class MetricsJsonTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    run_dir_ = new std::string(testing::MakeRunFolder("metrics_json_run", testing::ShippedConfig("go_to_goal")));
  }
  static void TearDownTestSuite() {
    delete run_dir_;
    run_dir_ = nullptr;
  }

  // The built-in kinds, go_to_goal given `own_metrics`.
  static std::shared_ptr<const agent_host::ControllerRegistry> KindsWithHook(
      std::function<nlohmann::json(const config::ControllerConfig&, const kind_api::RunPoses&, const std::string&)>
          own_metrics) {
    auto registry = std::make_shared<agent_host::ControllerRegistry>();
    const agent_host::ControllerRegistry& built_ins = agent_host::ControllerRegistry::BuiltIns();
    for (const std::string& name : built_ins.Names()) {
      kind_api::ControllerKind kind = *built_ins.Find(name);
      if (name == "go_to_goal") kind.own_metrics = own_metrics;
      registry->Add(kind, "test");
    }
    return registry;
  }

  nlohmann::ordered_json Metrics(
      std::function<nlohmann::json(const config::ControllerConfig&, const kind_api::RunPoses&, const std::string&)>
          own_metrics,
      const std::string& runtime_dir = "/runtime") {
    const agent_host::ControllerFactory factory(config_, KindsWithHook(std::move(own_metrics)));
    return MetricsJson(config_, factory, log_, runtime_dir);
  }

  static std::string* run_dir_;
  const run_config::RunConfig config_ =
      testing::LoadConfigText(testing::ReadText(*run_dir_ + "/config.yaml"), *run_dir_ + "/config.yaml");
  const run_log::RunLog log_ = run_log::RunLog::Read(*run_dir_ + "/run.lcmlog");
  const nlohmann::ordered_json plain_ = MetricsJson(agent_host::ControllerFactory(config_), log_);
};

std::string* MetricsJsonTest::run_dir_ = nullptr;

TEST_F(MetricsJsonTest, TheHookGetsTheLogsPosesAndTheRuntimeAndItsDocumentIsMerged) {
  ASSERT_FALSE(plain_.contains("error")) << plain_.dump();
  ASSERT_TRUE(plain_.contains("goal"));
  std::string figure;  // one of the kind's own figures, which the hook's may not replace
  for (const auto& [name, value] : plain_.items()) {
    if (value.is_number() && figure.empty()) figure = name;
  }
  ASSERT_FALSE(figure.empty()) << plain_.dump();
  kind_api::RunPoses seen;
  std::string seen_runtime;
  const nlohmann::ordered_json merged = Metrics(
      [&](const config::ControllerConfig& config, const kind_api::RunPoses& poses, const std::string& runtime_dir) {
        EXPECT_EQ(config.num_robots, config_.num_robots);
        seen = poses;
        seen_runtime = runtime_dir;
        return nlohmann::json{{"metrics", {{figure, -12345.0}, {"hooked_figure", 1.5}}},
                              {"goal", {{"met", false}, {"completion_step", -1}, {"detail", "hooked"}}},
                              {"goal_points", {{{0.1, 0.2}}}}};
      });
  EXPECT_EQ(seen_runtime, "/runtime");
  ASSERT_EQ(seen.steps.size(), log_.poses().size());
  const robot_poses_t& last = log_.poses().back();
  EXPECT_EQ(seen.steps.back().step, last.step);
  ASSERT_EQ(seen.steps.back().poses.size(), static_cast<size_t>(last.num_robots));
  EXPECT_EQ(seen.steps.back().poses[1].x(), last.x[1]);
  EXPECT_EQ(seen.steps.back().poses[1].z(), last.theta[1]);
  EXPECT_EQ(merged[figure], plain_[figure]);  // never replaced
  EXPECT_EQ(merged["hooked_figure"], 1.5);
  EXPECT_EQ(merged["goal"]["detail"], "hooked");
  EXPECT_EQ(merged["goal_points"], nlohmann::ordered_json::parse("[[[0.1, 0.2]]]"));
  EXPECT_FALSE(merged.contains("error"));
}

TEST_F(MetricsJsonTest, NoGoalNoPointsAndNoRuntimeLeaveTheKindsOwn) {
  const nlohmann::ordered_json nothing =
      Metrics([](const config::ControllerConfig&, const kind_api::RunPoses&, const std::string&) {
        return nlohmann::json{
            {"metrics", nlohmann::json::object()}, {"goal", nullptr}, {"goal_points", nlohmann::json::array()}};
      });
  EXPECT_EQ(nothing, plain_);
  bool called = false;
  const nlohmann::ordered_json without_runtime = Metrics(
      [&](const config::ControllerConfig&, const kind_api::RunPoses&, const std::string&) {
        called = true;
        return nlohmann::json{{"metrics", {{"hooked_figure", 1.5}}}};
      },
      "");
  EXPECT_FALSE(called);
  EXPECT_EQ(without_runtime, plain_);
}

TEST_F(MetricsJsonTest, AHookThatFailsGivesTheError) {
  const nlohmann::ordered_json failed =
      Metrics([](const config::ControllerConfig&, const kind_api::RunPoses&, const std::string&) -> nlohmann::json {
        throw std::runtime_error("the controller's metrics: pair.py:3: no figures today");
      });
  EXPECT_EQ(failed["error"], "the controller's metrics: pair.py:3: no figures today");
}

}  // namespace
}  // namespace dream::bridge
