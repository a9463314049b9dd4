#include "dream/workflows/sweep_plan.h"

#include <filesystem>
#include <set>
#include <stdexcept>

#include "dream/config_overrides/config_override.h"
#include "dream/workflows/seed_list.h"

namespace dream::workflows {
namespace {

// Letters, digits, _ - . stay (all the config's `name` allows); each run of
// other characters becomes one '-', none at the ends: "[0.1, 0.2]" -> "0.1-0.2".
std::string FolderSafe(const std::string& text, size_t max_chars) {
  std::string safe;
  bool pending_dash = false;
  for (char c : text) {
    const bool keep =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
    if (!keep) {
      pending_dash = !safe.empty();
      continue;
    }
    if (pending_dash) safe += '-';
    pending_dash = false;
    safe += c;
    if (safe.size() >= max_chars) break;
  }
  return safe.empty() ? "x" : safe;
}

std::string EscapedForSingleQuotes(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '\'' ? std::string("''") : std::string(1, c);
  return escaped;
}

std::string ZeroPadded(uint64_t value, size_t width) {
  std::string text = std::to_string(value);
  return std::string(width > text.size() ? width - text.size() : 0, '0') + text;
}

}  // namespace

std::string SweepPlan::Run::Label() const {
  std::string label = "seed " + std::to_string(seed);
  for (const auto& [key, value] : parameters) {
    config_overrides::SweepParameter parameter{key, {}};
    label += ", " + parameter.ShortName() + "=" + value;
  }
  return label;
}

SweepPlan::SweepPlan(const std::vector<uint64_t>& seeds,
                     const std::vector<config_overrides::SweepParameter>& parameters,
                     const std::vector<config_overrides::SweepParameter>& zipped) {
  if (seeds.empty()) throw std::invalid_argument("--seeds: no seeds to run");
  // Each --set is a dimension of its own; the --zip keys are one dimension
  // together, their i-th values in the same run.
  std::vector<std::vector<Run::Values>> dimensions;
  for (const config_overrides::SweepParameter& parameter : parameters) {
    AddKey(parameter, "--set");
    std::vector<Run::Values> choices;
    for (const std::string& value : parameter.values) choices.push_back({{parameter.key, value}});
    dimensions.push_back(std::move(choices));
  }
  if (!zipped.empty()) {
    std::vector<Run::Values> choices(zipped.front().values.size());
    for (const config_overrides::SweepParameter& parameter : zipped) {
      AddKey(parameter, "--zip");
      if (parameter.values.size() != choices.size()) {
        throw std::invalid_argument("--zip " + parameter.key + " has " + std::to_string(parameter.values.size()) +
                                    " values and --zip " + zipped.front().key + " " + std::to_string(choices.size()) +
                                    "; keys zipped together need as many values each");
      }
      for (size_t i = 0; i < choices.size(); ++i) choices[i].emplace_back(parameter.key, parameter.values[i]);
    }
    dimensions.push_back(std::move(choices));
  }
  size_t combinations = 1;
  for (const std::vector<Run::Values>& choices : dimensions) {
    combinations *= choices.size();
    if (combinations * seeds.size() > kMaxSweepRuns) {
      throw std::invalid_argument("the sweep would have more than " + std::to_string(kMaxSweepRuns) + " runs");
    }
  }
  uint64_t largest_seed = 0;
  for (uint64_t seed : seeds) largest_seed = std::max(largest_seed, seed);
  const size_t seed_width = std::to_string(largest_seed).size();

  // Dimensions outer (the first --set slowest), seeds inner: the table lists
  // every seed of one combination together.
  std::set<std::string> names;
  for (size_t combination = 0; combination < combinations; ++combination) {
    Run::Values values;
    size_t rest = combination;
    for (size_t d = dimensions.size(); d-- > 0;) {
      const Run::Values& choice = dimensions[d][rest % dimensions[d].size()];
      values.insert(values.begin(), choice.begin(), choice.end());
      rest /= dimensions[d].size();
    }
    for (uint64_t seed : seeds) AddRun(seed, seed_width, values, &names);
  }
}

void SweepPlan::AddKey(const config_overrides::SweepParameter& parameter, const std::string& option) {
  for (const std::string& key : keys_) {
    if (key == parameter.key) {
      throw std::invalid_argument(option + " " + key +
                                  ": the key is swept already; give each key once, with all its "
                                  "values (in one --set, or in one --zip to vary it with other keys)");
    }
  }
  if (parameter.values.empty()) throw std::invalid_argument(option + " " + parameter.key + ": no values");
  keys_.push_back(parameter.key);
}

void SweepPlan::AddRun(uint64_t seed, size_t seed_width, const Run::Values& values, std::set<std::string>* names) {
  Run run;
  run.index = runs_.size();
  run.seed = seed;
  run.parameters = values;
  run.name = "seed" + ZeroPadded(seed, seed_width);
  for (const auto& [key, value] : values) {
    config_overrides::SweepParameter parameter{key, {}};
    run.name += "_" + FolderSafe(parameter.ShortName(), 40) + "-" + FolderSafe(value, 40);
  }
  // Values that differ only in characters made safe would share a folder.
  if (!names->insert(run.name).second) {
    run.name += "_" + std::to_string(run.index);
    names->insert(run.name);
  }
  runs_.push_back(std::move(run));
}

SweepPlan SweepPlan::FromRuns(std::vector<std::string> parameter_keys, std::vector<Run> runs) {
  SweepPlan plan;
  plan.runs_ = std::move(runs);
  plan.keys_ = std::move(parameter_keys);
  const std::vector<Run>& runs_ = plan.runs_;
  const std::vector<std::string>& keys_ = plan.keys_;
  for (size_t i = 0; i < runs_.size(); ++i) {
    if (runs_[i].index != i)
      throw std::invalid_argument("run " + runs_[i].name + " is not number " + std::to_string(i));
    if (runs_[i].parameters.size() != keys_.size()) {
      throw std::invalid_argument("run " + runs_[i].name + " has " + std::to_string(runs_[i].parameters.size()) +
                                  " values for " + std::to_string(keys_.size()) + " keys");
    }
  }
  return plan;
}

YAML::Node SweepPlan::ParseBase(const std::string& base_text, const std::string& source_name) {
  YAML::Node root;
  try {
    root = YAML::Load(base_text);
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument(source_name + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
  }
  if (!root.IsMap()) throw std::invalid_argument(source_name + ": the config must be a YAML mapping of keys");
  return root;
}

YAML::Node SweepPlan::MakeRunConfig(const std::string& base_text, const std::string& source_name, const Run& run) {
  YAML::Node root = ParseBase(base_text, source_name);
  ApplyRun(root, source_name, run);
  return root;
}

YAML::Node SweepPlan::MakeRunConfig(const YAML::Node& parsed_base, const std::string& source_name, const Run& run) {
  YAML::Node root = YAML::Clone(parsed_base);
  ApplyRun(root, source_name, run);
  return root;
}

void SweepPlan::ApplyRun(YAML::Node& root, const std::string& source_name, const Run& run) {
  config_overrides::ApplyConfigOverride(root, "seed", std::to_string(run.seed), source_name);
  for (const auto& [key, value] : run.parameters) config_overrides::ApplyConfigOverride(root, key, value, source_name);
  const YAML::Node& read_only = root;
  // The run's config lives in another folder: relative plugin paths must keep
  // starting from the base config's (see `plugin_dir:` in config/README.md).
  if (read_only["plugins"].IsDefined() && !read_only["plugin_dir"].IsDefined()) {
    const std::string base_dir = std::filesystem::absolute(source_name).parent_path().lexically_normal().string();
    config_overrides::ApplyConfigOverride(root, "plugin_dir", "'" + EscapedForSingleQuotes(base_dir) + "'",
                                          source_name);
  }
  // So must a relative realism file of the base config (one given with
  // --set is absolute by now).
  const YAML::Node world = read_only["world"];  // a missing key's node may only be asked IsDefined()
  const YAML::Node realism = world.IsDefined() && world.IsMap() ? world["realism"] : YAML::Node();
  const YAML::Node realism_file = realism.IsDefined() && realism.IsMap() ? realism["file"] : YAML::Node();
  if (realism_file.IsDefined() && realism_file.IsScalar() &&
      std::filesystem::path(realism_file.Scalar()).is_relative()) {
    const std::filesystem::path base_dir = std::filesystem::absolute(source_name).parent_path();
    root["world"]["realism"]["file"] = (base_dir / realism_file.Scalar()).lexically_normal().string();
  }
  if (read_only["name"].IsScalar()) {
    config_overrides::ApplyConfigOverride(root, "name", read_only["name"].Scalar() + "_" + run.name, source_name);
  }
}

}  // namespace dream::workflows
