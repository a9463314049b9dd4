#include "dream/config_overrides/config_text.h"

#include <sstream>

namespace dream::config_overrides {

std::string CommentLines(const std::string& header) {
  std::string text;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) text += "# " + line + "\n";
  return text;
}

std::string ConfigText(const YAML::Node& config, const std::string& header) {
  YAML::Emitter out;
  out.SetIndent(2);
  out << config;
  return CommentLines(header) + out.c_str() + "\n";
}

}  // namespace dream::config_overrides
