#include "dream/files/run_folder_choice.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <stdexcept>

#include "dream/files/output_folder.h"
#include "dream/files/output_folder_lock.h"

namespace dream::files {
namespace fs = std::filesystem;
namespace {

// The files a run and the commands on it write into its folder (run, import,
// check-submission, render and compare without --out): --overwrite removes
// them all, so none of the earlier run's can pass for the new one's.
constexpr const char* kRunFiles[] = {"run.lcmlog",       "run.lcmlog.part", "summary.json", "trajectories.png",
                                     "trajectories.svg", "run.mp4",         "run.gif",      "metrics.png",
                                     "comparison.json",  "comparison.png",  "check.json",   "check_report.json",
                                     "refused.lcmlog"};

// The log a run leaves when it is killed before it ends (kill -9, a power
// cut): every event up to its last flush, the last one possibly cut. It is
// a run's data, so a folder holding one holds a run (a rerun truncated it).
constexpr const char* kUnfinishedLog = "run.lcmlog.part";

bool IsFile(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

// Why `dir`, which HoldsRun, cannot be written without --overwrite.
std::string HeldRun(const std::string& dir) {
  const fs::path part = fs::path(dir) / kUnfinishedLog;
  if (IsFile(fs::path(dir) / "run.lcmlog") || IsFile(fs::path(dir) / "summary.json") || !IsFile(part)) {
    return "--out " + dir +
           " already holds a run (run.lcmlog or summary.json); pass --overwrite to replace it, or "
           "another --out";
  }
  std::error_code error;
  const uintmax_t bytes = fs::file_size(part, error);
  return "--out " + dir + " holds " + part.string() + (error ? "" : " (" + std::to_string(bytes) + " bytes)") +
         ", the log of a run that did not end (killed?), every event it wrote until then. To keep it, move it out "
         "of the folder; --overwrite deletes it; or choose another --out";
}

void RemoveEarlierRun(const std::string& dir) {
  for (const char* name : kRunFiles) {
    std::error_code error;
    fs::remove(fs::path(dir) / name, error);
    if (error)
      throw std::runtime_error("--overwrite: cannot remove " + (fs::path(dir) / name).string() + ": " +
                               error.message());
  }
}

}  // namespace

bool RunFolderChoice::HoldsRun(const std::string& dir) {
  // Files only: anything else by those names is no run's output (and the
  // run will fail to write there, saying so).
  return IsFile(fs::path(dir) / "run.lcmlog") || IsFile(fs::path(dir) / "summary.json") ||
         IsFile(fs::path(dir) / kUnfinishedLog);
}

RunFolderChoice::RunFolderChoice(const std::string& out, const std::string& default_dir, bool overwrite,
                                 Create create) {
  if (!out.empty()) {
    // Locked before its run is looked at or removed: a run writing it refuses this one.
    if (fs::is_directory(out)) files::OutputFolderLock::HoldUntilExit(out);
    if (HoldsRun(out)) {
      if (!overwrite) throw std::runtime_error(HeldRun(out));
      spdlog::info("--overwrite: replacing the run in {}", out);
      RemoveEarlierRun(out);
    }
    dir_ = create == Create::kNow ? files::OutputFolder(out).dir() : out;
    if (create == Create::kNow) files::OutputFolderLock::HoldUntilExit(dir_);
    return;
  }
  std::string chosen = default_dir;
  if (overwrite) {
    if (fs::is_directory(default_dir)) files::OutputFolderLock::HoldUntilExit(default_dir);
    if (HoldsRun(default_dir)) {
      spdlog::info("--overwrite: replacing the run in {}", default_dir);
      RemoveEarlierRun(default_dir);
    }
  } else {
    // A folder is taken once it holds a run or another process writes it; an
    // empty one (a run that failed before starting) is reused.
    for (int n = 2;
         HoldsRun(chosen) || (fs::is_directory(chosen) && !files::OutputFolderLock::TryHoldUntilExit(chosen)); ++n) {
      chosen = default_dir + "_" + std::to_string(n);
    }
    renamed_ = chosen != default_dir;
  }
  if (create == Create::kNow) {
    dir_ = files::OutputFolder(chosen, files::OutputFolder::Parents::kCreate).dir();
    files::OutputFolderLock::HoldUntilExit(dir_);
  } else {
    std::error_code error;  // a failure shows when the folder is made
    fs::create_directories(fs::path(chosen).parent_path(), error);
    dir_ = chosen;
  }
  if (renamed_) {
    spdlog::warn(
        "{} holds an earlier run (or one being written), so this one goes to {} (--out DIR to choose, "
        "--overwrite to replace)",
        default_dir, dir_);
  }
}

}  // namespace dream::files
