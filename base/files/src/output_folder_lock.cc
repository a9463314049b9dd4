#include "dream/files/output_folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "dream/files/regular_file.h"

namespace dream::files {
namespace {

namespace fs = std::filesystem;

std::mutex held_mutex;
std::map<std::string, int>& HeldLocks() {  // canonical folder -> descriptor, kept open until exit
  static auto* held = new std::map<std::string, int>();
  return *held;
}

std::string CanonicalFolder(const std::string& dir) {
  std::error_code error;
  const fs::path canonical = fs::canonical(dir, error);
  if (error || !fs::is_directory(canonical)) {
    throw std::runtime_error("cannot lock the output folder " + dir + ": " +
                             (error ? error.message() : std::string("not a folder")));
  }
  return canonical.string();
}

/// This process's command line, arguments joined by spaces.
std::string CommandLine() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  while (!text.empty() && text.back() == '\0') text.pop_back();
  for (char& c : text) {
    if (c == '\0' || c == '\n') c = ' ';
  }
  if (text.size() > 300) text = text.substr(0, 300) + "...";
  return text;
}

/// The descriptor inherited from a parent holding the lock file `lock_path`, or -1.
int InheritedDescriptor(const std::string& lock_path) {
  const char* text = std::getenv(OutputFolderLock::kInheritedVariable);
  if (text == nullptr || *text == '\0') return -1;
  char* end = nullptr;
  const long fd = std::strtol(text, &end, 10);
  if (*end != '\0' || fd < 0 || fd > 1 << 20) return -1;
  struct stat inherited {};
  struct stat wanted {};
  if (::fstat(static_cast<int>(fd), &inherited) != 0 || ::stat(lock_path.c_str(), &wanted) != 0) return -1;
  if (inherited.st_dev != wanted.st_dev || inherited.st_ino != wanted.st_ino) return -1;
  // The same open file as the parent's, so this succeeds while the parent holds it.
  if (::flock(static_cast<int>(fd), LOCK_EX | LOCK_NB) != 0) return -1;
  ::fcntl(static_cast<int>(fd), F_SETFD, FD_CLOEXEC);
  return static_cast<int>(fd);
}

std::string HolderText(const std::string& lock_path) {
  constexpr std::uintmax_t kMaxHolderBytes = 4096;  // a pid and a command line cut at 300 characters
  std::istringstream in;
  try {
    in.str(RegularFile(lock_path).ReadAll(kMaxHolderBytes));  // a FIFO there is refused, not read forever
  } catch (const std::runtime_error&) {
    return "another process";
  }
  std::string pid;
  std::string command;
  std::getline(in, pid);
  std::getline(in, command);
  if (pid.empty()) return "another process";
  return "pid " + pid + (command.empty() ? std::string() : " (" + command + ")");
}

/// Locks `dir`; false when another process holds it.
bool Lock(const std::string& dir, std::string* holder) {
  const std::string folder = CanonicalFolder(dir);
  const std::lock_guard<std::mutex> guard(held_mutex);
  if (HeldLocks().count(folder) != 0) return true;
  const std::string lock_path = folder + "/" + OutputFolderLock::kFileName;
  int fd = InheritedDescriptor(lock_path);
  if (fd >= 0) {
    HeldLocks()[folder] = fd;
    return true;
  }
  fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) {
    throw std::runtime_error("cannot lock the output folder " + dir + ": " + lock_path + ": " + std::strerror(errno));
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error != EWOULDBLOCK) {
      throw std::runtime_error("cannot lock the output folder " + dir + ": " + std::strerror(error));
    }
    *holder = HolderText(lock_path);
    return false;
  }
  const std::string text = std::to_string(::getpid()) + "\n" + CommandLine() + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
    // The lock holds without the note; a second run then names no process.
  }
  HeldLocks()[folder] = fd;
  return true;
}

}  // namespace

void OutputFolderLock::HoldUntilExit(const std::string& dir) {
  std::string holder;
  if (!Lock(dir, &holder)) {
    throw std::runtime_error("output folder " + dir + " is being written by " + holder +
                             "; wait for it to end, or choose another --out");
  }
}

bool OutputFolderLock::TryHoldUntilExit(const std::string& dir) {
  std::string holder;
  return Lock(dir, &holder);
}

int OutputFolderLock::DescriptorOf(const std::string& dir) {
  std::error_code error;
  const std::string folder = fs::canonical(dir, error).string();
  if (error) return -1;
  const std::lock_guard<std::mutex> guard(held_mutex);
  const auto it = HeldLocks().find(folder);
  return it == HeldLocks().end() ? -1 : it->second;
}

}  // namespace dream::files
