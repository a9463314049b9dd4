#include "dream/workflows/sweep_folder.h"
#include "dream/workflows/shell_quoted.h"

#include <sys/stat.h>

#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

#include "dream/formats/sha256.h"
#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/session/run_exit_code.h"
#include "dream/workflows/seed_list.h"
#include "replace_file.h"
#include "run_folder_lock.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxPlanBytes = size_t{256} << 20;
constexpr size_t kMaxSettingsBytes = size_t{16} << 20;

std::string Escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      out += c;
    }
  }
  return out;
}

std::string Unescaped(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\' || i + 1 == text.size()) {
      out += text[i];
      continue;
    }
    const char next = text[++i];
    out += next == 't' ? '\t' : next == 'n' ? '\n' : next == 'r' ? '\r' : next;
  }
  return out;
}

std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (true) {
    const size_t tab = line.find('\t', start);
    fields.push_back(line.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
    if (tab == std::string::npos) return fields;
    start = tab + 1;
  }
}

/// The whole of a sweep file it reads (bounded, regular files only: a FIFO
/// is refused, never waited on), its errors saying which folder was meant.
std::string ReadSweepFile(const std::string& path, size_t max_bytes, const std::string& dir) {
  try {
    return files::ReadFileText(path, max_bytes);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(e.what()) + "; is " + dir + " a sweep folder?");
  }
}

bool ParseIndex(const std::string& text, size_t& value) {
  if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos) return false;
  value = std::stoul(text);
  return true;
}

}  // namespace

const std::vector<std::string>& SweepFolder::RunOutputFiles() {
  static const std::vector<std::string> files = {RunExit::kFileName, "summary.json",   "run.lcmlog",
                                                 "run.lcmlog.part",  "refused.lcmlog", "trajectories.png",
                                                 "output.txt"};
  return files;
}

SweepFolder::SweepFolder(const std::string& dir) : dir_(fs::absolute(dir).lexically_normal().string()) {
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
}

bool SweepFolder::IsRunName(const std::string& name) {
  if (name.empty() || name.size() > 4096 || name == "." || name == "..") return false;
  for (char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
    if (!ok) return false;
  }
  return true;
}

void SweepFolder::CheckFolderPath(const std::string& dir) {
  const std::string path = SweepFolder(dir).dir();
  for (char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      throw std::invalid_argument(
          "--out " + Escaped(dir) +
          ": a sweep folder whose path holds a control character (\\n, \\t, ...) "
          "would split the lines of commands.txt and of any scheduler's; choose another folder");
    }
  }
}

std::string SweepFolder::RunDir(const std::string& run_name) const {
  if (!IsRunName(run_name))
    throw std::invalid_argument("'" + Escaped(run_name.substr(0, 80)) + "' is no run folder name of a sweep");
  return dir_ + "/runs/" + run_name;
}

std::string SweepFolder::RunFolderProblem(const std::string& run_name) const {
  struct stat status {};
  for (const std::string& path : {Path("runs"), RunDir(run_name)}) {
    if (::lstat(path.c_str(), &status) != 0) return "";  // missing: nothing to refuse yet
    if (S_ISLNK(status.st_mode)) return path + " is a symbolic link, not a run folder of this sweep";
    if (!S_ISDIR(status.st_mode)) return path + " is not a folder";
  }
  return "";
}

bool SweepFolder::RunIsLocked(const std::string& run_name) const {
  return RunFolderProblem(run_name).empty() && RunFolderLock::HeldElsewhere(RunDir(run_name));
}

void SweepFolder::WritePlan(const SweepPlan& plan) const {
  std::string text =
      "# dream sweep plan: one line per run (number, folder under runs/, seed, the --set values); "
      "sh run.sh NUMBER runs one\nindex\trun\tseed";
  for (const std::string& key : plan.parameter_keys()) text += "\t" + Escaped(key);
  text += "\n";
  for (const SweepPlan::Run& run : plan.runs()) {
    text += std::to_string(run.index) + "\t" + run.name + "\t" + std::to_string(run.seed);
    for (const auto& parameter : run.parameters) text += "\t" + Escaped(parameter.second);
    text += "\n";
  }
  files::WriteFileAtomically(Path(kPlanFile), text);
}

