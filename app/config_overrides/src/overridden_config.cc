#include "dream/config_overrides/overridden_config.h"

#include <stdexcept>

#include "dream/config_overrides/config_override.h"
#include "dream/config_overrides/config_text.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/config_overrides/sweep_parameter.h"

namespace dream::config_overrides {

OverriddenConfig::OverriddenConfig(const std::string& path, long long seed, const std::vector<std::string>& sets)
    : path_(path) {
  text_ = config::ConfigNode::ReadFile(path);
  if (seed < 0 && sets.empty()) return;  // Load() reads the file as it always has

  // The config's own parser: a duplicate key or a second document is refused
  // here as `dream run` without overrides refuses it.
  root_ = config::ConfigNode::ParseYaml(text_, path);
  if (!root_.IsMap()) throw config::ConfigError(path + ": the config must be a YAML mapping of keys");
  if (seed >= 0) {
    ApplyConfigOverride(root_, "seed", std::to_string(seed), path);
    overrides_.push_back("--seed " + std::to_string(seed));
  }
  for (const std::string& set : sets) {
    const SweepParameter parameter =
        SweepParameter::ParseAssignment(set, "KEY=VALUE such as controller.max_speed_mps=0.1");
    const std::string option = "--set " + set;
    if (parameter.values.size() != 1) {
      throw std::invalid_argument(option + ": one value per key here (" + std::to_string(parameter.values.size()) +
                                  " given); dream sweep runs a list of values");
    }
    if (parameter.key == "seed" && seed >= 0) {
      throw std::invalid_argument(option + ": --seed and --set seed=... both set the seed; give one");
    }
    // What the key is looked up in: the file as the overrides before this one left it.
    std::string document = path;
    for (size_t i = 0; i < overrides_.size(); ++i) document += (i == 0 ? " after " : ", ") + overrides_[i];
    ApplyConfigOverride(root_, parameter.key, parameter.values.front(), document);
    overrides_.push_back("--set " + parameter.key + "=" + parameter.values.front());
  }
}

config::ConfigNode OverriddenConfig::Document() const {
  if (overrides_.empty()) return config::ConfigNode::LoadFile(path_);
  return config::ConfigNode(root_, path_, "");
}

config::ControllerConfig OverriddenConfig::LoadController() const { return LoadWith(&config::LoadControllerConfig); }

std::string OverriddenConfig::Noted(const std::string& message) const {
  return overrides_.empty() ? message : message + " (with " + OptionsText() + ")";
}

std::string OverriddenConfig::OptionsText() const {
  std::string text;
  for (const std::string& option : overrides_) text += (text.empty() ? "" : " ") + option;
  return text;
}

std::string OverriddenConfig::Text() const {
  if (overrides_.empty()) return text_;
  return ConfigText(root_,
                    path_ + " with " + OptionsText() + " (the values below include them; comments were not kept).");
}

}  // namespace dream::config_overrides
