#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <iostream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
}  // namespace CLI

namespace dream::workflows {

/// `dream render`: a recorded run drawn as the arena picture (.png/.svg), a
/// video (.mp4/.gif, through ffmpeg) or its metrics over time (a plot), with
/// the goals, radio and sensors of its config and the name and verdict of its
/// summary.json when they are beside the log. Prints what it wrote.
class RenderWorkflow {
 public:
  struct Options {
    std::string run_or_log;   ///< a run folder (its run.lcmlog) or an .lcmlog file (files::RunLogPath)
    std::string out;          ///< .png/.svg/.mp4/.gif; empty: beside the log (trajectories.svg, run.mp4, metrics.png)
    std::string config_path;  ///< empty: config.yaml beside the log, when there
    bool video = false;       ///< no `out`: write run.mp4
    bool plot = false;        ///< metric plots instead of the arena
    std::vector<std::string> metrics;  ///< plot only these series (implies plot)
    bool radio_links = false;
    bool sensor_ranges = false;
    int width_px = 0;       ///< 0: 1280 pictures, 1000 plots, 720 MP4, 480 GIF
    double fps = 0;         ///< 0: 30 MP4, 15 GIF
    double speed = 4.0;     ///< simulated seconds per video second
    double trail_s = 10.0;  ///< simulated seconds of trail behind each robot
    /// Videos: the part of the world shown, "XMIN,YMIN,XMAX,YMAX" metres
    /// (render::Viewport::Parse); empty: the arena.
    std::string viewport;
    /// Videos: the steps shown, "FIRST-LAST" (ParseStepRange); empty: the whole run.
    std::string steps;
    bool goals = true;       ///< the config's goals (pictures and videos)
    bool violations = true;  ///< the violations marked (pictures and videos)
    bool robot_ids = true;   ///< videos: each robot's id on its disc
    bool drawings = true;    ///< what the controllers drew (DREAM_DRAW_<id>; pictures and videos)
    /// Videos: frames drawn so far and to draw, after each (RunAnimation::Write).
    std::function<void(int drawn, int total)> progress;
    const std::atomic<bool>* stop = nullptr;  ///< asked between the stages and within the long ones
  };

  /// `dream render`'s argument and options, declared once on `command`, filling
  /// `options`: the command line parses them, and so does dream view's Export
  /// video (OptionsOfCommand), so the page's video is the command it prints.
  static void DeclareOptions(CLI::App& command, Options& options);
  /// The options of `dream render` WORDS... (the words after "dream render"),
  /// parsed as the command line parses them.
  /// @throws std::invalid_argument naming the words and what is wrong with them.
  static Options OptionsOfCommand(const std::vector<std::string>& words);

  /// "FIRST-LAST" (whole steps, "120-480") as {first, last}.
  /// @throws std::invalid_argument naming --steps and the value.
  static std::pair<int64_t, int64_t> ParseStepRange(const std::string& text);

  /// Options that do not go together (--plot with --video, an unknown
  /// extension): the command line's usage, not its input.
  struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  struct Result {
    bool interrupted = false;  ///< a video stopped part way: nothing written
    std::string out;           ///< the file written (or not, when interrupted)
  };

  explicit RenderWorkflow(std::ostream& out = std::cout) : out_(out) {}

  /// @throws UsageError for options that do not go together; std::runtime_error
  ///         (or config::ConfigError) naming the file for input that cannot be
  ///         drawn; files::Stopped when stopped before anything is written.
  Result Render(const Options& options) const;

 private:
  std::ostream& out_;
};

}  // namespace dream::workflows
