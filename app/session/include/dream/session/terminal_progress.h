#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <spdlog/sinks/sink.h>

#include "dream/node/progress_reporter.h"

namespace dream::session {

/// The progress display of one command, on stderr: a bar redrawn in place when
/// stderr is a terminal, a plain line every `line_interval_s` when it is not,
/// nothing with --quiet (log level above info) or a zero interval.
///
/// While it exists, every log line first clears the bar, so a warning in the
/// middle of a run starts on a clean line and the bar comes back below it.
/// One at a time; destroy it before printing results.
class TerminalProgress {
 public:
  explicit TerminalProgress(double line_interval_s);
  ~TerminalProgress();  // gives the logger its own sinks back

  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  /// Null when nothing is to be shown.
  node::ProgressReporter* reporter() { return reporter_.get(); }

 private:
  std::unique_ptr<node::ProgressReporter> reporter_;
  std::vector<spdlog::sink_ptr> original_sinks_;
};

}  // namespace dream::session
