// dream render: pictures, videos and metric plots of a recorded run
// (docs/rendering.md).
#include "dream/workflows/render_workflow.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "dream/files/run_log_path.h"
#include "dream/files/stop_token.h"
#include "dream/node/run_summary.h"
#include "dream/render/ffmpeg_encoder.h"
#include "dream/render/metric_plot.h"
#include "dream/render/render_format.h"
#include "dream/render/run_animation.h"
#include "dream/render/run_geometry.h"
#include "dream/render/viewport.h"
#include "dream/render/trajectory_picture.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/run_config/run_config.h"
#include "dream/session/render_overlays.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

enum class Kind { kPicture, kVideo, kPlot };

/// The default output beside the log: trajectories.svg, run.mp4 or
/// metrics.png; for a log not called run.lcmlog, its name before them
/// (lab1.lcmlog -> lab1_trajectories.svg, lab1.mp4, lab1_metrics.png).
fs::path DefaultOutput(const fs::path& log, Kind kind) {
  const bool run_log = log.filename() == "run.lcmlog";
  const std::string stem = log.stem().string();
  switch (kind) {
    case Kind::kVideo:
      return log.parent_path() / (run_log ? "run.mp4" : stem + ".mp4");
    case Kind::kPlot:
      return log.parent_path() / (run_log ? "metrics.png" : stem + "_metrics.png");
    case Kind::kPicture:
      break;
  }
  return log.parent_path() / (run_log ? "trajectories.svg" : stem + "_trajectories.svg");
}

Kind KindOf(const RenderWorkflow::Options& args) {
  const bool plot = args.plot || !args.metrics.empty();
  if (plot && args.video) throw RenderWorkflow::UsageError("--plot/--metric and --video: pick one");
  if (args.out.empty()) return plot ? Kind::kPlot : args.video ? Kind::kVideo : Kind::kPicture;
  const std::optional<render::RenderFormat> format = render::RenderFormatOfPath(args.out);
  if (!format) {
    throw RenderWorkflow::UsageError("--out " + args.out + ": unknown extension '" +
                                     fs::path(args.out).extension().string() +
                                     "'; allowed: " + render::RenderFormatExtensions());
  }
  if (render::IsPictureFormat(*format)) {
    if (args.video) throw RenderWorkflow::UsageError("--video needs an --out ending in .mp4 or .gif, got " + args.out);
    return plot ? Kind::kPlot : Kind::kPicture;
  }
  if (plot) throw RenderWorkflow::UsageError("--plot/--metric draw a .png or .svg, got --out " + args.out);
  return Kind::kVideo;
}

// What only a video draws, refused for pictures and plots rather than ignored.
void CheckVideoOnlyOptions(const RenderWorkflow::Options& args, Kind kind) {
  if (kind == Kind::kVideo) return;
  const char* option = !args.viewport.empty() ? "--viewport"
                       : !args.steps.empty()  ? "--steps"
                       : !args.robot_ids      ? "--no-ids"
                                              : nullptr;
  if (option != nullptr) throw RenderWorkflow::UsageError(std::string(option) + " is for videos (.mp4, .gif)");
}

