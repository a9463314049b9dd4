// Seeded fuzzing of the --set path (issue 23 item 1), in every CI build: lines
// of `--set KEY=VALUE` made from config/go_to_goal.yaml's own keys and values,
// the values mutated as YAML text (hostile scalars, aliases, nesting, stray
// bytes, as the config mutation test mutates whole files), plus attacks and
// keys that miss; each case through SetOverrideTarget, which applies them as
// `dream run` and `dream sweep` do and aborts on a finding (anything but a
// ConfigError naming the config or an invalid_argument naming the --set; an
// accepted config that does not reload or run). Deterministic: the case being
// run is kept in a file, so a crash leaves it to replay.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "../reliability/fuzz_scale.h"
#include "../reliability/yaml_text_mutator.h"
#include "fuzz_targets.h"
#include "../support/source_tree.h"

namespace dream::fuzz {
namespace {

constexpr uint32_t kSeed = 20261127;
constexpr long kCases = 1500;  // times DREAM_FUZZ_SCALE

// Every dotted key of `node` (map keys by name, list items by index) with the
// value there as one line of flow YAML.
void CollectKeys(const YAML::Node& node, const std::string& key,
                 std::vector<std::pair<std::string, std::string>>* out) {
  if (!key.empty()) {
    YAML::Emitter flow;
    flow.SetMapFormat(YAML::Flow);
    flow.SetSeqFormat(YAML::Flow);
    flow << node;
    out->emplace_back(key, flow.c_str());
  }
  const std::string prefix = key.empty() ? "" : key + ".";
  if (node.IsMap()) {
    for (const auto& entry : node) CollectKeys(entry.second, prefix + entry.first.Scalar(), out);
  } else if (node.IsSequence()) {
    for (size_t i = 0; i < node.size(); ++i) CollectKeys(node[i], prefix + std::to_string(i), out);
  }
}

// Values a config file may not hold, and some it may.
std::vector<std::string> AttackValues() {
  std::string laughs = "[&a0 [x,x,x,x,x,x,x,x,x,x]";
  for (int i = 1; i < 10; ++i) {
    laughs += ", &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) laughs += (k ? ",*a" : "*a") + std::to_string(i - 1);
    laughs += "]";
  }
  laughs += "]";
  return {"&a [*a]",
          "&m {k: *m}",
          laughs,
          std::string(150, '[') + std::string(150, ']'),
          std::string(99, '[') + std::string(99, ']'),
          "{a: 1, a: 2}",
          "{[1]: 2}",
          "1\n---\n2",
          "*undefined",
          "~",
          "!!binary aGk=",
          "1e400",
          "-1e400",
          ".nan",
          "9223372036854775808",
          "-2147483649",
          "0x7fffffff",
          "''",
          std::string(20000, '9'),
          "[" + std::string(3000, '1') + "]",
          "{kind: python, module: x.py}",
          "[[0, 0, 0]]"};
}

// Keys that are not in the config, or walk it wrongly.
std::vector<std::string> MissingKeys() {
  return {"controller.nope",
          "nope.deeper",
          "controller.goals.99",
          "controller.goals.x",
          "robots.0",
          "seed.x",
          "controller.goals.0.0.0",
          "initial_poses.generate",
          "world.realism.x",
          "controller.kind.x",
          "controller.goals.4294967296",
          "a.b.c.d.e.f.g.h.i.j.k"};
}

TEST(SetOverrideMutation, MutatedSetLinesApplyOrFailNamingTheOption) {
  const std::string config_path = dream::testing::SourceDir() + "/config/go_to_goal.yaml";
  std::vector<std::pair<std::string, std::string>> keys;
  CollectKeys(YAML::LoadFile(config_path), "", &keys);
  ASSERT_GT(keys.size(), 20u);
  const std::vector<std::string> attacks = AttackValues();
  const std::vector<std::string> missing = MissingKeys();
  testing::YamlTextMutator mutator(kSeed);
  std::mt19937 random(kSeed);
  auto below = [&](size_t n) { return static_cast<size_t>(random() % n); };
  const std::string keep = ::testing::TempDir() + "set_override_mutation_case.txt";
  std::cout << "each case is written to " << keep << " before it runs (a crash leaves it there)\n";
  const long cases = kCases * testing::FuzzScale();
  for (long i = 0; i < cases; ++i) {
    std::string lines;
    const size_t count = 1 + below(3);
    for (size_t n = 0; n < count; ++n) {
      const auto& [key, value] = keys[below(keys.size())];
      std::string line;
      switch (below(6)) {
        case 0:
          line = key + "=" + attacks[below(attacks.size())];
          break;
        case 1:
          line = missing[below(missing.size())] + "=" + value;
          break;
        case 2:
          line = key + "=" + keys[below(keys.size())].second;
          break;  // another key's value
        default:
          line = key + "=" + mutator.Mutate(value);
          break;
      }
      lines += (n == 0 ? "" : "\n") + line;
    }
    std::ofstream(keep, std::ios::binary | std::ios::trunc) << lines;
    SetOverrideTarget(reinterpret_cast<const uint8_t*>(lines.data()), lines.size());
  }
  RecordProperty("cases", std::to_string(cases));
}

}  // namespace
}  // namespace dream::fuzz
