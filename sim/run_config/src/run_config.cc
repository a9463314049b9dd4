#include "dream/run_config/run_config.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "dream/config/name_suggestion.h"
#include "dream/world/initial_pose_generator.h"
#include "dream/world/printf_text.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/start_pose_obstacle_check.h"

namespace dream::run_config {

static_assert(config::ControllerConfig::kMaxRobots == robotarium::RobotariumConstants::kMaxRobotsInSimulation &&
                  config::ControllerConfig::kMaxRobotsOnHardware ==
                      robotarium::RobotariumConstants::kMaxRobotsOnHardware,
              "the agents' robot limits must be the simulator's");

namespace {

using robotarium::RobotariumConstants;

// The lab can only place a robot whose whole body (radius 0.055 m) is inside
// the arena: `dream export` refuses a start pose closer to a wall than this
// (rule start_inside_arena, bridge::LabLimits::start_wall_margin_m). It is
// stricter than the world's boundary error (centre outside the arena), so a
// start pose that passes it passes both.
constexpr double kStartWallClearanceM = robotarium::RobotariumConstants::kRobotDiameterMeters / 2.0;

// The same comparison as the export's check, so "accepted here" can never be
// "refused there" through rounding.
bool ClearOfTheWalls(const world::Arena& arena, const world::Pose2& pose) {
  const double m = kStartWallClearanceM;
  return !(pose.x_m < arena.x_min_m + m || pose.x_m > arena.x_max_m - m || pose.y_m < arena.y_min_m + m ||
           pose.y_m > arena.y_max_m - m);
}

std::string Format(double value) { return world::PrintfText("%.3f", value); }

// For constants with more digits than millimetres (the 0.0675 m radius).
std::string FormatExact(double value) { return world::PrintfText("%g", value); }

// `world.command_limits: robotarium | official` (config/README.md): official takes any finite
// command, as the official simulator does (dream run SCRIPT.py sets it); max_abs_* then have no say.
void ReadCommandLimits(const config::ConfigNode& world, config::SimNodeOptions* options) {
  enum class Limits { kRobotarium, kOfficial };
  const Limits limits = world.GetChoice<Limits>("command_limits", "robotarium", "world command_limits",
                                                {{"robotarium", Limits::kRobotarium}, {"official", Limits::kOfficial}});
  if (limits == Limits::kRobotarium) return;
  for (const char* key : {"max_abs_v_mps", "max_abs_w_radps"}) {
    if (world.Has(key)) world.FailAt(key, "is not taken with command_limits: official (any finite command is)");
  }
  options->max_abs_v_mps = config::SimNodeOptions::kOfficialCommandLimit;
  options->max_abs_w_radps = config::SimNodeOptions::kOfficialCommandLimit;
}

config::SimNodeOptions ReadSimOptions(const config::ConfigNode& root) {
  config::SimNodeOptions options;
  options.max_steps = root.GetInt("steps", options.max_steps);
  if (options.max_steps < 1) root.Required("steps").Fail("must be >= 1, got " + std::to_string(options.max_steps));
  options.stop_when_done = root.GetBool("stop_when_done", options.stop_when_done);
  const config::ConfigNode world = root.Optional("world");
  if (world.IsDefined()) {
    world.RejectUnknownKeys({"mode", "agent_timeout_s", "start_timeout_s", "resend_interval_s", "max_abs_v_mps",
                             "max_abs_w_radps", "command_limits", "script_ends_run", "realism", "start"});
    if (world.Has("mode")) {
      const config::ConfigNode mode = world.Required("mode");
      try {
        options.mode = config::ParseWorldMode(mode.AsString());
      } catch (const std::invalid_argument& e) {
        mode.Fail(e.what());
      }
    }
    // Each duration or limit must be positive; the error points at its line.
    auto positive = [&world](const char* key, double fallback) {
      const double value = world.GetDouble(key, fallback);
      if (!(value > 0.0)) world.Required(key).Fail("must be > 0, got " + world.Required(key).AsString());
      return value;
    };
    options.agent_timeout_s = positive("agent_timeout_s", options.agent_timeout_s);
    options.start_timeout_s = positive("start_timeout_s", options.start_timeout_s);
    options.resend_interval_s = world.GetDouble("resend_interval_s", options.resend_interval_s);
    if (!(options.resend_interval_s >= config::SimNodeOptions::kMinResendIntervalS)) {
      world.FailAt("resend_interval_s", "must be >= 0.01 s (more often floods the bus), got " +
                                            world.Required("resend_interval_s").AsString());
    }
    options.max_abs_v_mps = positive("max_abs_v_mps", options.max_abs_v_mps);
    options.max_abs_w_radps = positive("max_abs_w_radps", options.max_abs_w_radps);
    ReadCommandLimits(world, &options);
    // A Robotarium script's run (dream run SCRIPT.py writes it): the script ends the run.
    options.script_ends_run = world.GetBool("script_ends_run", options.script_ends_run);
  }
  std::string error;
  if (!options.IsValid(&error)) root.Fail(error);  // unreachable when the checks above hold
  return options;
}

// `world.start: exact | placed` (config/README.md#the-start-up-drive-worldstart-and-lab_safe).
WorldStart ReadWorldStart(const config::ConfigNode& root) {
  const config::ConfigNode world = root.Optional("world");
  if (!world.IsDefined()) return WorldStart::kExact;
  return world.GetChoice<WorldStart>("start", "exact", "world start",
                                     {{"exact", WorldStart::kExact}, {"placed", WorldStart::kPlaced}});
}

world::RealismParams RealismPreset(const config::ConfigNode& name) {
  world::RealismParams params;
  const std::string text = name.AsString();
  if (!world::RealismParams::FromPreset(text, &params)) {
    std::string known;
    for (const std::string& preset : world::RealismParams::PresetNames()) known += (known.empty() ? "" : ", ") + preset;
    name.Fail("unknown realism preset '" + text + "'" + config::DidYouMean(text, world::RealismParams::PresetNames()) +
              "; known presets: " + known);
  }
  return params;
}

// The realism keys of `node` over `base`, each checked in turn so the error
// names the first bad one with its line.
world::RealismParams ReadRealismKeys(const config::ConfigNode& node, world::RealismParams params) {
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
    if (field.steps != nullptr) {
      const long long value = node.GetInt(field.key, params.*field.steps);
      if (value < 0 || value > world::RealismParams::kMaxDelaySteps) {
        node.Required(field.key).Fail("must be 0.." + std::to_string(world::RealismParams::kMaxDelaySteps) +
                                      " steps, got " + std::to_string(value));
      }
      params.*field.steps = static_cast<int>(value);
      continue;
    }
    params.*field.number = node.GetDouble(field.key, params.*field.number);
    std::string error;
    if (node.Has(field.key) && !params.IsValid(&error)) node.Required(field.key).Fail(error);
  }
  std::string error;
  if (!params.IsValid(&error)) node.Fail(error);  // a rule between keys (loop_stall_max_s)
  return params;
}

// A realism map's keys: preset, `extra` (unless null) and every model's.
std::vector<const char*> RealismKeys(const char* extra) {
  std::vector<const char*> keys = {"preset"};
  if (extra != nullptr) keys.push_back(extra);
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) keys.push_back(field.key);
  return keys;
}