SweepPlan SweepFolder::ReadPlan() const {
  const std::string path = Path(kPlanFile);
  std::istringstream in(ReadSweepFile(path, kMaxPlanBytes, dir_));
  std::string line;
  size_t number = 0;
  auto bad = [&](const std::string& why) {
    return std::runtime_error(path + ":" + std::to_string(number) + ": " + why);
  };
  std::vector<std::string> keys;
  std::vector<SweepPlan::Run> runs;
  std::set<std::string> names;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = SplitTabs(line);
    if (!header) {
      if (fields.size() < 3 || fields[0] != "index" || fields[1] != "run" || fields[2] != "seed") {
        throw bad("expected the header 'index<TAB>run<TAB>seed...'");
      }
      for (size_t i = 3; i < fields.size(); ++i) keys.push_back(Unescaped(fields[i]));
      header = true;
      continue;
    }
    if (fields.size() != 3 + keys.size()) {
      throw bad("expected " + std::to_string(3 + keys.size()) + " tab-separated fields, got " +
                std::to_string(fields.size()));
    }
    SweepPlan::Run run;
    if (!ParseIndex(fields[0], run.index) || run.index != runs.size()) {
      throw bad("expected run number " + std::to_string(runs.size()) + ", got '" + fields[0].substr(0, 20) + "'");
    }
    if (runs.size() >= kMaxSweepRuns) throw bad("more than " + std::to_string(kMaxSweepRuns) + " runs");
    if (!IsRunName(fields[1]) || !names.insert(fields[1]).second)
      throw bad("'" + fields[1].substr(0, 80) + "' is no run folder name, or a repeated one");
    run.name = fields[1];
    try {
      const std::vector<uint64_t> seed = ParseSeedList(fields[2]);
      if (seed.size() != 1 || fields[2].find_first_of("-,") != std::string::npos)
        throw std::invalid_argument("a range");
      run.seed = seed[0];
    } catch (const std::invalid_argument&) {
      throw bad("'" + fields[2].substr(0, 30) + "' is not a seed");
    }
    for (size_t k = 0; k < keys.size(); ++k) run.parameters.emplace_back(keys[k], Unescaped(fields[3 + k]));
    runs.push_back(std::move(run));
  }
  if (!header) throw std::runtime_error(path + ": no header line; not a sweep plan");
  if (runs.empty()) throw std::runtime_error(path + ": no runs");
  return SweepPlan::FromRuns(std::move(keys), std::move(runs));
}

void SweepFolder::WriteSettings(const nlohmann::json& settings) const {
  files::WriteFileAtomically(Path(kSettingsFile), settings.dump(2) + "\n");
}

nlohmann::json SweepFolder::ReadSettings() const {
  const std::string path = Path(kSettingsFile);
  const std::string text = ReadSweepFile(path, kMaxSettingsBytes, dir_);
  if (text.empty()) throw std::runtime_error(path + ": empty; is " + dir_ + " a sweep folder?");
  nlohmann::json settings = nlohmann::json::parse(text, nullptr, false);
  if (!settings.is_object()) throw std::runtime_error(path + ": not a JSON object; the file is damaged");
  return settings;
}

