#pragma once
// Helpers shared by the bridge's tests: in-process runs through the same code
// as `dream run` (ControllerFactory -> AgentHost on memq://, SimNode,
// RunRecorder), with the world passed in, and lab results made from a run.

#include <functional>
#include <string>
#include <vector>

#include "dream/formats/npy_file.h"
#include "dream/bridge/run_track.h"
#include "dream/run_config/run_config.h"
#include "dream/node/run_outcome.h"
#include "dream/world/world.h"

namespace dream::bridge::testing {

std::string ReadText(const std::string& path);
void WriteText(const std::string& path, const std::string& text);

/// A fresh empty folder under the test temp dir (one set per process).
std::string NewFolder(const std::string& name);

/// The text of config/<name>.yaml.
std::string ShippedConfig(const std::string& name);

/// The config in `text` (as if read from <source>).
run_config::RunConfig LoadConfigText(const std::string& text, const std::string& source = "test.yaml");

/// Runs the config's agents against `world` on memq:// and records the run
/// to log_path: exactly what `dream run` does, with any World.
node::RunOutcome RunAgainst(world::World& world, const run_config::RunConfig& config, const std::string& log_path);

/// A run folder as `dream run` writes it (run.lcmlog, config.yaml) for the
/// config text, simulated with UnicycleWorld.
std::string MakeRunFolder(const std::string& name, const std::string& config_text);

/// The rows a perfect lab would save for the export in export_dir: no
/// settle steps, the recorded poses and commands, 0.033 s stamps; `perturb`
/// may change each row (row index, values) before it is stored.
formats::NpyArray PerfectLabResult(const std::string& export_dir,
                                   const std::function<void(int64_t, double*)>& perturb = nullptr);

/// Every file name in a folder (recursively, relative), sorted.
std::vector<std::string> FilesIn(const std::string& dir);

}  // namespace dream::bridge::testing
