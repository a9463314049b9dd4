#include "dream/workflows/view_video_exports.h"

#include <filesystem>
#include <sstream>
#include <vector>

#include "dream/workflows/render_workflow.h"
#include "dream/workflows/shell_quoted.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

// The run's folder name ("go_to_goal"), or a log's stem: the download's name.
std::string RunNameOf(const std::string& run) {
  const fs::path path = fs::path(run).lexically_normal();
  const fs::path named = path.filename().empty() ? path.parent_path() : path;
  return named.extension() == ".lcmlog" ? named.stem().string() : named.filename().string();
}

RenderWorkflow::Options RenderOptionsOf(const view::VideoExportRequest& request, const std::string& run,
                                        const std::string& config_path, const std::string& out) {
  RenderWorkflow::Options options;
  options.run_or_log = run;
  options.out = out;
  options.config_path = config_path;
  options.width_px = request.width_px;
  options.fps = request.fps;
  options.speed = request.speed;
  options.trail_s = request.trail_s;
  if (request.viewport) options.viewport = request.viewport->Text();
  if (request.first_step >= 0) {
    options.steps = std::to_string(request.first_step) + "-" + std::to_string(request.last_step);
  }
  options.goals = request.goals;
  options.violations = request.violations;
  options.robot_ids = request.robot_ids;
  options.drawings = request.drawings;
  options.radio_links = request.radio_links;
  options.sensor_ranges = request.sensor_ranges;
  return options;
}

}  // namespace

std::shared_ptr<view::VideoExports> VideoExportsOfRun(const ViewReplay& replay, const std::string& run,
                                                      const std::string& config_path) {
  view::VideoExports::Run about;
  about.name = RunNameOf(run);
  std::vector<std::string> command = {"dream", "render", run};
  if (!config_path.empty()) command.insert(command.end(), {"--config", config_path});
  about.render_command = ShellCommandLine(command);
  about.first_step = replay.first_step;
  about.last_step = replay.last_step;
  auto render = [run, config_path](const view::VideoExportRequest& request, const std::string& out,
                                   const std::function<void(int, int)>& progress, const std::atomic<bool>& stop) {
    RenderWorkflow::Options options = RenderOptionsOf(request, run, config_path, out);
    options.progress = progress;
    options.stop = &stop;
    std::ostringstream said;  // "video: ..." is the page's to say
    RenderWorkflow(said).Render(options);
  };
  return std::make_shared<view::VideoExports>(std::move(about), std::move(render));
}

}  // namespace dream::workflows
