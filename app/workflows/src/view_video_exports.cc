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
    // The command the page prints, parsed as `dream render` parses it: one
    // mapping of a request (RenderArguments) to what is drawn. The run after
    // "--", so a path that starts with '-' is not taken for an option.
    std::vector<std::string> typed = request.RenderArguments();
    typed.push_back("--out=" + out);  // one word each, as the run below
    if (!config_path.empty()) typed.push_back("--config=" + config_path);
    typed.insert(typed.end(), {"--", run});
    RenderWorkflow::Options options = RenderWorkflow::OptionsOfCommand(typed);
    options.progress = progress;
    options.stop = &stop;
    std::ostringstream said;  // "video: ..." is the page's to say
    RenderWorkflow(said).Render(options);
  };
  return std::make_shared<view::VideoExports>(std::move(about), std::move(render));
}

}  // namespace dream::workflows
