#include "dream/files/file_text.h"

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

}  // namespace

std::string ReadFileText(const std::string& path, std::uintmax_t max_bytes) {
  // Non-blocking, so a FIFO is refused below instead of waited on.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) throw std::runtime_error(path + ": cannot open the file: " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw std::runtime_error(path + ": cannot read the file: " + std::strerror(errno));
  if (!S_ISREG(status.st_mode)) {
    throw std::runtime_error(path + (S_ISDIR(status.st_mode) ? ": is a folder" : ": is not a regular file") +
                             ", not a file to read");
  }
  if (static_cast<std::uintmax_t>(status.st_size) > max_bytes) {
    throw TooLarge(path, static_cast<std::uintmax_t>(status.st_size), max_bytes);
  }
  std::string text;
  text.reserve(static_cast<size_t>(status.st_size));
  char buffer[65536];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof(buffer));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw std::runtime_error(path + ": cannot read the file: " + std::strerror(errno));
    if (got == 0) break;
    // The file may grow while it is read: the bound holds for what is read.
    if (text.size() + static_cast<size_t>(got) > max_bytes) throw TooLarge(path, text.size() + got, max_bytes);
    text.append(buffer, static_cast<size_t>(got));
  }
  return text;
}

}  // namespace dream::files
