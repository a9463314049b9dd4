#include "dream/bridge/run_comparison.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "dream/lcm/wire_text.h"
#include "dream/files/file_text.h"
#include "dream/files/json_text.h"
#include "dream/node/run_summary.h"
#include "dream/files/output_folder.h"
#include "dream/bridge/run_track.h"
#include "dream/run_config/run_config.h"
#include "dream/render/comparison_picture.h"
#include "dream/world/run_report.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/bridge/metrics_json.h"

namespace dream::bridge {
namespace {

namespace fs = std::filesystem;

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

std::string Pad(std::string text, size_t width) {
  if (text.size() < width) text.insert(0, width - text.size(), ' ');
  return text;
}

/// A run folder's log, read once, and its run.
struct FolderRun {
  explicit FolderRun(const std::string& log_path)
      : log(run_log::RunLog::Read(log_path)), track(RunTrackOf(log, &end)) {}
  run_log::RunLog log;
  RunEnd end;
  RunTrack track;
};

/// The two folders of a comparison, read: the first's config and both runs.
struct ComparedFolders {
  ComparedFolders(const std::string& first_dir, const std::string& second_dir)
      : config(LoadConfig(first_dir, second_dir)),
        first((fs::path(first_dir) / "run.lcmlog").string()),
        second((fs::path(second_dir) / "run.lcmlog").string()) {}

  static run_config::RunConfig LoadConfig(const std::string& first_dir, const std::string& second_dir) {
    const std::string config_path = (fs::path(first_dir) / "config.yaml").string();
    for (const fs::path& path :
         {fs::path(first_dir) / "run.lcmlog", fs::path(second_dir) / "run.lcmlog", fs::path(config_path)}) {
      if (!fs::exists(path)) {
        throw std::runtime_error(path.string() + ": missing; pass two run folders (dream run / dream import)");
      }
    }
    return run_config::LoadRunConfigFile(config_path);
  }

