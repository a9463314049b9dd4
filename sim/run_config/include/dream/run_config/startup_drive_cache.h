#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/startup_drive_trials.h"
#include "dream/world/world_params.h"

namespace dream::run_config {

/// The start-up drive's trials of one set of start poses, kept so that
/// repeat runs, exports and tests of the same start poses skip the drives
/// (0.1-1 s of CPU each time, docs/performance.md): one small JSON file per
/// key under the user's cache folder, written atomically, read strictly
/// (a file that is not exactly what Store writes is ignored with a warning
/// naming it, and the drives run again). The key is everything a drive
/// depends on: the world's parameters (arena, time step, wheels, collision
/// rule), the start poses (to the bit), the placement seeds and the drive's
/// revision (world::StartupDrive::kRevision); the drive ignores virtual
/// obstacles, as rps's does, so they are no part of it.
class StartupDriveCache {
 public:
  /// Bytes of a cache file read at most (one holds at most a few KiB).
  static constexpr std::uintmax_t kMaxFileBytes = 1 << 20;

  /// $DREAM_CACHE_DIR if set (empty: no cache), else $XDG_CACHE_HOME/dream,
  /// else $HOME/.cache/dream; "" when none of them is set.
  static std::string DefaultFolder();

  /// A cache in `folder` (made when first stored into); "" keeps nothing.
  explicit StartupDriveCache(std::string folder);

  /// The trials of `start_poses` from `seeds`, from the cache when it has
  /// them, else run (world::StartupDriveTrials::Try) and stored.
  world::StartupDriveTrials Trials(const world::WorldParams& world, const std::vector<world::Pose2>& start_poses,
                                   uint64_t run_seed) const;

  /// The text the key is made of (exact: hex floats), and its file.
  static std::string KeyText(const world::WorldParams& world, const std::vector<world::Pose2>& start_poses,
                             const std::vector<uint64_t>& seeds);
  std::string FileOf(const std::string& key_text) const;

  /// What the cache holds for `key_text`; none when nothing, or when the
  /// file is not a whole entry of this key (then warned about, naming it).
  std::optional<world::StartupDriveTrials> Find(const std::string& key_text) const;
  /// Keeps `trials` for `key_text`, atomically; a failure is warned about, not thrown.
  void Store(const std::string& key_text, const world::StartupDriveTrials& trials) const;

 private:
  std::string folder_;
};

}  // namespace dream::run_config
