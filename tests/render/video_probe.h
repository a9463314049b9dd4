#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace dream::render::testing {

/// True when `program` is on PATH.
inline bool OnPath(const std::string& program) {
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

/// Frames in the first video stream of `path`, counted by ffprobe (-1 on failure).
inline long CountVideoFrames(const std::string& path) {
  const std::string command =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
      "-of default=nokey=1:noprint_wrappers=1 '" +
      path + "' 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return -1;
  char line[64] = {0};
  const bool read = std::fgets(line, sizeof(line), pipe) != nullptr;
  ::pclose(pipe);
  return read ? std::strtol(line, nullptr, 10) : -1;
}

}  // namespace dream::render::testing
