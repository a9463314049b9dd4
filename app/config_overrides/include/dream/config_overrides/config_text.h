#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace dream::config_overrides {

/// `config` as YAML text (two-space indent) below `header` as "# " comment
/// lines: a config with overrides or a sweep's run config, written so that it
/// alone reruns the run and says where it came from.
std::string ConfigText(const YAML::Node& config, const std::string& header);

/// `header` as ConfigText writes it above the config: each line as "# line".
std::string CommentLines(const std::string& header);

}  // namespace dream::config_overrides
