#include "replace_file.h"

#include <unistd.h>

#include <cerrno>
#include <stdexcept>

#include "dream/files/atomic_file.h"
#include "dream/files/regular_file.h"

namespace dream::workflows {

void ReplaceFile(const std::string& path, const std::string& content) {
  files::WriteFileAtomically(path, content, files::Durability::kRenamedOnly);
}

namespace {

// `max_bytes` of the regular file at `path`, its first or its last; empty
// when it cannot be read (a FIFO or device there is refused, not waited on).
std::string ReadPart(const std::string& path, size_t max_bytes, bool from_end) {
  try {
    const files::RegularFile file(path);
    const std::uintmax_t size = file.size();
    const std::uintmax_t start = from_end && size > max_bytes ? size - max_bytes : 0;
    std::string text(max_bytes, '\0');
    size_t got = 0;
    while (got < max_bytes) {
      const ssize_t n = ::pread(file.descriptor(), text.data() + got, max_bytes - got, static_cast<off_t>(start + got));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<size_t>(n);
    }
    text.resize(got);
    return text;
  } catch (const std::runtime_error&) {
    return "";
  }
}

}  // namespace

std::string ReadFileTail(const std::string& path, size_t max_bytes) { return ReadPart(path, max_bytes, true); }

}  // namespace dream::workflows