bool AllDigits(const std::string& text) {
  return !text.empty() && text.size() <= 12 &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// The run's config: --config, else config.yaml beside the log when there.
/// A broken config.yaml beside the log is only a warning unless `needed`.
std::optional<run_config::RunConfig> LoadConfig(const RenderWorkflow::Options& args, const fs::path& log, bool needed) {
  if (!args.config_path.empty()) return run_config::LoadRunConfigFile(args.config_path);
  const fs::path beside = log.parent_path() / "config.yaml";
  if (!fs::is_regular_file(beside)) return std::nullopt;
  try {
    return run_config::LoadRunConfigFile(beside.string());
  } catch (const std::exception& e) {
    if (needed) throw;
    spdlog::warn("drawing without the config's goals: {}", e.what());
    return std::nullopt;
  }
}

render::ArenaOverlays Overlays(const RenderWorkflow::Options& args, const fs::path& log, int log_robots) {
  const bool needed = args.radio_links || args.sensor_ranges;
  const std::optional<run_config::RunConfig> config = LoadConfig(args, log, needed);
  if (!config) {
    if (needed) {
      throw std::runtime_error(std::string(args.radio_links ? "--radio-links" : "--sensor-ranges") +
                               " needs the run's config: no config.yaml beside " + log.string() +
                               " (give --config FILE)");
    }
    return {};
  }
  // Another run's config would draw its goals, radio and sensors on these robots.
  if (config->num_robots != log_robots) {
    const std::string mismatch = config->source + " has " + std::to_string(config->num_robots) + " robots, " +
                                 log.string() + " " + std::to_string(log_robots);
    if (needed || !args.config_path.empty())
      throw std::runtime_error("--config: " + mismatch + ": not this run's config");
    spdlog::warn("drawing without the config's goals: {}", mismatch);
    return {};
  }
  render::ArenaOverlays overlays;
  try {
    overlays = session::ArenaOverlaysFromConfig(*config);
  } catch (const std::exception& e) {
    // Goals are a nicety: without them the log still draws the run.
    if (needed || !args.config_path.empty()) throw;
    spdlog::warn("drawing without the config's goals: {}", e.what());
    return {};
  }
  if (args.radio_links && !overlays.hears) {
    throw std::runtime_error("--radio-links: the robots of " + config->source + " have no radio (controller.radio)");
  }
  if (args.sensor_ranges && overlays.sensor_reaches.empty()) {
    throw std::runtime_error("--sensor-ranges: the robots of " + config->source +
                             " have no movement or obstacle sensor (controller.sensors)");
  }
  overlays.draw_radio_links = args.radio_links;
  overlays.draw_sensor_ranges = args.sensor_ranges;
  return overlays;
}

/// The run's name and verdict from summary.json beside `log`, when it is
/// there and holds them (the pictures' captions show them).
void RunLabelFromSummary(const fs::path& log, render::ArenaOverlays* overlays) {
  const fs::path summary_path = log.parent_path() / node::RunSummary::kFileName;
  if (!fs::is_regular_file(summary_path)) return;
  node::RunSummary summary;
  try {
    summary = node::RunSummary::Read(summary_path.string());
  } catch (const std::exception& e) {
    // A label is a nicety, not worth failing for.
    spdlog::warn("{} (the picture goes without the run's name and verdict)", e.what());
    return;
  }
  if (summary.Has("run")) overlays->run_name = summary.run;
  if (summary.Has("verdict")) overlays->verdict = world::RunVerdictName(summary.verdict);  // the caption's text
  overlays->sim_only = summary.sim_only;
  // A Python controller's goal_points(), judged when the run was reported.
  if (summary.metrics.is_object()) session::AddDeclaredGoals(summary.metrics, overlays);
}

/// summary.json's metric series ({"name": [[step, value], ...]}) beside the
/// log, then the closest approach computed from the log's poses.
std::vector<render::MetricSeries> MetricSeriesOf(const fs::path& log, const run_log::RunLog& run, std::string* title) {
  std::vector<render::MetricSeries> series;
  const fs::path summary_path = log.parent_path() / node::RunSummary::kFileName;
  *title = log.string();
  if (fs::is_regular_file(summary_path)) {
    const node::RunSummary summary = node::RunSummary::Read(summary_path.string());
    if (summary.Has("run")) *title = summary.run;
    if (summary.metrics.is_object()) {
      for (const auto& [name, value] : summary.metrics.items()) {
        if (!value.is_array() || value.empty()) continue;
        render::MetricSeries s;
        s.name = name;
        for (const auto& point : value) {
          if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) break;
          s.points.push_back({point[0].get<double>(), point[1].get<double>()});
        }
        if (s.points.size() == value.size()) series.push_back(std::move(s));
      }
    }
  }
  render::MetricSeries closest;
  closest.name = "min_distance_m";
  closest.points = render::MinimumDistanceSeries(run);
  closest.limit = robotarium::RobotariumConstants::kCollisionDiameterMeters;
  closest.limit_label = "collision distance 0.135 m";
  if (!closest.points.empty()) series.push_back(std::move(closest));
  return series;
}

std::vector<render::MetricSeries> PickMetrics(std::vector<render::MetricSeries> all,
                                              const std::vector<std::string>& names, const fs::path& log) {
  std::string available;
  for (const render::MetricSeries& s : all) available += (available.empty() ? "" : ", ") + s.name;
  if (all.empty())
    throw std::runtime_error(log.string() + ": no metric series to plot (a single robot, no summary.json)");
  if (names.empty()) return all;
  std::vector<render::MetricSeries> picked;
  for (const std::string& name : names) {
    auto found = std::find_if(all.begin(), all.end(), [&](const render::MetricSeries& s) { return s.name == name; });
    if (found == all.end())
      throw std::runtime_error("--metric " + name + ": not a series of this run; it has: " + available);
    picked.push_back(*found);
  }
  return picked;
}

void CheckOutputFolder(const fs::path& out) {
  const fs::path folder = out.has_parent_path() ? out.parent_path() : fs::path(".");
  if (!fs::is_directory(folder)) {
    throw std::runtime_error("--out " + out.string() + ": " +
                             (fs::exists(folder) ? folder.string() + " is a file, not a folder"
                                                 : "the folder " + folder.string() + " does not exist"));
  }
}

// "2.35 s": durations for people, not "6.66667 s" nor "0.123456 s".
std::string SecondsText(double seconds) { return fmt::format("{:.2f} s", seconds); }

