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

// `robots:` within the Robotarium simulator's 50, or with `sim_only: true`
// within the bus's 128; a count in between says how to lift the limit.
void ReadRobots(const ConfigNode& root, ControllerConfig* config) {
  if (root.Has("sim_only")) config->sim_only_node = root.Required("sim_only");  // a missing key has no node to keep
  config->sim_only = root.GetBool("sim_only", false);
  const ConfigNode robots = root.Required("robots");
  const long long n = robots.AsInt();
  const int limit = config->sim_only ? ControllerConfig::kMaxRobotsSimOnly : ControllerConfig::kMaxRobots;
  if (n < 1 || n > limit) {
    const std::string got = ", got " + std::to_string(n);
    const std::string why = config->sim_only ? " with sim_only (what one message of the bus carries)"
                                             : " (the Robotarium simulator's limit; the lab runs at most " +
                                                   std::to_string(ControllerConfig::kMaxRobotsOnHardware) + ")";
    if (!config->sim_only && n > limit && n <= ControllerConfig::kMaxRobotsSimOnly) {
      robots.Fail("must be at most " + std::to_string(limit) + why + got + "; add `sim_only: true` to run up to " +
                  std::to_string(ControllerConfig::kMaxRobotsSimOnly) +
                  " robots in simulation only (it can never go to the lab)");
    }
    robots.Fail("must be between 1 and " + std::to_string(limit) + why + got);
  }
  config->num_robots = static_cast<int>(n);
}

}  // namespace

std::string ControllerConfig::LabRefusal(const std::string& action) const {
  if (!sim_only) return "";
  const std::string where = sim_only_node.line() > 0 ? source + ":" + std::to_string(sim_only_node.line()) : source;
  return where + ": sim_only: true — this run was declared simulation-only; remove `sim_only` (and use at most " +
         std::to_string(kMaxRobotsOnHardware) + " robots) to " + action;
}

ControllerConfig LoadControllerConfig(const ConfigNode& root) {
  ControllerConfig config;
  config.source = root.file();
  config.name = root.Required("name").AsString();
  for (char c : config.name) {
    const bool safe =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!safe || config.name == "." || config.name == "..") {
      root.Required("name").Fail("'" + config.name + "' is not a plain name; use letters, digits, _ - . only");
    }
  }
  const long long seed = root.GetInt("seed", 1);
  if (seed < 0) root.Required("seed").Fail("must be >= 0, got " + std::to_string(seed));
  config.seed = static_cast<uint64_t>(seed);
  ReadRobots(root, &config);
  config.controller = root.Required("controller");
  if (!config.controller.IsMap()) config.controller.Fail("expected a mapping with at least `kind:`");
  ReadPlugins(root, &config);
  return config;
}

}  // namespace dream::config
