#include "sweep_inputs.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "dream/formats/sha256.h"
#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"

namespace dream::workflows {
namespace {

constexpr size_t kMaxRecordBytes = 64 * 1024;

std::string Digest(const std::string& path) { return formats::Sha256::Hex(files::ReadFileText(path)); }

/// A path on one line of the record (sha256sum's format has no room for a newline in it).
std::string OneLine(std::string path) {
  for (char& c : path) {
    if (c == '\n' || c == '\r') c = '?';
  }
  return path;
}

bool IsDigest(const std::string& text) {
  return text.size() == 64 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

}  // namespace

void SweepInputs::Record(const SweepFolder& folder, const std::string& config_path) {
  const std::string absolute = std::filesystem::absolute(config_path).lexically_normal().string();
  const std::string text = Digest(absolute) + "  " + OneLine(absolute) + "\n" +
                           Digest(folder.Path(SweepFolder::kSettingsFile)) + "  " + SweepFolder::kSettingsFile + "\n" +
                           Digest(folder.Path(SweepFolder::kPlanFile)) + "  " + SweepFolder::kPlanFile + "\n";
  files::WriteFileAtomically(folder.Path(kFileName), text);
}

std::vector<std::string> SweepInputs::Changed(const SweepFolder& folder, const std::string& config_path,
                                              std::string* unchecked) {
  const std::string record_path = folder.Path(kFileName);
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(record_path, error))) {
    if (unchecked != nullptr)
      *unchecked = "no " + std::string(kFileName) + " (a sweep planned by an older dream): its inputs are not checked";
    return {};
  }
  // Line 1: the base config, 2: sweep.json, 3: plan.tsv, as Record writes them.
  std::vector<std::string> recorded;
  std::istringstream lines(files::ReadFileText(record_path, kMaxRecordBytes));
  for (std::string line; std::getline(lines, line);) {
    const std::string digest = line.substr(0, 64);
    if (!IsDigest(digest) || line.compare(64, 2, "  ") != 0) break;
    recorded.push_back(digest);
  }
  if (recorded.size() != 3) throw std::runtime_error(record_path + ": damaged (expected three 'SHA256  FILE' lines)");

  std::vector<std::string> changed;
  try {
    if (Digest(config_path) != recorded[0]) changed.push_back("the base config " + config_path);
  } catch (const std::runtime_error& e) {
    if (unchecked != nullptr) *unchecked = "the base config could not be checked (" + std::string(e.what()) + ")";
  }
  const std::pair<const char*, const std::string*> files[] = {{SweepFolder::kSettingsFile, &recorded[1]},
                                                              {SweepFolder::kPlanFile, &recorded[2]}};
  for (const auto& [name, digest] : files) {
    if (Digest(folder.Path(name)) != *digest) changed.push_back(name);
  }
  return changed;
}

}  // namespace dream::workflows
