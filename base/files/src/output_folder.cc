#include "dream/files/output_folder.h"

#include <filesystem>
#include <stdexcept>

#include "dream/files/atomic_file.h"

namespace dream::files {
namespace fs = std::filesystem;
namespace {

// Throws when `name` is not a plain relative path that stays below its
// folder (empty, absolute, "..", or a NUL byte).
void CheckRelativeName(const std::string& name) {
  if (name.empty() || name.find('\0') != std::string::npos) {
    throw std::runtime_error("refusing to write a file with an empty or binary name");
  }
  const fs::path path(name);
  if (path.is_absolute() || path.has_root_name() || path.has_root_directory()) {
    throw std::runtime_error("refusing to write " + name + ": an absolute path would escape the output folder");
  }
  for (const fs::path& part : path) {
    if (part == "..") throw std::runtime_error("refusing to write " + name + ": '..' would escape the output folder");
  }
}

// True for runs/, sweeps/ or exports/ of the working folder, however written.
bool IsToolFolder(const fs::path& parent) {
  const fs::path plain = parent.lexically_normal();
  for (const char* name : OutputFolder::kToolFolders) {
    if (plain == fs::path(name) || plain == fs::path(name) / "") return true;
  }
  return false;
}

}  // namespace

OutputFolder::OutputFolder(std::string dir, Parents parents) : dir_(std::move(dir)) {
  if (dir_.empty()) throw std::runtime_error("the output folder name is empty");
  fs::path out(dir_);
  if (!out.has_filename() && out.has_parent_path()) out = out.parent_path();  // "runs/x/" is runs/x
  dir_ = out.string();
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code error;
  if (parents == Parents::kCreate || (!fs::exists(parent) && IsToolFolder(parent))) {
    fs::create_directories(out, error);
  } else if (!fs::is_directory(parent)) {
    throw std::runtime_error("output folder " + dir_ + ": its parent " +
                             (fs::exists(parent) ? parent.string() + " is a file, not a folder"
                                                 : "folder " + parent.string() + " does not exist"));
  } else {
    fs::create_directory(out, error);
  }
  if (error || !fs::is_directory(out)) {
    if (fs::exists(out) && !fs::is_directory(out)) {
      throw std::runtime_error("output folder " + dir_ + ": is a file, not a folder");
    }
    throw std::runtime_error("cannot create the output folder " + dir_ +
                             (error ? ": " + error.message() : std::string()));
  }
  real_dir_ = fs::canonical(out, error).string();
  if (error) throw std::runtime_error("cannot resolve the output folder " + dir_ + ": " + error.message());
}

std::string OutputFolder::PathOf(const std::string& name) const {
  CheckRelativeName(name);
  const fs::path path = fs::path(dir_) / name;
  std::error_code error;
  const fs::path real = fs::weakly_canonical(path, error);
  if (error) throw std::runtime_error("cannot resolve " + path.string() + ": " + error.message());
  const std::string real_text = real.string();
  if (real_text.size() <= real_dir_.size() || real_text.compare(0, real_dir_.size(), real_dir_) != 0 ||
      real_text[real_dir_.size()] != '/') {
    throw std::runtime_error("refusing to write " + path.string() + ": it resolves to " + real_text +
                             ", outside the output folder " + real_dir_ + " (a symbolic link?)");
  }
  return path.string();
}

std::string OutputFolder::MakeSubfolder(const std::string& name) const {
  const std::string path = PathOf(name);
  std::error_code error;
  fs::create_directory(path, error);
  if (error || !fs::is_directory(path)) {
    const bool in_the_way = fs::exists(fs::symlink_status(path));
    throw std::runtime_error("cannot create the folder " + path + ": " +
                             (in_the_way ? "a file of that name is in the way; move it or choose another output folder"
                              : error    ? error.message()
                                         : std::string("it is no folder")));
  }
  PathOf(name);  // a link created meanwhile must not lead out either
  return path;
}

void OutputFolder::RemoveFiles(const std::string& why) const {
  for (const fs::directory_entry& entry : fs::directory_iterator(real_dir_)) {
    if (!entry.is_regular_file()) continue;
    std::error_code error;
    fs::remove(entry.path(), error);
    if (error) throw std::runtime_error(entry.path().string() + ": cannot remove " + why + ": " + error.message());
  }
}

void OutputFolder::WriteFile(const std::string& name, const std::string& bytes) const {
  WriteFileAtomically(PathOf(name), bytes);
}

void OutputFolder::WriteFileInSubfolders(const std::string& name, const std::string& bytes) const {
  fs::path folder;
  for (const auto& part : fs::path(name).parent_path()) MakeSubfolder((folder /= part).string());
  WriteFile(name, bytes);
}

}  // namespace dream::files
