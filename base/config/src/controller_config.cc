#include "dream/config/controller_config.h"

#include <filesystem>

namespace dream::config {
std::filesystem::path PluginBaseDir(const ConfigNode& root) {
  namespace fs = std::filesystem;
  const ConfigNode dir = root.Optional("plugin_dir");
  if (dir.IsDefined()) {
    const fs::path path = dir.AsString();
    if (!path.is_absolute()) dir.Fail("must be an absolute path, got '" + path.string() + "'");
    return path;
  }
  const fs::path folder = fs::path(root.file()).parent_path();
  return folder.empty() ? fs::current_path() : fs::absolute(folder);
}

std::filesystem::path FileBesideConfig(const ConfigNode& node, const std::string& what) {
  namespace fs = std::filesystem;
  const std::string written = node.AsString();
  fs::path path(written);
  if (path.is_absolute()) return path.lexically_normal();
  for (const fs::path& part : path.lexically_normal()) {
    if (part == "..") {
      node.Fail("'" + written + "' leaves the config's folder: put the " + what +
                " in that folder (or below it), or give its absolute path");
    }
  }
  return (fs::path(node.file()).parent_path() / path).lexically_normal();
}

namespace {

void ReadPlugins(const ConfigNode& root, ControllerConfig* config) {
  const ConfigNode list = root.Optional("plugins");
  if (!list.IsDefined()) return;
  if (!list.IsSequence()) list.Fail("expected a list of plugin files, like [build/libmy_controller.so]");
  const std::filesystem::path base = PluginBaseDir(root);
  for (size_t i = 0; i < list.size(); ++i) {
    const std::filesystem::path path = list[i].AsString();
    if (path.empty()) list[i].Fail("expected the path of a plugin file, got an empty one");
    config->plugins.push_back((path.is_absolute() ? path : base / path).lexically_normal().string());
    config->plugin_nodes.push_back(list[i]);
  }
}

}  // namespace

ControllerConfig LoadControllerConfig(const ConfigNode& root) {
  ControllerConfig config;
  config.source = root.file();
  config.name = root.Required("name").AsString();
  for (char c : config.name) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                      c == '-' || c == '.';
    if (!safe || config.name == "." || config.name == "..") {
      root.Required("name").Fail("'" + config.name + "' is not a plain name; use letters, digits, _ - . only");
    }
  }
  const long long seed = root.GetInt("seed", 1);
  if (seed < 0) root.Required("seed").Fail("must be >= 0, got " + std::to_string(seed));
  config.seed = static_cast<uint64_t>(seed);
  const ConfigNode robots = root.Required("robots");
  const long long num_robots = robots.AsInt();
  if (num_robots < 1 || num_robots > ControllerConfig::kMaxRobots) {
    robots.Fail("must be between 1 and " + std::to_string(ControllerConfig::kMaxRobots) +
                " (the Robotarium simulator's limit; the lab runs at most " +
                std::to_string(ControllerConfig::kMaxRobotsOnHardware) + "), got " + std::to_string(num_robots));
  }
  config.num_robots = static_cast<int>(num_robots);
  config.controller = root.Required("controller");
  if (!config.controller.IsMap()) config.controller.Fail("expected a mapping with at least `kind:`");
  ReadPlugins(root, &config);
  return config;
}

}  // namespace dream::config
