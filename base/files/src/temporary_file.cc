#include "dream/files/temporary_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace dream::files {
namespace {

// Names drawn before giving up: each taken one is a file someone else put
// there; so many in a row is no accident.
constexpr int kMaxNameDraws = 100;

// Eight characters from the kernel's random source: not guessable ahead, so a
// link cannot be planted at the name (and if one is there, O_EXCL refuses it).
std::string RandomSuffix() {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[8] = {};
  size_t got = 0;
  while (got < sizeof(bytes)) {
    const ssize_t n = ::getrandom(bytes + got, sizeof(bytes) - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("cannot draw a temporary file name: ") + std::strerror(errno));
    got += static_cast<size_t>(n);
  }
  std::string suffix;
  for (unsigned char byte : bytes) suffix += kAlphabet[byte % (sizeof(kAlphabet) - 1)];
  return suffix;
}

}  // namespace

TemporaryFile::TemporaryFile(std::string target, const std::string& suffix) : target_(std::move(target)) {
  for (int draw = 0; draw < kMaxNameDraws; ++draw) {
    path_ = target_ + ".tmp." + RandomSuffix() + suffix;
    // 0666 as any file a program creates: the user's umask decides the rest.
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, 0666);
    if (fd_ >= 0) return;
    if (errno != EEXIST) {
      throw std::runtime_error("cannot write " + target_ + ": " + std::strerror(errno) + " (does the folder exist?)");
    }
  }
  throw std::runtime_error("cannot write " + target_ + ": " + std::to_string(kMaxNameDraws) +
                           " temporary names beside it were all taken by files already there");
}

TemporaryFile::~TemporaryFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) ::unlink(path_.c_str());
}

void TemporaryFile::Fail(const std::string& reason) {
  throw std::runtime_error("cannot write " + target_ + ": " + reason);
}

void TemporaryFile::Write(const std::string& bytes) {
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) Fail(std::strerror(errno));
    written += static_cast<size_t>(n);
  }
}

void TemporaryFile::Sync() {
  if (::fsync(fd_) != 0) Fail(std::strerror(errno));
}

void TemporaryFile::Commit() {
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) Fail(std::strerror(errno));
  // rename replaces the target's directory entry itself: a link planted at
  // the target is replaced, never followed.
  if (std::rename(path_.c_str(), target_.c_str()) != 0) Fail(std::strerror(errno));
  committed_ = true;
}

}  // namespace dream::files
