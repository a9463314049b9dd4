#include "run_folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "dream/files/output_folder_lock.h"

namespace dream::workflows {
namespace {

std::string LockPath(const std::string& dir) { return dir + "/" + files::OutputFolderLock::kFileName; }

}  // namespace

bool RunFolderLock::HeldElsewhere(const std::string& dir) {
  const int fd = ::open(LockPath(dir).c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return false;
  struct stat status {};
  bool held = false;
  if (::fstat(fd, &status) == 0 && S_ISREG(status.st_mode)) {
    held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  }
  ::close(fd);  // drops the shared lock if it was taken
  return held;
}

RunFolderLock::RunFolderLock(const std::string& dir) {
  const std::string path = LockPath(dir);
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, 0644);
  if (fd_ < 0)
    throw std::runtime_error("cannot lock the run folder " + dir + ": " + path + ": " + std::strerror(errno));
  struct stat status {};
  if (::fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("cannot lock the run folder " + dir + ": " + path + " is not a regular file");
  }
  held_ = ::flock(fd_, LOCK_EX | LOCK_NB) == 0;
}

RunFolderLock::~RunFolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace dream::workflows
