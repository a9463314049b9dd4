#include "dream/workflows/slurm_jobs.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "replace_file.h"

namespace dream::workflows {
namespace {

constexpr size_t kMaxJobsFileBytes = 1 << 20;
constexpr size_t kMaxJobs = 10000;
constexpr size_t kLogTailBytes = 4096;

bool IsJobId(const std::string& text) {
  return !text.empty() && text.size() <= 20 && text.find_first_not_of("0123456789") == std::string::npos;
}

std::string JoinedIds(const std::vector<std::string>& ids) {
  std::string joined;
  for (const std::string& id : ids) joined += (joined.empty() ? "" : ",") + id;
  return joined;
}

}  // namespace

SlurmJobs::SlurmJobs(const SweepFolder& folder) : folder_(folder) {
  const std::string path = folder_.Path(kJobsFile);
  std::error_code error;
  // No jobs.txt: no job was submitted. One that is there is read bounded, a FIFO refused.
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return;
  const std::string text = files::ReadFileText(path, kMaxJobsFileBytes);
  std::istringstream in(text);
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string kind;
    std::string id;
    fields >> kind >> id;
    size_t offset = 0;
    const bool ok =
        IsJobId(id) && ((kind == "array" && (fields >> offset) && offset < (size_t{1} << 30)) || kind == "table");
    if (!ok || arrays_.size() + table_jobs_.size() >= kMaxJobs) {
      throw std::runtime_error(path + ":" + std::to_string(number) +
                               ": expected 'array JOBID OFFSET' or 'table JOBID'");
    }
    if (kind == "array") {
      arrays_.push_back({id, offset});
    } else {
      table_jobs_.push_back(id);
    }
  }
}

void SlurmJobs::RecordArray(const ArrayJob& job) {
  arrays_.push_back(job);
  Write();
}

void SlurmJobs::RecordTableJob(const std::string& job_id) {
  table_jobs_.push_back(job_id);
  Write();
}

void SlurmJobs::Write() const {
  std::string text =
      "# dream sweep's Slurm jobs, oldest first: 'array JOBID OFFSET' (task T runs run OFFSET+T), 'table JOBID'\n";
  for (const ArrayJob& job : arrays_) text += "array " + job.job_id + " " + std::to_string(job.offset) + "\n";
  for (const std::string& id : table_jobs_) text += "table " + id + "\n";
  files::WriteFileAtomically(folder_.Path(kJobsFile), text);
}

std::optional<std::string> SlurmJobs::ParseJobId(const std::string& sbatch_output) {
  std::istringstream in(sbatch_output);
  std::string line;
  while (std::getline(in, line)) {
    const std::string id = line.substr(0, line.find(';'));
    if (IsJobId(id)) return id;
  }
  return std::nullopt;
}

void SlurmJobs::ApplyListing(const std::string& listing, std::map<size_t, SlurmTaskState>& states) const {
  std::istringstream in(listing);
  std::string line;
  while (std::getline(in, line)) {
    const size_t bar = line.find('|');
    const size_t underscore = line.find('_');
    if (bar == std::string::npos || underscore == std::string::npos || underscore > bar) continue;
    const std::string job = line.substr(0, underscore);
    const std::string task = line.substr(underscore + 1, bar - underscore - 1);
    if (!IsJobId(job) || !IsJobId(task) || task.size() > 9) continue;  // "123_[4-9%2]": not one task
    for (const ArrayJob& array : arrays_) {
      if (array.job_id != job) continue;
      if (auto state = SlurmTaskState::FromSlurmWord(line.substr(bar + 1)))
        states[array.offset + std::stoul(task)] = *state;
    }
  }
}

std::map<size_t, SlurmTaskState> SlurmJobs::TaskStates(CommandRunner* commands, std::string* queue_note) const {
  std::map<size_t, SlurmTaskState> states;
  if (arrays_.empty()) return states;
  // The logs: slurm/<job>_<task>.out, as the array job's --output names them.
  for (const ArrayJob& array : arrays_) {
    const std::string prefix = array.job_id + "_";
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder_.Path("slurm"), error)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(prefix, 0) != 0 || name.size() < prefix.size() + 5 || name.substr(name.size() - 4) != ".out")
        continue;
      const std::string task = name.substr(prefix.size(), name.size() - 4 - prefix.size());
      if (!IsJobId(task) || task.size() > 9) continue;
      if (auto state = SlurmTaskState::FromTaskLog(ReadFileTail(entry.path().string(), kLogTailBytes))) {
        states[array.offset + std::stoul(task)] = *state;
      }
    }
  }
  if (commands == nullptr) return states;
  std::vector<std::string> ids;
  for (const ArrayJob& array : arrays_) ids.push_back(array.job_id);
  const std::string joined = JoinedIds(ids);
  // sacct fails where the cluster keeps no accounting; the logs stand then.
  const CommandRunner::Result sacct = commands->Run(
      {"sacct", "--noheader", "--parsable2", "--allocations", "--jobs=" + joined, "--format=JobID,State"});
  if (sacct.exit_code == 0) ApplyListing(sacct.output, states);
  const CommandRunner::Result squeue =
      commands->Run({"squeue", "--noheader", "--array", "--jobs=" + joined, "--format=%i|%T"});
  if (squeue.exit_code == 0) {
    ApplyListing(squeue.output, states);
  } else if (squeue.output.find("Invalid job id") == std::string::npos && queue_note != nullptr) {
    // (Slurm forgets ended jobs after MinJobAge: "Invalid job id" means none is queued.)
    *queue_note = "squeue failed (" +
                  (squeue.output.empty() ? "exit " + std::to_string(squeue.exit_code) : squeue.output.substr(0, 200)) +
                  ")";
  }
  return states;
}

}  // namespace dream::workflows