// A realism map's base: its preset, else ideal.
world::RealismParams RealismBase(const config::ConfigNode& node) {
  return node.Has("preset") ? RealismPreset(node.Required("preset")) : world::RealismParams::Ideal();
}

// A realism file's map over `base`, or over its own preset.
world::RealismParams RealismOfFile(const config::ConfigNode& file, const world::RealismParams& base) {
  file.RejectUnknownKeys(RealismKeys(nullptr));
  return ReadRealismKeys(file, file.Has("preset") ? RealismBase(file) : base);
}

// `file: PATH`: a realism file (a map of realism keys, with an optional
// preset; what dream calibrate writes), relative to the config's folder. Its
// keys go over `base` (the config's preset), or over its own preset.
world::RealismParams ReadRealismFile(const config::ConfigNode& file_node, const world::RealismParams& base,
                                     RunConfig* config) {
  namespace fs = std::filesystem;
  const std::string written = file_node.AsString();
  if (written.empty()) file_node.Fail("expected the path of a realism file (e.g. from dream calibrate), got ''");
  const fs::path path = config::FileBesideConfig(file_node, "realism file");
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    file_node.Fail("no realism file '" + path.lexically_normal().string() +
                   "' (relative paths are taken from the config file's folder)");
  }
  const std::string file_path = path.lexically_normal().string();
  YAML::Node file_root = config::ConfigNode::ParseYaml(config::ConfigNode::ReadFile(file_path), file_path);
  if (!file_root.IsMap()) {
    file_node.Fail("'" + file_path +
                   "' is not a realism file: a realism file is a map of world.realism keys (as dream "
                   "calibrate writes)");
  }
  config->realism_file_as_written = written;
  config->realism_file = fs::absolute(path, error).lexically_normal().string();
  return RealismOfFile(config::ConfigNode(file_root, file_path, ""), base);
}

