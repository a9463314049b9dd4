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
  // Declared in the workflow: dream view's Export video parses the same options.
  workflows::RenderWorkflow::DeclareOptions(*command, *args);
  command->get_option("--trail")->check(Seconds(true));
}

}  // namespace dream::cli
