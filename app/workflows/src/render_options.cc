// dream render's argument and options, declared once: the command line
// parses them and so does dream view's Export video, so a request of the page
// and the command it prints cannot mean different videos.
#include <CLI/CLI.hpp>

#include <stdexcept>

#include "dream/workflows/render_workflow.h"

namespace dream::workflows {

void RenderWorkflow::DeclareOptions(CLI::App& command, Options& options) {
  command.add_option("run", options.run_or_log, "A run folder (its run.lcmlog) or an .lcmlog file")->required();
  command.add_option("--out", options.out, "Output file: .png, .svg, .mp4 or .gif");
  command.add_option("--config", options.config_path,
                     "The run's config, for goals, sensors and radio (default: config.yaml beside the log)");
  command.add_flag("--video", options.video, "Without --out: write run.mp4 beside the log");
  command.add_flag("--plot", options.plot,
                   "Plot the metrics over time (summary.json's series and the closest approach)");
  command.add_option("--metric", options.metrics, "Plot only this series (repeat for more; implies --plot)")
      ->allow_extra_args(false);
  command.add_flag("--radio-links", options.radio_links,
                   "Draw radio broadcasts from sender to the robots that hear it (from the config's radio)");
  command.add_flag("--sensor-ranges", options.sensor_ranges,
                   "Draw the reach of the movement/obstacle sensors round each robot");
  command
      .add_option("--width", options.width_px, "Width in pixels (default 1280 picture, 1000 plot, 720 MP4, 480 GIF)")
      ->check(CLI::Range(160, 8192));
  command.add_option("--fps", options.fps, "Video frames per second (default 30 MP4, 15 GIF)")
      ->check(CLI::Range(1.0, 120.0));
  command.add_option("--speed", options.speed, "Simulated seconds per video second")
      ->check(CLI::Range(0.01, 10000.0))
      ->capture_default_str();
  // Its check is the command line's (cli's Seconds, shared by its commands).
  command.add_option("--trail", options.trail_s, "Seconds of simulated time drawn behind each robot")
      ->capture_default_str();
  command.add_option("--viewport", options.viewport,
                     "Video: show this part of the world, XMIN,YMIN,XMAX,YMAX in metres (zoomed to fit; "
                     "dream view's Export video gives it)");
  command.add_option("--steps", options.steps, "Video: only these steps, FIRST-LAST (e.g. 120-480)");
  command.add_flag("--no-goals{false}", options.goals, "Leave out the config's goals");
  command.add_flag("--no-violations{false}", options.violations, "Leave out the violation marks");
  command.add_flag("--no-ids{false}", options.robot_ids, "Video: leave out the robots' ids");
  command.add_flag("--no-drawings{false}", options.drawings,
                   "Leave out what the controllers drew (DREAM_DRAW_<id>: self.draw_*, drawing())");
}

RenderWorkflow::Options RenderWorkflow::OptionsOfCommand(const std::vector<std::string>& words) {
  Options options;
  CLI::App command("dream render", "render");
  DeclareOptions(command, options);
  std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 takes them last first
  try {
    command.parse(reversed);
  } catch (const CLI::ParseError& e) {
    std::string typed = "dream render";
    for (const std::string& word : words) typed += " " + word;
    throw std::invalid_argument(typed + ": " + e.what());
  }
  return options;
}

}  // namespace dream::workflows