// `world.realism`: a preset name, or a map of models: `preset:` (ideal when
// absent), then `file:`, then the map's own keys. See docs/experiments.md.
world::RealismParams ReadRealism(const config::ConfigNode& root, RunConfig* config) {
  const config::ConfigNode world = root.Optional("world");
  const config::ConfigNode node = world.IsDefined() ? world.Optional("realism") : config::ConfigNode();
  if (!node.IsDefined()) return world::RealismParams::Ideal();
  if (!node.IsMap()) return RealismPreset(node);
  node.RejectUnknownKeys(RealismKeys("file"));
  // Layers, each over the one before: the preset, the file, the keys here.
  world::RealismParams base = RealismBase(node);
  if (node.Has("file")) base = ReadRealismFile(node.Required("file"), base, config);
  return ReadRealismKeys(node, base);
}

// `generate: {lab_safe: true}`: the spacing rps's generate_random_poses gives
// the official simulator's own random start poses.
constexpr double kLabSafeSpacingM = 0.5;

// `initial_poses` absent or `{generate: {...}}`: poses drawn clear of the
// walls, of each other and of the obstacles; with `lab_safe: true` spaced as
// the official simulator spaces random start poses (StartupDriveCheck refuses
// them when the start-up drive does not settle: when a command runs, not at
// every load of the config).
std::vector<world::Pose2> GenerateInitialPoses(const config::ConfigNode& node, RunConfig* config_out) {
  const RunConfig& config = *config_out;
  world::InitialPoseParams params;
  config::ConfigNode where = node;  // the key a failure names
  bool lab_safe = false;
  if (node.IsDefined()) {
    node.RejectUnknownKeys({"generate"});
    const config::ConfigNode generate = node.Required("generate");
    where = generate;
    if (generate.IsMap()) {
      generate.RejectUnknownKeys({"min_spacing_m", "wall_margin_m", "lab_safe"});
      lab_safe = generate.GetBool("lab_safe", false);
      if (lab_safe) params.min_spacing_m = kLabSafeSpacingM;
      params.min_spacing_m = generate.GetDouble("min_spacing_m", params.min_spacing_m);
      params.wall_margin_m = generate.GetDouble("wall_margin_m", params.wall_margin_m);
      if (params.wall_margin_m < kStartWallClearanceM) {
        generate.Required("wall_margin_m")
            .Fail("must be at least " + FormatExact(kStartWallClearanceM) +
                  " m (the robot's radius): the lab refuses a start pose closer to a wall "
                  "(start_inside_arena), got " +
                  generate.Required("wall_margin_m").AsString());
      }
    }
  }
  std::vector<world::Pose2> poses;
  try {
    poses =
        world::InitialPoseGenerator(config.world, params, config.obstacles).Generate(config.num_robots, config.seed);
  } catch (const std::invalid_argument& e) {
    where.Fail(std::string("cannot generate initial poses: ") + e.what() +
               "; or list one [x, y, theta] per robot under initial_poses");
  }
  if (lab_safe) config_out->lab_safe_spacing_m = params.min_spacing_m;
  return poses;
}

