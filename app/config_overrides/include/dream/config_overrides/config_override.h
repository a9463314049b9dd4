#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

namespace dream::config_overrides {

/// Sets one key of a loaded run config to a new value, for `dream sweep --set`.
///
/// `dotted_key` walks the YAML: map keys by name, list items by index
/// (controller.sensors.0.noise_std). Every part but the last must exist or be a
/// section of the run config schema (world, world.realism, controller,
/// initial_poses, initial_poses.generate), which is then created; the
/// last may name a key the config leaves out (it takes its default), which is
/// then added -- a misspelt one is caught by the config check, which refuses
/// unknown keys everywhere. A missing part that is no such section is an error
/// with a did-you-mean. `value_text` is parsed as YAML ("0.1", "thesis",
/// "[0.5, 0]").
///
/// `world.realism.file`'s value, a path, is taken from the current folder
/// (made absolute here), as every command-line path is.
///
/// A value replaces the node in place, so a ConfigError about it still points
/// at the key's line in `source_name`.
/// @throws std::invalid_argument naming the key, the missing part and the keys
///         that are there.
/// The value is checked as a config file is (ConfigNode::ParseYaml: aliases,
/// duplicate keys, a second document; at most ConfigNode::kMaxFileBytes), and
/// the config with it in place must keep a file's limits (kMaxDepth levels,
/// kMaxValues values once aliases are expanded). Being copied, a value may
/// expand to at most kMaxSetValues values.
inline constexpr size_t kMaxSetValues = 100000;
void ApplyConfigOverride(YAML::Node root, const std::string& dotted_key, const std::string& value_text,
                         const std::string& source_name);

}  // namespace dream::config_overrides
