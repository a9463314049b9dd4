#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "fuzz_targets.h"

namespace dream::fuzz {

void Finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

std::string ScratchFile(const uint8_t* data, size_t size, const std::string& suffix) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("dream_fuzz_" + std::to_string(::getpid()) + suffix)).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out.flush()) Finding("cannot write the scratch file " + path);
  return path;
}

}  // namespace dream::fuzz
