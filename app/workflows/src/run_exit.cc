#include "dream/workflows/run_exit.h"

#include <cmath>
#include <sstream>

#include "dream/world/printf_text.h"

namespace dream::workflows {

std::string RunExit::Text() const {
  std::string text =
      std::to_string(exit_code) + " " + world::PrintfText("%.3f", wall_time_s) + " " + (timed_out ? "1" : "0") + "\n";
  std::string line;
  for (char c : problem) line += (c == '\n' || c == '\r') ? ' ' : c;
  return line.empty() ? text : text + line.substr(0, 1000) + "\n";
}

std::optional<RunExit> RunExit::Parse(const std::string& text) {
  if (text.size() > kMaxBytes) return std::nullopt;
  std::istringstream in(text);
  std::string first;
  if (!std::getline(in, first)) return std::nullopt;
  std::istringstream fields(first);
  RunExit exit;
  int timed_out = 0;
  std::string rest;
  if (!(fields >> exit.exit_code >> exit.wall_time_s >> timed_out) || (fields >> rest)) return std::nullopt;
  if (exit.exit_code < -1 || exit.exit_code > 255 || !std::isfinite(exit.wall_time_s) || exit.wall_time_s < 0.0 ||
      (timed_out != 0 && timed_out != 1)) {
    return std::nullopt;
  }
  exit.timed_out = timed_out == 1;
  std::getline(in, exit.problem);
  return exit;
}

}  // namespace dream::workflows
