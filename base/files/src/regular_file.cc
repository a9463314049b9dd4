#include "dream/files/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace dream::files {
namespace {

std::runtime_error TooLarge(const std::string& path, std::uintmax_t size, std::uintmax_t max_bytes) {
  return std::runtime_error(path + ": " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
                            " a file read here may hold; is it the file you meant?");
}

const char* KindOf(mode_t mode) {
  if (S_ISDIR(mode)) return ": is a folder";
  if (S_ISFIFO(mode)) return ": is a FIFO (named pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return ": is a device";
  if (S_ISSOCK(mode)) return ": is a socket";
  return ": is not a regular file";
}

}  // namespace

RegularFile::RegularFile(std::string path) : path_(std::move(path)) {
  // O_NONBLOCK: opening a FIFO without a writer would wait, in the kernel, for
  // one; the descriptor is then asked what it is. O_NOCTTY: a terminal device
  // named here must not become the controlling terminal.
  fd_ = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) throw std::runtime_error(path_ + ": cannot open the file: " + std::strerror(errno));
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd_);
    throw std::runtime_error(path_ + ": cannot read the file: " + reason);
  }
  if (!S_ISREG(status.st_mode)) {
    ::close(fd_);
    throw std::runtime_error(path_ + KindOf(status.st_mode) + ", not a file to read");
  }
  // A regular file's reads never block; clear the flag anyway for the
  // libraries the descriptor is handed to.
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
  size_ = static_cast<std::uintmax_t>(status.st_size);
}

RegularFile::~RegularFile() {
  if (fd_ >= 0) ::close(fd_);
}

RegularFile::RegularFile(RegularFile&& other) noexcept
    : path_(std::move(other.path_)), fd_(other.fd_), size_(other.size_) {
  other.fd_ = -1;
}

std::string RegularFile::OpenedName() const { return "/proc/self/fd/" + std::to_string(fd_); }

std::string RegularFile::ReadAll(std::uintmax_t max_bytes) {
  if (size_ > max_bytes) throw TooLarge(path_, size_, max_bytes);
  std::string text;
  text.reserve(static_cast<size_t>(size_));
  char buffer[65536];
  for (;;) {
    const ssize_t got = ::read(fd_, buffer, sizeof(buffer));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw std::runtime_error(path_ + ": cannot read the file: " + std::strerror(errno));
    if (got == 0) break;
    // The file may grow while it is read: the bound holds for what is read.
    if (text.size() + static_cast<size_t>(got) > max_bytes) throw TooLarge(path_, text.size() + got, max_bytes);
    text.append(buffer, static_cast<size_t>(got));
  }
  return text;
}

}  // namespace dream::files
