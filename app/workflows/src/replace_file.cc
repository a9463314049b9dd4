#include "replace_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace dream::workflows {
namespace {

/// Closes a descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

bool WriteAll(int fd, const std::string& content) {
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t wrote = ::write(fd, content.data() + done, content.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) return false;
    done += static_cast<size_t>(wrote);
  }
  return true;
}

}  // namespace

void ReplaceFile(const std::string& path, const std::string& content) {
  std::vector<char> temporary(path.begin(), path.end());
  const std::string suffix = ".part.XXXXXX";
  temporary.insert(temporary.end(), suffix.begin(), suffix.end());
  temporary.push_back('\0');
  Descriptor file{::mkstemp(temporary.data())};
  if (file.fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  const std::string temporary_path(temporary.data());
  // mkstemp makes it 0600; the sweep's files are read by its Slurm jobs and people alike.
  const bool written = ::fchmod(file.fd, 0644) == 0 && WriteAll(file.fd, content);
  const int write_error = errno;
  const bool closed = ::close(file.fd) == 0;
  file.fd = -1;
  if (!written || !closed) {
    ::unlink(temporary_path.c_str());
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(written ? errno : write_error));
  }
  if (::rename(temporary_path.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary_path.c_str());
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(error));
  }
}

std::string ReadFileTail(const std::string& path, size_t max_bytes) {
  // Non-blocking, so a FIFO is refused below instead of waited on (as files::ReadFileText does).
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  struct stat status {};
  if (file.fd < 0 || ::fstat(file.fd, &status) != 0 || !S_ISREG(status.st_mode)) return "";
  const off_t size = status.st_size;
  const off_t start = size > static_cast<off_t>(max_bytes) ? size - static_cast<off_t>(max_bytes) : 0;
  std::string text(static_cast<size_t>(size - start), '\0');
  size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::pread(file.fd, text.data() + got, text.size() - got, start + static_cast<off_t>(got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<size_t>(n);
  }
  text.resize(got);
  return text;
}

}  // namespace dream::workflows