void SweepFolder::WriteRunScript(const std::string& dream_path) const {
  const std::string plan_sha256 = formats::Sha256::Hex(ReadSweepFile(Path(kPlanFile), kMaxPlanBytes, dir_));
  const std::string text =
      "#!/bin/sh\n"
      "# Generated by dream sweep: `sh run.sh N` runs run N of plan.tsv, the same dream run\n"
      "# the local engine runs, into runs/<run>/ (console output in output.txt), and writes\n"
      "# runs/<run>/exit.txt (exit code, wall time) last: a folder without it holds no finished run.\n"
      "# It holds the run folder's lock (.dream.lock, which its dream run inherits) from before it\n"
      "# clears the folder until exit.txt is written, and refuses a plan.tsv changed since the sweep\n"
      "# was planned, a run name that could leave runs/, a run folder that is a link, a running run.\n"
      "out=" +
      ShellQuoted(dir_) +
      "\n"
      "dream=" +
      ShellQuoted(dream_path) +
      "\n"
      "plan_sha256=" +
      plan_sha256 +
      "\n"
      "case \"${1:-}\" in ''|*[!0-9]*) echo \"run.sh: usage: sh run.sh N (N: a run number of $out/plan.tsv)\" >&2; "
      "exit 2;; esac\n"
      "if [ \"$(sha256sum < \"$out/plan.tsv\" | cut -d ' ' -f 1)\" != \"$plan_sha256\" ]; then\n"
      "  echo \"run.sh: $out/plan.tsv changed since the sweep was planned; run $1 not run\" >&2; exit 2\n"
      "fi\n"
      "name=$(awk -F '\\t' -v i=\"$1\" '$1 == i { print $2; exit }' \"$out/plan.tsv\")\n"
      "if [ -z \"$name\" ]; then echo \"run.sh: no run $1 in $out/plan.tsv\" >&2; exit 2; fi\n"
      "case \"$name\" in .|..|*[!A-Za-z0-9._-]*) echo \"run.sh: run $1 of $out/plan.tsv is named '$name', no run "
      "folder name; not run\" >&2; exit 2;; esac\n"
      "dir=\"$out/runs/$name\"\n"
      "if [ -L \"$out/runs\" ] || [ -L \"$dir\" ] || [ ! -d \"$dir\" ]; then\n"
      "  echo \"run.sh: $dir is not a run folder of this sweep (missing, or a symbolic link); not run\" >&2; exit 2\n"
      "fi\n"
      "cd \"$dir\" || exit 2\n"
      "exec 9>>.dream.lock || exit 2\n"
      "# (waits a little: dream sweep status holds a run's lock for an instant to see whether it runs)\n"
      "if ! flock -w 5 9; then echo \"run.sh: run $name is still running (a process holds $dir/.dream.lock); not "
      "touched\" >&2; exit 75; fi\n"
      "rm -f exit.txt exit.txt.part summary.json run.lcmlog run.lcmlog.part refused.lcmlog trajectories.png "
      "output.txt\n"
      "start=$(date +%s%N)\n"
      "DREAM_OUTPUT_LOCK_FD=9 \"$dream\" run \"$dir/config.yaml\" --out \"$dir\" --private-bus > \"$dir/output.txt\" "
      "2>&1 < /dev/null\n"
      "code=$?\n"
      "end=$(date +%s%N)\n"
      "ms=$(( (end - start) / 1000000 ))\n"
      "printf '%d %d.%03d 0\\n' \"$code\" $((ms / 1000)) $((ms % 1000)) > exit.txt.part && mv -f exit.txt.part "
      "exit.txt\n"
      "exit \"$code\"\n";
  files::WriteFileAtomically(Path(kRunScript), text);
}

std::string SweepFolder::RunCommand(size_t index) const {
  return "/bin/sh " + ShellQuoted(Path(kRunScript)) + " " + std::to_string(index);
}

void SweepFolder::WriteCommands(const std::vector<size_t>& indices) const {
  std::string text;
  for (size_t index : indices) text += RunCommand(index) + "\n";
  files::WriteFileAtomically(Path(kCommandsFile), text);
}

void SweepFolder::ClearRun(const std::string& run_name) const {
  const std::string problem = RunFolderProblem(run_name);
  if (!problem.empty()) throw std::runtime_error("run " + run_name + ": " + problem + "; not touched");
  const RunFolderLock lock(RunDir(run_name));
  if (!lock.held()) {
    throw std::runtime_error("run " + run_name + " is still running (a process holds " + RunDir(run_name) +
                             "/.dream.lock); not touched");
  }
  std::error_code error;
  for (const std::string& file : RunOutputFiles()) fs::remove(RunDir(run_name) + "/" + file, error);
}

void SweepFolder::WriteRunExit(const std::string& run_name, const RunExit& exit) const {
  ReplaceFile(RunDir(run_name) + "/" + RunExit::kFileName, exit.Text());
}