  run_config::RunConfig config;
  FolderRun first;
  FolderRun second;
};

/// What a run folder holds, from the sections its summary.json has (what
/// wrote it): dream import adds "lab", dream lab-replay "lab_replay", a world
/// with realism "realism". Only named: a summary that cannot be read says nothing.
std::string WhatRunIs(const std::string& folder) {
  const std::string path = (fs::path(folder) / node::RunSummary::kFileName).string();
  try {
    const node::RunSummary summary = node::RunSummary::Read(path);
    if (summary.Has("lab")) return "lab run (dream import)";
    if (summary.Has("lab_replay")) return "lab replay (dream lab-replay)";
    if (summary.Has("realism")) return "simulation, world.realism on";
    return "simulation";
  } catch (const std::exception&) {
    return "run (no readable summary.json)";
  }
}

ComparedRun Describe(const std::string& folder, const FolderRun& folder_run, const run_config::RunConfig& config,
                     const std::string& python_runtime_dir) {
  const RunTrack& track = folder_run.track;
  const RunEnd& end = folder_run.end;
  ComparedRun run;
  run.folder = folder;
  run.what = WhatRunIs(folder);
  run.steps = track.last_step();
  run.end = end.detail;
  run.violations = end.violations;
  run.verdict = world::RunVerdictName(world::RunReport::FromViolations(run.steps, end.violations).verdict);
  const int n = track.num_robots;
  for (int64_t k = 0; k <= track.last_step(); ++k) {
    for (int i = 0; i < n; ++i) {
      const world::Pose2& a = track.pose(k, i);
      for (int j = i + 1; j < n; ++j) {
        const world::Pose2& b = track.pose(k, j);
        const double d = std::hypot(a.x_m - b.x_m, a.y_m - b.y_m);
        if (d < run.min_distance_m) {
          run.min_distance_m = d;
          run.min_distance_step = k;
          run.min_distance_first = i;
          run.min_distance_second = j;
        }
      }
    }
  }
  try {
    run.metrics = MetricsJson(config, agent_host::ControllerFactory(config), folder_run.log, python_runtime_dir);
  } catch (const std::exception& e) {
    run.metrics = nlohmann::ordered_json{{"error", e.what()}};
  }
  return run;
}

std::string Cm(double m) { return Format("%.2f", m * 100.0); }

std::string Closest(const ComparedRun& run) {
  if (run.min_distance_step < 0) return "-";
  return Format("%.3f m", run.min_distance_m) + " (robots " + std::to_string(run.min_distance_first) + ", " +
         std::to_string(run.min_distance_second) + ", step " + std::to_string(run.min_distance_step) + ")";
}

std::string MetricText(const nlohmann::ordered_json& value) {
  if (value.is_number()) return Format("%.6g", value.get<double>());
  if (value.is_array()) return std::to_string(value.size()) + " entries";
  return files::JsonText(value, -1);
}

RunComparison Compare(const std::string& first_dir, const std::string& second_dir, const ComparedFolders& runs,
                      const std::string& python_runtime_dir) {
  const RunTrack& first = runs.first.track;
  const RunTrack& second = runs.second.track;
  if (first.num_robots != second.num_robots) {
    throw std::runtime_error(runs.second.log.path() + ": has " + std::to_string(second.num_robots) + " robots, " +
                             runs.first.log.path() + " " + std::to_string(first.num_robots) +
                             ": these are not runs of one experiment");
  }
  RunComparison comparison;
  comparison.first = Describe(first_dir, runs.first, runs.config, python_runtime_dir);
  comparison.second = Describe(second_dir, runs.second, runs.config, python_runtime_dir);
  comparison.compared_steps = std::min(first.last_step(), second.last_step());
  const int n = first.num_robots;
  for (int i = 0; i < n; ++i) {
    RobotTracking tracking;
    tracking.robot = i;
    for (int64_t k = 0; k <= comparison.compared_steps; ++k) {
      const world::Pose2& a = first.pose(k, i);
      const world::Pose2& b = second.pose(k, i);
      tracking.position_m.Add(std::hypot(b.x_m - a.x_m, b.y_m - a.y_m), k);
      tracking.heading_rad.Add(std::remainder(b.theta_rad - a.theta_rad, 2 * M_PI), k);
    }
    if (i == 0 || tracking.position_m.max() > comparison.position_m.max()) comparison.max_robot = i;
    comparison.position_m.Merge(tracking.position_m);
    comparison.robots.push_back(tracking);
  }
  return comparison;
}

}  // namespace

RunComparison CompareRuns(const std::string& first_dir, const std::string& second_dir,
                          const std::string& python_runtime_dir) {
  return Compare(first_dir, second_dir, ComparedFolders(first_dir, second_dir), python_runtime_dir);
}

std::string RunComparison::Text() const {
  std::string text;
  text += "first (" + first.what + "): " + first.folder + ": " + std::to_string(first.steps) + " steps, " +
          first.verdict + (first.end.empty() ? "" : " (" + first.end + ")") + "\n";
  text += "second (" + second.what + "): " + second.folder + ": " + std::to_string(second.steps) + " steps, " +
          second.verdict + (second.end.empty() ? "" : " (" + second.end + ")") + "\n";
  text += "compared steps 0.." + std::to_string(compared_steps) + "\n\n";
  text += "tracking error (second - first, robot centre)\n";
  text += "  robot   RMS cm   max cm   at step   RMS heading deg\n";
  for (const RobotTracking& r : robots) {
    text += Pad(std::to_string(r.robot), 7) + Pad(Cm(r.position_m.Rms()), 9) + Pad(Cm(r.position_m.max()), 9) +
            Pad(std::to_string(r.position_m.max_step()), 10) +
            Pad(Format("%.2f", r.heading_rad.Rms() * 180.0 / M_PI), 18) + "\n";
  }
  text += "    all" + Pad(Cm(position_m.Rms()), 9) + Pad(Cm(position_m.max()), 9) +
          Pad(std::to_string(position_m.max_step()), 10) + "   (robot " + std::to_string(max_robot) + ")\n\n";
  text += "closest robots: first " + Closest(first) + "\n                second " + Closest(second) + "\n\n";
  text += "violations            first   second\n";
  auto row = [&text](const char* name, int64_t a, int64_t b) {
    text += std::string("  ") + name + Pad(std::to_string(a), 22 - std::string(name).size()) +
            Pad(std::to_string(b), 9) + "\n";
  };
  row("boundary", first.violations.boundary_errors, second.violations.boundary_errors);
  row("collision", first.violations.collision_errors, second.violations.collision_errors);
  row("actuator", first.violations.actuator_errors, second.violations.actuator_errors);
  row("obstacle", first.violations.obstacle_collisions, second.violations.obstacle_collisions);
  text += "\nmetrics (" +
          (first.metrics.contains("kind") ? first.metrics["kind"].get<std::string>() : std::string("?")) + ")\n";
  for (const auto& [name, value] : first.metrics.items()) {
    if (name == "kind") continue;
    const std::string other = second.metrics.contains(name) ? MetricText(second.metrics[name]) : "-";
    text += "  " + name + ": " + MetricText(value) + "  |  " + other + "\n";
  }
  return text;
}

nlohmann::ordered_json RunComparison::Json() const {
  auto side = [](const ComparedRun& run) {
    nlohmann::ordered_json json;
    json["folder"] = run.folder;
    json["what"] = run.what;
    json["steps"] = run.steps;
    json["end"] = run.end;
    json["verdict"] = run.verdict;
    json["violations"] = {{"boundary_errors", run.violations.boundary_errors},
                          {"collision_errors", run.violations.collision_errors},
                          {"actuator_errors", run.violations.actuator_errors},
                          {"obstacle_collisions", run.violations.obstacle_collisions}};
    json["min_distance_m"] = std::isfinite(run.min_distance_m) ? nlohmann::ordered_json(run.min_distance_m) : nullptr;
    json["min_distance_step"] = run.min_distance_step;
    json["min_distance_robots"] = {run.min_distance_first, run.min_distance_second};
    json["metrics"] = run.metrics;
    return json;
  };
  nlohmann::ordered_json json;
  json["first"] = side(first);
  json["second"] = side(second);
  json["compared_steps"] = compared_steps;
  json["tracking_rms_m"] = position_m.Rms();
  json["tracking_max_m"] = position_m.max();
  json["tracking_max_robot"] = max_robot;
  json["tracking_max_step"] = position_m.max_step();
  nlohmann::ordered_json robots_json = nlohmann::ordered_json::array();
  for (const RobotTracking& r : robots) {
    robots_json.push_back({{"robot", r.robot},
                           {"rms_m", r.position_m.Rms()},
                           {"max_m", r.position_m.max()},
                           {"max_step", r.position_m.max_step()},
                           {"rms_heading_rad", r.heading_rad.Rms()}});
  }
  json["robots"] = robots_json;
  return json;
}

RunComparison CompareRunsAndWrite(const std::string& first_dir, const std::string& second_dir,
                                  const std::string& out_dir, const std::string& python_runtime_dir) {
  const ComparedFolders runs(first_dir, second_dir);
  RunComparison comparison = Compare(first_dir, second_dir, runs, python_runtime_dir);
  const files::OutputFolder out(out_dir);
  const std::string picture = out.PathOf("comparison.png");
  out.WriteFile("comparison.json", files::JsonText(comparison.Json()) + "\n");
  // cairo draws UTF-8 only: a folder name that is not (Latin-1) would cost the picture.
  const auto shown = [](const std::string& folder) { return lcm::WireText::Of(folder, folder.size() * 2); };
  render::ComparisonPicture::Render(
      runs.first.log, runs.second.log, picture,
      {"dashed: " + shown(first_dir) + " (" + std::to_string(comparison.first.steps) +
           " steps), solid: " + shown(second_dir) + " (" + std::to_string(comparison.second.steps) + " steps)",
       "tracking error: RMS " + Cm(comparison.position_m.Rms()) + " cm, max " + Cm(comparison.position_m.max()) +
           " cm (robot " + std::to_string(comparison.max_robot) + ", step " +
           std::to_string(comparison.position_m.max_step()) + ")"});
  return comparison;
}

}  // namespace dream::bridge