// A listed start pose the lab would refuse: outside the arena, against a wall,
// or inside an obstacle at step 0. `item` (robot `i`'s entry) names the failure.
void CheckListedPose(const config::ConfigNode& item, size_t i, const world::Pose2& pose, const RunConfig& config,
                     const world::StartPoseObstacleCheck& obstacle_check) {
  if (!config.world.arena.Contains(pose.x_m, pose.y_m)) {
    item.Fail("robot " + std::to_string(i) + " starts at (" + Format(pose.x_m) + ", " + Format(pose.y_m) +
              "), outside the arena x in [" + Format(config.world.arena.x_min_m) + ", " +
              Format(config.world.arena.x_max_m) + "], y in [" + Format(config.world.arena.y_min_m) + ", " +
              Format(config.world.arena.y_max_m) + "]");
  }
  if (!ClearOfTheWalls(config.world.arena, pose)) {
    const world::Arena& arena = config.world.arena;
    const double m = kStartWallClearanceM;
    item.Fail("robot " + std::to_string(i) + " starts at (" + Format(pose.x_m) + ", " + Format(pose.y_m) +
              "), closer than its radius " + FormatExact(m) +
              " m to the arena's wall: the lab cannot place it there (dream export's start_inside_arena "
              "rule); start poses need x in [" +
              Format(arena.x_min_m + m) + ", " + Format(arena.x_max_m - m) + "], y in [" + Format(arena.y_min_m + m) +
              ", " + Format(arena.y_max_m - m) + "]");
  }
  // Only step 0 counts: a moving obstacle may sweep over a start pose later.
  const int touched = obstacle_check.FirstTouchedObstacle(pose);
  if (touched >= 0) {
    const world::RectangleObstacleSpec& obstacle = config.obstacles[static_cast<size_t>(touched)];
    item.Fail("robot " + std::to_string(i) + " starts inside obstacle " + std::to_string(touched) + ": at (" +
              Format(pose.x_m) + ", " + Format(pose.y_m) + ", " + Format(pose.theta_rad) +
              ") its collision disc (centre (" + Format(obstacle_check.CollisionCenterX(pose)) + ", " +
              Format(obstacle_check.CollisionCenterY(pose)) + "), radius " +
              FormatExact(obstacle_check.collision_radius_m()) + " m) touches obstacles[" + std::to_string(touched) +
              "] (centre (" + Format(obstacle.center_m.x()) + ", " + Format(obstacle.center_m.y()) + "), size " +
              Format(obstacle.width_m) + " x " + Format(obstacle.height_m) +
              " m, at step 0); move the robot or the obstacle");
  }
}

// Robots that start in collision would make the Robotarium reject the run.
void CheckStartsApart(const config::ConfigNode& node, const std::vector<world::Pose2>& poses, const RunConfig& config) {
  const double offset = config.world.collision_offset_m;
  for (size_t i = 0; i < poses.size(); ++i) {
    for (size_t j = i + 1; j < poses.size(); ++j) {
      const double dx = (poses[i].x_m + offset * std::cos(poses[i].theta_rad)) -
                        (poses[j].x_m + offset * std::cos(poses[j].theta_rad));
      const double dy = (poses[i].y_m + offset * std::sin(poses[i].theta_rad)) -
                        (poses[j].y_m + offset * std::sin(poses[j].theta_rad));
      const double distance = std::hypot(dx, dy);
      if (distance <= config.world.collision_diameter_m) {
        node[j].Fail("robots " + std::to_string(i) + " and " + std::to_string(j) +
                     " start in collision: their collision centres are " + Format(distance) +
                     " m apart, they must be more than " + Format(config.world.collision_diameter_m) + " m");
      }
    }
  }
}

