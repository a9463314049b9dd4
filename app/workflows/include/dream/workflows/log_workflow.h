#pragma once

#include <iostream>
#include <ostream>
#include <regex>
#include <string>

namespace dream::workflows {

/// `dream log info / diff / echo`: what dream::run_log says of an LCM log,
/// printed. Paths are log files (files::RunLogPath of what the user gave).
class LogWorkflow {
 public:
  explicit LogWorkflow(std::ostream& out = std::cout, std::ostream& problems = std::cerr)
      : out_(out), problems_(problems) {}

  /// The log's events and bytes per channel and the log time it spans
  /// (run_log::LogChannelCounts). @throws std::runtime_error for an empty or damaged log.
  void Info(const std::string& path) const;

  /// Two logs compared per channel (run_log::LogDifference): each difference,
  /// then "same" or "different". Returns whether they are the same.
  /// `first_name`/`second_name`: what the differences call the logs.
  /// @throws std::runtime_error for a missing or damaged log.
  bool Diff(const std::string& first_path, const std::string& first_name, const std::string& second_path,
            const std::string& second_name, const std::regex& channels, const std::string& channels_text,
            bool raw) const;

  /// Each message on channels matching `channels` as one JSON line, at most
  /// `limit` when > 0 (run_log::LogEcho); what was skipped or did not decode
  /// to `problems`.
  void Echo(const std::string& path, const std::regex& channels, const std::string& channels_text,
            long long limit) const;

 private:
  std::ostream& out_;
  std::ostream& problems_;
};

}  // namespace dream::workflows