std::optional<RunExit> SweepFolder::ReadRunExit(const std::string& run_name) const {
  const std::string path = RunDir(run_name) + "/" + RunExit::kFileName;
  std::error_code error;
  if (!fs::exists(fs::symlink_status(path, error))) return std::nullopt;
  std::string text;
  try {
    text = files::ReadFileText(path, RunExit::kMaxBytes);
  } catch (const std::runtime_error& e) {
    // Too large to be a record: one that does not parse; anything else (a FIFO, a folder) is named.
    if (fs::is_regular_file(path, error)) return std::nullopt;
    throw;
  }
  return RunExit::Parse(text);
}

SweepRunResult SweepFolder::JudgeRun(const SweepPlan::Run& run, const RunExit& exit) const {
  const std::string dir = RunDir(run.name);
  const bool failed = !session::RanToAVerdict(exit.exit_code) && exit.exit_code != session::kExitInterrupted;
  const std::string hint = !exit.problem.empty() ? exit.problem
                           : failed              ? LastErrorLine(dir + "/output.txt")
                                                 : std::string();
  std::string summary_problem;
  const std::optional<node::RunSummary> summary =
      ReadSummary(dir + "/" + node::RunSummary::kFileName, &summary_problem);
  return SweepRunResult::Judge(run, exit.exit_code, exit.timed_out, exit.wall_time_s, summary, hint, summary_problem);
}

SweepRunResult SweepFolder::CollectRun(const SweepPlan::Run& run, const std::optional<SlurmTaskState>& slurm,
                                       bool folder_busy, bool run_locked) const {
  const std::string dir = RunDir(run.name);
  const std::string problem = RunFolderProblem(run.name);
  if (!problem.empty()) return SweepRunResult::LostRun(run, problem);
  // The lock says it runs, unless Slurm says its task ended: then its processes are only ending (a
  // cancelled task's dream run still writing its log), and Slurm's word is the row; resume leaves
  // the run alone while its lock is held either way.
  const bool ended_in_slurm = slurm && !slurm->Queued();
  if (run_locked && !ended_in_slurm) return SweepRunResult::NotRun(run, std::string(kRunningReason));
  try {
    if (const std::optional<RunExit> exit = ReadRunExit(run.name)) return JudgeRun(run, *exit);
  } catch (const std::runtime_error& e) {
    return SweepRunResult::LostRun(run, std::string("no readable exit record (") + e.what() + ")");
  }
  if (slurm && slurm->Queued()) return SweepRunResult::NotRun(run, slurm->Why());
  if (folder_busy) return SweepRunResult::NotRun(run, "not finished: a dream sweep is working in this folder");
  if (slurm) return SweepRunResult::LostRun(run, slurm->Why());
  std::error_code error;
  for (const char* trace : {"run.lcmlog.part", "run.lcmlog", "summary.json", "output.txt"}) {
    if (fs::exists(dir + "/" + trace, error)) {
      return SweepRunResult::LostRun(
          run, "killed before it ended (" + std::string(trace) + " but no exit.txt; dream sweep resume runs it again)");
    }
  }
  return SweepRunResult::NotRun(run, "never started");
}

std::string SweepFolder::LastErrorLine(const std::string& output_path) {
  std::istringstream in(ReadFileTail(output_path, 64 * 1024));
  std::string line;
  std::string last;
  std::string last_error;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    last = line;
    if (line.find("[error]") != std::string::npos || line.rfind("dream:", 0) == 0) last_error = line;
  }
  std::string chosen = last_error.empty() ? last : last_error;
  // Drop spdlog's "[12:00:00.000] [error] " prefix.
  const size_t bracket = chosen.find("] ", chosen.find("] ") + 2);
  if (chosen.rfind("[", 0) == 0 && bracket != std::string::npos) chosen = chosen.substr(bracket + 2);
  return chosen.size() > 160 ? chosen.substr(0, 157) + "..." : chosen;
}

std::optional<node::RunSummary> SweepFolder::ReadSummary(const std::string& path, std::string* problem) {
  problem->clear();
  std::error_code error;
  if (!fs::exists(fs::symlink_status(path, error))) return std::nullopt;  // the run left none
  try {
    return node::RunSummary::Read(path);
  } catch (const std::runtime_error& e) {
    *problem = e.what();  // too large, no regular file, not JSON, or a field that is wrong
    return std::nullopt;
  }
}

}  // namespace dream::workflows
