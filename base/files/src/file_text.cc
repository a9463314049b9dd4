#include "dream/files/file_text.h"

#include "dream/files/regular_file.h"

namespace dream::files {

std::string ReadFileText(const std::string& path, std::uintmax_t max_bytes) {
  return RegularFile(path).ReadAll(max_bytes);
}

}  // namespace dream::files
