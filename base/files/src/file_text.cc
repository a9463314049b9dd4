#include "dream/files/file_text.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dream::files {

std::string ReadFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace dream::files