// Needs config.obstacles: generated poses avoid them and listed poses may not
// start inside one (either would be an obstacle collision at step 0).
std::vector<world::Pose2> ReadInitialPoses(const config::ConfigNode& root, RunConfig* config_out) {
  const RunConfig& config = *config_out;
  const config::ConfigNode node = root.Optional("initial_poses");
  if (!node.IsDefined() || node.IsMap()) return GenerateInitialPoses(node, config_out);
  if (!node.IsSequence() || node.size() != static_cast<size_t>(config.num_robots)) {
    node.Fail("expected one [x, y, theta] per robot (" + std::to_string(config.num_robots) + "), got " +
              (node.IsSequence() ? std::to_string(node.size()) : std::string("no list")) +
              "; or write `initial_poses: {generate: {min_spacing_m: 0.3}}`");
  }
  const world::StartPoseObstacleCheck obstacle_check(config.world, config.obstacles);
  std::vector<world::Pose2> poses;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::vector<double> values = node[i].AsDoubles();
    if (values.size() != 3) node[i].Fail("expected [x, y, theta] (metres, metres, radians)");
    const world::Pose2 pose{values[0], values[1], values[2]};
    CheckListedPose(node[i], i, pose, config, obstacle_check);
    poses.push_back(pose);
  }
  CheckStartsApart(node, poses, config);
  return poses;
}

std::vector<world::RectangleObstacleSpec> ReadObstacles(const config::ConfigNode& root) {
  std::vector<world::RectangleObstacleSpec> specs;
  const config::ConfigNode list = root.Optional("obstacles");
  if (!list.IsDefined()) return specs;
  if (!list.IsSequence()) list.Fail("expected a list of obstacles (each with center: and size:)");
  if (list.size() > RunConfig::kMaxObstacles) {
    list.Fail("at most " + std::to_string(RunConfig::kMaxObstacles) + " obstacles, got " + std::to_string(list.size()));
  }
  for (size_t i = 0; i < list.size(); ++i) {
    const config::ConfigNode item = list[i];
    item.RejectUnknownKeys({"center", "size", "path"});
    world::RectangleObstacleSpec spec;
    spec.id = static_cast<int>(i);
    const std::vector<double> center = item.Required("center").AsDoubles();
    if (center.size() != 2) item.Required("center").Fail("expected [x, y] in metres");
    const std::vector<double> size = item.Required("size").AsDoubles();
    if (size.size() != 2) item.Required("size").Fail("expected [width, height] in metres");
    spec.center_m = Eigen::Vector2d(center[0], center[1]);
    spec.width_m = size[0];
    spec.height_m = size[1];
    const config::ConfigNode path = item.Optional("path");
    if (path.IsDefined()) {
      path.RejectUnknownKeys({"waypoints", "speed_mps", "mode"});
      world::ObstaclePath route;
      const config::ConfigNode waypoints = path.Required("waypoints");
      if (!waypoints.IsSequence()) waypoints.Fail("expected a list of [x, y] waypoints");
      for (size_t w = 0; w < waypoints.size(); ++w) {
        const std::vector<double> xy = waypoints[w].AsDoubles();
        if (xy.size() != 2) waypoints[w].Fail("expected [x, y] in metres");
        route.waypoints_m.emplace_back(xy[0], xy[1]);
      }
      route.speed_mps = path.Required("speed_mps").AsDouble();
      route.mode = path.GetChoice<world::ObstaclePathMode>(
          "mode", "loop", "path mode",
          {{"loop", world::ObstaclePathMode::kLoop}, {"ping_pong", world::ObstaclePathMode::kPingPong}});
      spec.path = route;
    }
    std::string error;
    if (!spec.IsValid(&error)) item.Fail(error);
    specs.push_back(spec);
  }
  return specs;
}

/// `script:`: the Robotarium script whose run this is (a .py file), or "".
std::string ReadScript(const config::ConfigNode& root) {
  const config::ConfigNode node = root.Optional("script");
  if (!node.IsDefined()) return "";
  const std::string path = node.AsString();
  if (path.size() < 4 || path.substr(path.size() - 3) != ".py") {
    node.Fail("expected the path of a Robotarium script (a .py file), got '" + path + "'");
  }
  return path;
}

}  // namespace

