// Every key a built-in kind declares (ControllerKind::keys, which the factory
// lets through) is really read: set to a value no key takes, it makes the
// factory fail naming that key. A key declared but never read would be
// accepted and silently ignored, the worst answer to a researcher's config.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/factory_error.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "../support/source_tree.h"

namespace dream::agents {
namespace {

using ::testing::HasSubstr;

/// kind -> a shipped config of that kind (config/*.yaml).
std::map<std::string, std::string> ShippedConfigsByKind() {
  std::map<std::string, std::string> configs;
  for (const auto& entry : std::filesystem::directory_iterator(dream::testing::SourceDir() + "/config")) {
    if (entry.path().extension() != ".yaml") continue;
    const YAML::Node root = YAML::LoadFile(entry.path().string());
    if (!root["controller"] || !root["controller"]["kind"]) continue;
    configs.emplace(root["controller"]["kind"].as<std::string>(), entry.path().string());
  }
  return configs;
}

/// The error of `path` with controller.<key> set to `value` (by default a
/// string no key takes).
std::string ErrorWithBadValue(const std::string& path, const std::string& key,
                              const std::string& value = "no_such_value") {
  YAML::Node root = YAML::LoadFile(path);
  root["controller"][key] = value;
  std::ostringstream text;
  text << root;
  return testing::FactoryErrorOf(run_config::LoadRunConfig(config::ConfigNode::LoadString(text.str(), path)));
}

TEST(KindKeysTest, EveryDeclaredKeyOfEveryBuiltInKindIsRead) {
  const std::map<std::string, std::string> configs = ShippedConfigsByKind();
  int keys_checked = 0;
  for (const std::string& name : agent_host::ControllerRegistry::BuiltIns().Names()) {
    const kind_api::ControllerKind* kind = agent_host::ControllerRegistry::BuiltIns().Find(name);
    if (kind->checks_own_keys) continue;  // the python kind: the Python class declares and reads its keys
    SCOPED_TRACE(name);
    const auto config = configs.find(name);
    ASSERT_NE(config, configs.end()) << "no config/*.yaml of kind " << name;
    for (const std::string& key : kind->keys) {
      SCOPED_TRACE(key);
      EXPECT_THAT(ErrorWithBadValue(config->second, key), HasSubstr("controller." + key));
      ++keys_checked;
    }
  }
  EXPECT_GE(keys_checked, 30);  // the five built-in experiments' keys, not an empty registry
}

// A whole number past int's range is refused naming the key, never narrowed:
// 4294967336 would otherwise wrap to 40 sides, steps or rounds and pass.
TEST(KindKeysTest, WholeNumbersPastIntAreRefusedNotWrapped) {
  const std::map<std::string, std::string> configs = ShippedConfigsByKind();
  const std::vector<std::pair<std::string, std::string>> int_keys = {
      {"voronoi_coverage", "disc_sides"},
      {"voronoi_coverage", "done_after_still_steps"},
      {"voronoi_coverage", "radio_rounds_before_moving"},
      {"voronoi_coverage", "coverage_sample_steps"},
      {"voronoi_coverage", "still_window_steps"},
      {"line_deployment", "settle_updates"},
      {"hrvo_circle", "formations"},
  };
  for (const auto& [kind, key] : int_keys) {
    SCOPED_TRACE(kind + "." + key);
    ASSERT_NE(configs.find(kind), configs.end());
    const std::string error = ErrorWithBadValue(configs.at(kind), key, "4294967336");
    EXPECT_THAT(error, HasSubstr("controller." + key));
    EXPECT_THAT(error, HasSubstr("4294967336"));
  }
  // Nested ones: an obstacle id of the affine formation's gate metrics.
  ASSERT_NE(configs.find("affine_formation"), configs.end());
  YAML::Node root = YAML::LoadFile(configs.at("affine_formation"));
  root["controller"]["metrics"]["obstacle_pairs"] = YAML::Load("[[0, 4294967297]]");
  std::ostringstream text;
  text << root;
  EXPECT_THAT(testing::FactoryErrorOf(run_config::LoadRunConfig(config::ConfigNode::LoadString(text.str(), "a.yaml"))),
              HasSubstr("controller.metrics.obstacle_pairs[0][1]: must be <= 2147483647, got 4294967297"));
}

}  // namespace
}  // namespace dream::agents
