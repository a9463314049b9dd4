#include "dream/config_overrides/config_override.h"

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/config/name_suggestion.h"

namespace dream::config_overrides {
namespace {

std::vector<std::string> SplitKey(const std::string& dotted_key) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t dot = dotted_key.find('.', start);
    parts.push_back(dotted_key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

std::string KeysOf(const YAML::Node& map) {
  std::string keys;
  for (const auto& entry : map) keys += (keys.empty() ? "" : ", ") + entry.first.as<std::string>();
  return keys.empty() ? "none" : keys;
}

// The sections of a run config (LoadRunConfig) whose keys are all optional or
// checked there: a --set may create them when the config leaves them out
// (`--set world.realism=lab` on a config without `world:`, `--set
// barriers.kind=unicycle` on one without `barriers:`). Any other missing
// part is a typo until proven otherwise.
const std::vector<std::string>& CreatableSections() {
  static const std::vector<std::string> sections = {"world",         "world.realism",          "controller",
                                                    "initial_poses", "initial_poses.generate", "barriers"};
  return sections;
}

bool IsCreatableSection(const std::string& dotted_path) {
  for (const std::string& section : CreatableSections()) {
    if (section == dotted_path) return true;
  }
  return false;
}

// The names a missing part may have meant: the keys there and the sections
// that could be created there.
std::vector<std::string> NamesAt(const YAML::Node& map, const std::string& path) {
  std::vector<std::string> names;
  for (const auto& entry : map) names.push_back(entry.first.as<std::string>());
  const std::string prefix = path.empty() ? "" : path + ".";
  for (const std::string& section : CreatableSections()) {
    if (section.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = section.substr(prefix.size());
    if (rest.find('.') == std::string::npos) names.push_back(rest);
  }
  return names;
}

bool IsIndex(const std::string& part) {
  return !part.empty() && part.size() < 10 && part.find_first_not_of("0123456789") == std::string::npos;
}

// A copy of `value` made of new nodes: they carry no line of their own, so an
// error inside them names the key without pointing at an unrelated line.
YAML::Node FreshCopy(const YAML::Node& value) {
  switch (value.Type()) {
    case YAML::NodeType::Sequence: {
      YAML::Node copy(YAML::NodeType::Sequence);
      for (const YAML::Node& item : value) copy.push_back(FreshCopy(item));
      copy.SetStyle(YAML::EmitterStyle::Flow);
      return copy;
    }
    case YAML::NodeType::Map: {
      YAML::Node copy(YAML::NodeType::Map);
      for (const auto& entry : value) copy[entry.first.as<std::string>()] = FreshCopy(entry.second);
      copy.SetStyle(YAML::EmitterStyle::Flow);
      return copy;
    }
    case YAML::NodeType::Scalar:
      return YAML::Node(value.Scalar());
    default:
      return YAML::Node(YAML::NodeType::Null);
  }
}

// Replaces what `target` holds without rebinding it, so it keeps its place
// (and its line) in the document.
void AssignInPlace(YAML::Node target, const YAML::Node& value) {
  switch (value.Type()) {
    case YAML::NodeType::Scalar:
      target = value.Scalar();
      target.SetTag(value.Tag());  // quoted or not as --set wrote it, not as the file did
      return;
    case YAML::NodeType::Sequence:
      target = YAML::Null;
      for (const YAML::Node& item : value) target.push_back(FreshCopy(item));
      target.SetStyle(YAML::EmitterStyle::Flow);
      return;
    case YAML::NodeType::Map:
      target = YAML::Null;
      for (const auto& entry : value) target[entry.first.as<std::string>()] = FreshCopy(entry.second);
      target.SetStyle(YAML::EmitterStyle::Flow);
      return;
    default:
      target = YAML::Null;
  }
}

// The value of `--set <key>` (`option`) parsed into `value`, with the checks a
// config file gets and a bound on its copy; its extent.
config::ConfigNode::Extent ParseSetValue(const std::string& option, const std::string& value_text, YAML::Node* value) {
  using config::ConfigNode;
  if (value_text.size() > ConfigNode::kMaxFileBytes) {
    throw std::invalid_argument(option + ": the value is " + std::to_string(value_text.size()) + " bytes; at most " +
                                std::to_string(ConfigNode::kMaxFileBytes) + " (the limit of a config file)");
  }
  ConfigNode::Extent extent;
  try {
    YAML::Load(value_text);  // yaml-cpp's own message for text that is not YAML
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument(option + ": value '" + value_text + "' is not valid YAML: " + e.msg);
  }
  try {
    // The config file's checks: the value is copied below, and an alias to
    // itself (&a [*a]) or aliases nested ten by ten would be copied without end.
    *value = ConfigNode::ParseYaml(value_text, option);
    extent = ConfigNode::CheckTree(*value, option);
  } catch (const config::ConfigError& e) {
    throw std::invalid_argument(e.what());
  }

  // A file's aliases share their nodes; a --set value is copied node by node
  // (FreshCopy), so its expansion is held to what a command line can write out.
  if (extent.values > kMaxSetValues) {
    throw std::invalid_argument(option + ": the value holds " + std::to_string(extent.values) +
                                " values once its aliases are expanded; a --set value may hold at most " +
                                std::to_string(kMaxSetValues) +
                                " (it is copied into the config; put a larger "
                                "value in the config file)");
  }
  return extent;
}

}  // namespace

void ApplyConfigOverride(YAML::Node root, const std::string& dotted_key, const std::string& value_text,
                         const std::string& source_name) {
  const std::string option = "--set " + dotted_key;
  using config::ConfigNode;
  YAML::Node value;
  const ConfigNode::Extent extent = ParseSetValue(option, value_text, &value);

  // A path given on the command line is relative to the current folder, as
  // every command-line path is (in a config file it is relative to the config).
  if (dotted_key == "world.realism.file" && value.IsScalar() && !value.Scalar().empty() &&
      std::filesystem::path(value.Scalar()).is_relative()) {
    value = YAML::Node(std::filesystem::absolute(value.Scalar()).lexically_normal().string());
  }

  const std::vector<std::string> parts = SplitKey(dotted_key);
  YAML::Node node = root;
  std::string path;  // the parts walked so far, for messages
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    const std::string where = path.empty() ? "at the top level" : "under " + path;
    if (part.empty()) throw std::invalid_argument(option + ": empty part in the key");
    if (node.IsSequence()) {
      if (!IsIndex(part)) {
        throw std::invalid_argument(option + ": " + path + " is a list in " + source_name +
                                    "; the next part must be an index 0.." + std::to_string(node.size() - 1) +
                                    ", got '" + part + "'");
      }
      const size_t index = std::stoul(part);
      if (index >= node.size()) {
        throw std::invalid_argument(option + ": " + path + " has " + std::to_string(node.size()) + " items in " +
                                    source_name + ", no index " + part);
      }
      node.reset(node[index]);  // rebind; Node::operator= would overwrite the document's node
    } else if (node.IsMap()) {
      const YAML::Node& read_only = node;
      const bool exists = read_only[part].IsDefined();
      const std::string section = path + (path.empty() ? "" : ".") + part;
      if (!exists && !last && !IsCreatableSection(section)) {
        throw std::invalid_argument(option + ": " + source_name + " has no key '" + part + "' " + where +
                                    config::DidYouMean(part, NamesAt(node, path)) + " (keys there: " + KeysOf(node) +
                                    ")");
      }
      if (!exists && !last) node[part] = YAML::Node(YAML::NodeType::Map);  // a section created
      node.reset(node[part]);
    } else {
      throw std::invalid_argument(option + ": " + path + " is a single value in " + source_name + ", it has no '" +
                                  part + "'");
    }
    path += (path.empty() ? "" : ".") + part;
  }
  // The config with the value in place must keep a file's limits too.
  const int depth = static_cast<int>(parts.size()) + extent.height;
  if (depth > ConfigNode::kMaxDepth) {
    throw std::invalid_argument(option + ": the value would nest the config " + std::to_string(depth) +
                                " levels deep; at most " + std::to_string(ConfigNode::kMaxDepth));
  }
  ConfigNode::Extent before;
  try {
    before = ConfigNode::CheckTree(root, source_name);
  } catch (const config::ConfigError& e) {
    throw std::invalid_argument(option + ": " + e.what());
  }
  if (before.values + extent.values > ConfigNode::kMaxValues) {
    throw std::invalid_argument(option + ": the config (" + std::to_string(before.values) +
                                " values) and this value (" + std::to_string(extent.values) +
                                " values once its aliases are expanded) exceed " +
                                std::to_string(ConfigNode::kMaxValues) + " values, the limit of a config file");
  }
  AssignInPlace(node, value);
}

}  // namespace dream::config_overrides