std::string SecondsSince(std::chrono::steady_clock::time_point start) {
  return SecondsText(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

std::pair<int64_t, int64_t> RenderWorkflow::ParseStepRange(const std::string& text) {
  const size_t dash = text.find('-');
  const std::string first = text.substr(0, dash);
  const std::string last = dash == std::string::npos ? "" : text.substr(dash + 1);
  if (!AllDigits(first) || !AllDigits(last)) {
    throw std::invalid_argument("--steps " + text.substr(0, 40) + ": expected FIRST-LAST, whole steps (120-480)");
  }
  const std::pair<int64_t, int64_t> range{std::stoll(first), std::stoll(last)};
  if (range.first > range.second) {
    throw std::invalid_argument("--steps " + text + ": the first step is after the last");
  }
  return range;
}

RenderWorkflow::Result RenderWorkflow::Render(const Options& args) const {
  const auto start = std::chrono::steady_clock::now();
  const Kind kind = KindOf(args);
  CheckVideoOnlyOptions(args, kind);
  const std::optional<render::Viewport> viewport =
      args.viewport.empty() ? std::nullopt : std::optional<render::Viewport>(render::Viewport::Parse(args.viewport));
  const std::pair<int64_t, int64_t> steps =
      args.steps.empty() ? std::pair<int64_t, int64_t>{-1, -1} : ParseStepRange(args.steps);
  const fs::path log = files::RunLogPath(args.run_or_log);
  const fs::path out = args.out.empty() ? DefaultOutput(log, kind) : fs::path(args.out);
  const render::RenderFormat format = *render::RenderFormatOfPath(out.string());
  CheckOutputFolder(out);

  // Ctrl-C or SIGTERM: asked between the stages and within the long ones;
  // files::Stopped (exit 130) before anything is written.
  const files::StopToken stop = args.stop ? files::StopToken(*args.stop) : files::StopToken();
  const run_log::RunLog run = run_log::RunLog::Read(log.string());
  stop.ThrowIfRequested();
  render::Drawable(run);
  if (kind == Kind::kPlot) {
    std::string title;
    const std::vector<render::MetricSeries> series = PickMetrics(MetricSeriesOf(log, run, &title), args.metrics, log);
    stop.ThrowIfRequested();
    render::MetricPlot::Render(series, title, out.string(), format, args.width_px > 0 ? args.width_px : 1000);
    out_ << "plot:    " << out.string() << " (" << series.size() << " series)\n";
    return {false, out.string()};
  }
  render::ArenaOverlays overlays = Overlays(args, log, run.num_robots());
  RunLabelFromSummary(log, &overlays);
  if (!args.goals) overlays.goals_m.clear();
  overlays.draw_drawings = args.drawings;
  // Where and when the run broke a rule, by the world's own checks (the
  // Robotarium's arena and collision rule: WorldParams is not configurable).
  if (args.violations) {
    overlays.violations = render::LocateViolations(run, {}, world::ViolationTracker::kDefaultMaxListed, stop);
  }
  stop.ThrowIfRequested();
  if (kind == Kind::kPicture) {
    render::TrajectoryPicture::Render(run, overlays, out.string(), format, args.width_px > 0 ? args.width_px : 1280);
    out_ << "picture: " << out.string() << " (" << run.num_robots() << " robots, " << run.poses().size() << " steps, "
         << SecondsSince(start) << ")\n";
    return {false, out.string()};
  }

  if (!render::FfmpegEncoder::IsInstalled()) throw std::runtime_error(render::FfmpegEncoder::NotInstalledMessage());
  const bool gif = format == render::RenderFormat::kGif;
  render::AnimationOptions options;
  options.width_px = args.width_px > 0 ? args.width_px : gif ? 480 : 720;
  options.fps = args.fps > 0 ? args.fps : gif ? 15 : 30;
  options.speed = args.speed;
  options.trail_s = args.trail_s;
  options.viewport = viewport;
  options.first_step = steps.first;
  options.last_step = steps.second;
  options.robot_ids = args.robot_ids;
  render::RunAnimation animation(run, overlays, options);
  spdlog::info("rendering {} frames ({:.1f} s of video at {} fps) to {}", animation.frame_count(),
               animation.duration_s(), options.fps, out.string());
  if (!animation.Write(
          out.string(), format, [&stop] { return stop.Requested(); }, args.progress)) {
    return {true, out.string()};
  }
  out_ << "video:   " << out.string() << " (" << animation.frame_count() << " frames, "
       << SecondsText(animation.duration_s()) << " at " << options.fps << " fps, " << animation.layout().width_px()
       << "x" << animation.layout().height_px() << ", " << SecondsSince(start) << "), steps "
       << animation.StepOfFrame(0) << "-" << animation.StepOfFrame(animation.frame_count() - 1) << "\n";
  return {false, out.string()};
}

}  // namespace dream::workflows