RunConfig LoadRunConfig(const config::ConfigNode& root) {
  root.RejectUnknownKeys({"name", "seed", "robots", "sim_only", "steps", "stop_when_done", "world", "initial_poses",
                          "obstacles", "controller", "description", "plugins", "plugin_dir", "barriers", "script"});
  RunConfig config;
  // Free text nobody reads back; a list or mapping here is still a mistake.
  root.GetString("description", "");
  config.script = ReadScript(root);
  // What agents read too, from the one place that checks it.
  static_cast<config::ControllerConfig&>(config) = config::LoadControllerConfig(root);
  config.sim = ReadSimOptions(root);
  if (config.sim.script_ends_run && config.script.empty()) {
    root.Required("world").FailAt("script_ends_run", "only a Robotarium script's run (script:) ends with its script");
  }
  config.start = ReadWorldStart(root);
  config.realism = ReadRealism(root, &config);
  config.obstacles = ReadObstacles(root);
  config.initial_poses = ReadInitialPoses(root, &config);
  config.barriers = BarrierConfig::Read(root);
  return config;
}

world::RealismParams LoadRealismFile(const std::string& path) {
  YAML::Node root = config::ConfigNode::ParseYaml(config::ConfigNode::ReadFile(path), path);
  if (!root.IsMap()) {
    throw config::ConfigError(path +
                              ": not a realism file: a realism file is a map of world.realism keys (as dream calibrate "
                              "writes)");
  }
  return RealismOfFile(config::ConfigNode(root, path, ""), world::RealismParams::Ideal());
}

RunConfig LoadRunConfigFile(const std::string& path) { return LoadRunConfig(config::ConfigNode::LoadFile(path)); }

std::string RealismFileInRunFolder(const RunConfig& config) {
  if (config.realism_file_as_written.empty()) return "";
  const std::filesystem::path written = std::filesystem::path(config.realism_file_as_written).lexically_normal();
  return written.is_absolute() ? (std::filesystem::path("realism") / written.filename()).string() : written.string();
}

namespace {

// `text` with world.realism.file naming the run folder's copy, when it names
// an absolute path (the copy is elsewhere than written). The text is
// re-emitted, so its comments go; a header says why.
std::string WithRealismCopy(const RunConfig& config, const std::string& text) {
  const std::string copy = RealismFileInRunFolder(config);
  if (copy.empty() || copy == std::filesystem::path(config.realism_file_as_written).lexically_normal().string()) {
    return text;
  }
  YAML::Node root = config::ConfigNode::ParseYaml(text, config.source);
  const YAML::Node& read_only = root;
  const YAML::Node world = read_only["world"];  // a missing key's node may only be asked IsDefined()
  if (!world.IsDefined() || !world.IsMap()) return text;
  const YAML::Node realism_read = world["realism"];
  if (!realism_read.IsDefined() || !realism_read.IsMap() || !realism_read["file"].IsDefined()) return text;
  YAML::Node realism = root["world"]["realism"];
  realism["file"] = copy;
  YAML::Emitter out;
  out.SetIndent(2);
  out << root;
  return "# Written by dream: world.realism.file names this folder's copy of " + config.realism_file + "\n" +
         out.c_str() + "\n";
}

std::string WithPluginDir(const RunConfig& config, const std::string& text) {
  if (config.plugin_nodes.empty()) return text;
  const config::ConfigNode root = config::ConfigNode::LoadString(text, config.source);
  bool relative = false;
  for (size_t i = 0; i < config.plugin_nodes.size(); ++i) {
    relative = relative || !std::filesystem::path(config.plugin_nodes[i].AsString()).is_absolute();
  }
  if (!relative || root.Has("plugin_dir")) return text;
  const std::string dir = config::PluginBaseDir(root).string();
  std::string quoted = "\"";
  for (char c : dir) quoted += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  quoted += "\"";
  const std::string copy = text + (text.empty() || text.back() == '\n' ? "" : "\n") +
                           "# Added by dream: the folder the relative plugin paths above are relative to.\n"
                           "plugin_dir: " +
                           quoted + "\n";
  // An unusual file (a flow mapping, an explicit document end) would not take
  // the extra key: keep it unchanged rather than store a broken copy.
  try {
    if (config::ConfigNode::LoadString(copy, config.source).GetString("plugin_dir", "") == dir) return copy;
  } catch (const config::ConfigError&) {
  }
  return text;
}

}  // namespace

std::string RunFolderConfigText(const RunConfig& config, const std::string& text) {
  return WithPluginDir(config, WithRealismCopy(config, text));
}

}  // namespace dream::run_config
