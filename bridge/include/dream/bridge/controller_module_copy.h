#pragma once

#include "dream/run_config/run_config.h"
#include "dream/files/output_folder.h"

namespace dream::bridge {

/// Copies the file a kind's section names by its ControllerKind::file_key (the
/// python kind's `module`) into `out` at the path the config names it by, when
/// that path is relative (it then stays inside the config's folder:
/// config::FileBesideConfig refuses others), so that the copy of the config in
/// `out` finds it: `dream run` keeps the module in the run folder this way,
/// and export and import do the same, so `dream lab-replay` of an imported run
/// runs the same controller. Kinds without a file, and absolute paths, need
/// nothing.
/// @throws config::ConfigError when the module cannot be read.
void KeepControllerModule(const run_config::RunConfig& config, const files::OutputFolder& out);

/// The same for a realism file (`world.realism: {file: PATH}`), at
/// run_config::RealismFileInRunFolder (a relative path as written, an
/// absolute one under realism/), so the run folder's config.yaml (which
/// RunFolderConfigText points at the copy) finds its lab model on its own.
void KeepRealismFile(const run_config::RunConfig& config, const files::OutputFolder& out);

}  // namespace dream::bridge
