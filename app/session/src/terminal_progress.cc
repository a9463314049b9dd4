#include "dream/session/terminal_progress.h"

#include <spdlog/spdlog.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace dream::session {
namespace {

/// Forwards log lines to `inner` after clearing the progress bar off the line.
class BarClearingSink final : public spdlog::sinks::sink {
 public:
  BarClearingSink(node::ProgressReporter& bar, spdlog::sink_ptr inner) : bar_(bar), inner_(std::move(inner)) {}

  void log(const spdlog::details::log_msg& message) override {
    if (!inner_->should_log(message.level)) return;
    bar_.ClearLine();
    inner_->log(message);
  }
  void flush() override { inner_->flush(); }
  void set_pattern(const std::string& pattern) override { inner_->set_pattern(pattern); }
  void set_formatter(std::unique_ptr<spdlog::formatter> formatter) override {
    inner_->set_formatter(std::move(formatter));
  }

 private:
  node::ProgressReporter& bar_;
  spdlog::sink_ptr inner_;
};

/// Columns of the terminal on stderr: its window size, else $COLUMNS, else 80.
int TerminalColumns() {
  winsize size{};
  if (ioctl(fileno(stderr), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  if (const char* columns = std::getenv("COLUMNS")) {
    const int value = std::atoi(columns);
    if (value > 0) return value;
  }
  return 80;
}

}  // namespace

TerminalProgress::TerminalProgress(double line_interval_s) {
  // --quiet sets the level to warn: no progress either.
  if (line_interval_s <= 0.0 || !spdlog::should_log(spdlog::level::info)) return;
  node::ProgressReporter::Options options;
  options.interactive = isatty(fileno(stderr)) != 0;
  options.line_interval_s = line_interval_s;
  options.width_columns = TerminalColumns();
  reporter_ = std::make_unique<node::ProgressReporter>(std::cerr, options);
  if (!options.interactive) return;
  std::vector<spdlog::sink_ptr>& sinks = spdlog::default_logger()->sinks();
  original_sinks_ = sinks;
  for (spdlog::sink_ptr& sink : sinks) sink = std::make_shared<BarClearingSink>(*reporter_, sink);
}

TerminalProgress::~TerminalProgress() {
  if (reporter_ != nullptr) reporter_->ClearLine();
  if (!original_sinks_.empty()) spdlog::default_logger()->sinks() = original_sinks_;
}

}  // namespace dream::session
