// Config fuzzing (issue 10 item 7): the shipped run configs, mutated as text
// (hostile values and numbers, broken lines and indentation, duplicate keys,
// document markers, aliases, deep nesting, stray bytes, truncation), loaded as
// `dream run` loads them, then built into agents. Each mutated file must load,
// or fail with a ConfigError naming the file; any other exception (yaml-cpp's,
// bad_alloc, out_of_range) or a crash is a failure. Under the sanitizer build
// (CMakePresets.json `asan`) undefined behaviour such as a huge double
// converted to an int fails too. Deterministic: a failure names its case, and
// the same seed gives the same text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dream/agent_host/controller_factory.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "fuzz_scale.h"
#include "yaml_text_mutator.h"
#include "../support/source_tree.h"

namespace dream::testing {
namespace {

constexpr uint32_t kSeed = 20261124;
constexpr int kMutationsPerConfig = 700;  // x 6 configs, times DREAM_FUZZ_SCALE
const char* const kSourceName = "fuzz.yaml";

/// The shipped configs whose controllers are C++ (a Python one would start an
/// embedded interpreter per case), as text.
std::vector<std::pair<std::string, std::string>> SeedConfigs() {
  std::vector<std::pair<std::string, std::string>> seeds;
  for (const char* name : {"go_to_goal", "hrvo_circle", "line_deployment", "voronoi_coverage",
                           "voronoi_coverage_static", "affine_formation"}) {
    const std::string path = dream::testing::SourceDir() + "/config/" + name + ".yaml";
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in || text.str().empty()) throw std::runtime_error("cannot read " + path);
    seeds.emplace_back(name, text.str());
  }
  return seeds;
}

enum class Outcome { kLoaded, kBuilt, kRefused };

/// What `dream run` does with a config's text before the run starts: parse,
/// check, and build every robot's agent and the metrics.
Outcome LoadAndBuild(const std::string& text) {
  const run_config::RunConfig run = run_config::LoadRunConfig(config::ConfigNode::LoadString(text, kSourceName));
  // A mutation can name kind python (an interpreter per case) or a plugin
  // (a library to load); both are read by code of their own, tested elsewhere.
  if (!run.plugins.empty() || run.controller.GetString("kind", "") == "python") return Outcome::kLoaded;
  const agent_host::ControllerFactory factory(run);
  for (int robot = 0; robot < run.num_robots; ++robot) factory.Make(robot);
  factory.MakeMetrics();
  return Outcome::kBuilt;
}

/// LoadAndBuild, with every failure other than a ConfigError naming the file
/// recorded as a test failure.
Outcome LoadsOrNamesTheFile(const std::string& text, const std::string& what) {
  try {
    return LoadAndBuild(text);
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(kSourceName, 0), 0U)
        << what << ": the error does not start with the file: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": not a ConfigError but " << typeid(e).name() << ": " << e.what();
  } catch (...) {
    ADD_FAILURE() << what << ": threw something that is not an exception";
  }
  return Outcome::kRefused;
}

TEST(ConfigMutation, EveryShippedConfigLoadsAndBuildsUnmutated) {
  for (const auto& [name, text] : SeedConfigs()) {
    EXPECT_EQ(LoadsOrNamesTheFile(text, name), Outcome::kBuilt) << name;
  }
}

TEST(ConfigMutation, MutatedConfigsLoadOrFailNamingTheFile) {
  const long mutations = kMutationsPerConfig * FuzzScale();
  YamlTextMutator mutator(kSeed);
  long built = 0;
  long loaded = 0;
  long refused = 0;
  for (const auto& [name, text] : SeedConfigs()) {
    for (long i = 0; i < mutations; ++i) {
      const std::string mutated = mutator.Mutate(text);
      switch (LoadsOrNamesTheFile(mutated, name + " mutation " + std::to_string(i))) {
        case Outcome::kBuilt:
          ++built;
          break;
        case Outcome::kLoaded:
          ++loaded;
          break;
        case Outcome::kRefused:
          ++refused;
          break;
      }
      if (HasFailure()) {
        // The first failing text, to replay by hand with `dream run`.
        const std::string keep = ::testing::TempDir() + "config_mutation_failure.yaml";
        std::ofstream(keep, std::ios::binary) << mutated;
        FAIL() << name << " mutation " << i << " failed; its text is in " << keep;
      }
    }
  }
  // Both ends are reached: most mutations are refused, some still build a run.
  EXPECT_GT(refused, built);
  EXPECT_GT(built, 0);
  RecordProperty("configs", std::to_string(built + loaded + refused));
  std::cout << "config mutations: " << built + loaded + refused << " (built " << built << ", loaded " << loaded
            << ", refused " << refused << ")\n";
}

// Nesting at and around both limits, ours (ConfigNode::kMaxDepth) and
// yaml-cpp's own recursion guard (2000), in flow and block style, at the top
// and inside the controller section: a ConfigError naming the file, never a
// stack overflow.
TEST(ConfigMutation, DeepNestingIsRefusedWithTheFile) {
  const std::string base = SeedConfigs().front().second;
  for (const int depth : {config::ConfigNode::kMaxDepth - 1, config::ConfigNode::kMaxDepth,
                          config::ConfigNode::kMaxDepth + 1, 1999, 2000, 2001, 100000}) {
    for (const bool flow : {true, false}) {
      if (!flow && depth > 3000) continue;  // block style costs depth^2 bytes of indentation
      const std::string nested = YamlTextMutator::Nested(depth, flow);
      const std::string what = std::to_string(depth) + (flow ? " flow" : " block");
      for (const std::string& text : {base + "deep:" + (flow ? " " : "") + nested + "\n",
                                      base + "  extra:" + (flow ? " " : "") + nested + "\n"}) {
        EXPECT_EQ(LoadsOrNamesTheFile(text, what), Outcome::kRefused) << what;
      }
      // The same nesting in a value nobody reads as a list is still refused past the limit.
      if (depth > config::ConfigNode::kMaxDepth) {
        try {
          config::ConfigNode::ParseYaml("description: " + nested + "\n", kSourceName);
          ADD_FAILURE() << what << ": nesting past the limit was parsed";
        } catch (const config::ConfigError& e) {
          EXPECT_EQ(std::string(e.what()).rfind(kSourceName, 0), 0U) << what << ": " << e.what();
        }
      }
    }
  }
}

}  // namespace
}  // namespace dream::testing
