#pragma once

#include <memory>
#include <string>

#include "dream/view/video_exports.h"
#include "dream/workflows/view_replay.h"

namespace dream::workflows {

/// The video exports of a replayed run (`dream view RUN`, `dream run --view`
/// at the run's end): each drawn by RenderWorkflow, as `dream render RUN`
/// with the request's options draws it (the page prints that command).
/// `run` and `config_path` as given to the view ("" : config.yaml beside the log).
std::shared_ptr<view::VideoExports> VideoExportsOfRun(const ViewReplay& replay, const std::string& run,
                                                      const std::string& config_path);

}  // namespace dream::workflows
