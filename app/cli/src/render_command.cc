// dream render: pictures, videos and metric plots of a recorded run
// (docs/rendering.md). The work is workflows::RenderWorkflow's; this file is
// options, messages and exit codes.
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "dream/workflows/render_workflow.h"
#include "shared_options.h"

namespace dream::cli {

namespace {

int RunRender(workflows::RenderWorkflow::Options options) {
  options.stop = &StopFlag();
  workflows::RenderWorkflow::Result result;
  try {
    result = workflows::RenderWorkflow().Render(options);
  } catch (const workflows::RenderWorkflow::UsageError& e) {
    std::cerr << "dream: " << e.what() << " (dream render --help)\n";
    return kExitUsage;
  }
  if (result.interrupted) {
    std::cerr << "dream: interrupted; " << result.out << " not written\n";
    return kExitInterrupted;
  }
  return kExitOk;
}

}  // namespace

void DeclareRenderCommand(CommandLine& line) {
  const auto [command, args] = line.AddCommand<workflows::RenderWorkflow::Options>(
      "render",
      "Draw a recorded run (simulated or imported from the lab): the arena with trajectories, obstacles,\n"
      "goals and final poses (.png/.svg), a video of the run (.mp4/.gif, needs ffmpeg), or the metrics\n"
      "over time (--plot). --out's extension picks; without --out: trajectories.svg, run.mp4 (--video)\n"
      "or metrics.png (--plot) beside the log.\n"
      "Example: dream render runs/hrvo_circle --out runs/hrvo_circle/run.mp4 --radio-links",
      RunRender);
  AddRunLogArgument(command, "run", &args->run_or_log);
  command->add_option("--out", args->out, "Output file: .png, .svg, .mp4 or .gif");
  command->add_option("--config", args->config_path,
                      "The run's config, for goals, sensors and radio (default: config.yaml beside the log)");
  command->add_flag("--video", args->video, "Without --out: write run.mp4 beside the log");
  command->add_flag("--plot", args->plot,
                    "Plot the metrics over time (summary.json's series and the closest approach)");
  command->add_option("--metric", args->metrics, "Plot only this series (repeat for more; implies --plot)")
      ->allow_extra_args(false);
  command->add_flag("--radio-links", args->radio_links,
                    "Draw radio broadcasts from sender to the robots that hear it (from the config's radio)");
  command->add_flag("--sensor-ranges", args->sensor_ranges,
                    "Draw the reach of the movement/obstacle sensors round each robot");
  command->add_option("--width", args->width_px, "Width in pixels (default 1280 picture, 1000 plot, 720 MP4, 480 GIF)")
      ->check(CLI::Range(160, 8192));
  command->add_option("--fps", args->fps, "Video frames per second (default 30 MP4, 15 GIF)")
      ->check(CLI::Range(1.0, 120.0));
  command->add_option("--speed", args->speed, "Simulated seconds per video second")
      ->check(CLI::Range(0.01, 10000.0))
      ->capture_default_str();
  command->add_option("--trail", args->trail_s, "Seconds of simulated time drawn behind each robot")
      ->check(Seconds(true))
      ->capture_default_str();
  command->add_option("--viewport", args->viewport,
                      "Video: show this part of the world, XMIN,YMIN,XMAX,YMAX in metres (zoomed to fit; "
                      "dream view's Export video gives it)");
  command->add_option("--steps", args->steps, "Video: only these steps, FIRST-LAST (e.g. 120-480)");
  command->add_flag("--no-goals{false}", args->goals, "Leave out the config's goals");
  command->add_flag("--no-violations{false}", args->violations, "Leave out the violation marks");
  command->add_flag("--no-ids{false}", args->robot_ids, "Video: leave out the robots' ids");
  command->add_flag("--no-drawings{false}", args->drawings,
                    "Leave out what the controllers drew (DREAM_DRAW_<id>: self.draw_*, drawing())");
}

}  // namespace dream::cli
