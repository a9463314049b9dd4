#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "fuzz_targets.h"
#include "dream/config_overrides/overridden_config.h"
#include "dream/config_overrides/sweep_parameter.h"
#include "dream/workflows/sweep_plan.h"
#include "../support/source_tree.h"

namespace dream::fuzz {
namespace {

// The config the overrides edit: a shipped one, so most keys exist.
const std::string kBaseConfig = dream::testing::SourceDir() + "/config/go_to_goal.yaml";
// More would only repeat the same code on a longer input.
constexpr size_t kMaxSets = 8;
// A sweep of more runs than this is the same code again, slower.
constexpr size_t kMaxSweepRuns = 4;

// The lines of the input: one `--set` argument each.
std::vector<std::string> SetsOf(const uint8_t* data, size_t size) {
  std::vector<std::string> sets;
  std::string current;
  for (size_t i = 0; i < size && sets.size() < kMaxSets; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c != '\n') {
      current += c;
      continue;
    }
    sets.push_back(current);
    current.clear();
  }
  if (!current.empty() && sets.size() < kMaxSets) sets.push_back(current);
  return sets;
}

bool StartsWith(const std::string& text, const std::string& start) { return text.rfind(start, 0) == 0; }

// What `dream run --set ...` does: the overrides, the run config, and the
// run folder's config.yaml, which must load again (it alone reruns the run);
// then that text through the config target (agents built, 80 steps run).
void AsDreamRun(const std::vector<std::string>& sets) {
  std::string folder_text;
  try {
    const config_overrides::OverriddenConfig overridden(kBaseConfig, -1, sets);
    const run_config::RunConfig run = overridden.LoadWith(&run_config::LoadRunConfig);
    // dream run checks the controller's keys before it writes the folder
    // (session::RunSession::CheckAgents; for the C++ kinds, the factory's check).
    if (run.plugins.empty() && run.controller.GetString("kind", "") != "python") {
      try {
        const agent_host::ControllerFactory factory(run);
      } catch (const config::ConfigError& e) {
        throw config::ConfigError(overridden.Noted(e.what()));
      }
    }
    folder_text = run_config::RunFolderConfigText(run, overridden.Text());
  } catch (const config::ConfigError& e) {
    if (!StartsWith(e.what(), kBaseConfig)) Finding("a config error without its file: " + std::string(e.what()));
    return;
  } catch (const std::invalid_argument& e) {
    if (!StartsWith(e.what(), "--set ")) Finding("a --set error without its option: " + std::string(e.what()));
    return;
  } catch (const std::exception& e) {
    Finding("a --set refused by something else than a ConfigError or invalid_argument: " + std::string(e.what()));
  }
  try {
    (void)run_config::LoadRunConfig(config::ConfigNode::LoadString(folder_text, "config.yaml"));
  } catch (const std::exception& e) {
    Finding("the run folder's config.yaml of an accepted --set does not load: " + std::string(e.what()));
  }
  RunConfigTarget(reinterpret_cast<const uint8_t*>(folder_text.data()), folder_text.size());
}

// What `dream sweep --set ...` does with the same lines (each a list of values).
void AsDreamSweep(const std::vector<std::string>& sets) {
  try {
    std::vector<config_overrides::SweepParameter> parameters;
    size_t runs = 1;
    for (const std::string& set : sets) {
      parameters.push_back(config_overrides::SweepParameter::Parse(set));
      runs *= parameters.back().values.size();
      if (runs > kMaxSweepRuns) return;
    }
    const std::string base_text = config::ConfigNode::ReadFile(kBaseConfig);
    const workflows::SweepPlan plan({1}, parameters);
    for (const workflows::SweepPlan::Run& run : plan.runs()) {
      const YAML::Node root = workflows::SweepPlan::MakeRunConfig(base_text, kBaseConfig, run);
      (void)run_config::LoadRunConfig(config::ConfigNode(root, kBaseConfig, ""));
    }
  } catch (const config::ConfigError& e) {
    if (!StartsWith(e.what(), kBaseConfig))
      Finding("a sweep's config error without its file: " + std::string(e.what()));
  } catch (const std::invalid_argument& e) {
    if (!StartsWith(e.what(), "--set ")) Finding("a sweep's --set error without its option: " + std::string(e.what()));
  } catch (const std::exception& e) {
    Finding("a sweep's --set refused by something else than a ConfigError or invalid_argument: " +
            std::string(e.what()));
  }
}

}  // namespace

void SetOverrideTarget(const uint8_t* data, size_t size) {
  const std::vector<std::string> sets = SetsOf(data, size);
  AsDreamRun(sets);
  AsDreamSweep(sets);
}

}  // namespace dream::fuzz
