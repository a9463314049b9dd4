#include "dream/node/progress_reporter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace dream::node {
namespace {

// The rate is measured over the last one to two seconds: long enough not to
// flicker, short enough to follow a run that changes pace.
constexpr double kRateWindowS = 1.0;
// A wider bar is no easier to read.
constexpr int kMaxBarColumns = 50;
// Narrower than this, the bar says nothing: only the text is shown.
constexpr int kMinBarColumns = 10;

double SecondsBetween(ProgressReporter::Clock::time_point from, ProgressReporter::Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

std::string Printf(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

}  // namespace

ProgressReporter::ProgressReporter(std::ostream& out, Options options) : out_(out), options_(options) {
  if (!options_.interactive && !(options_.line_interval_s > 0.0)) {
    throw std::invalid_argument("progress: line_interval_s must be > 0, got " +
                                std::to_string(options_.line_interval_s));
  }
}

void ProgressReporter::Start(int64_t total_steps, int64_t done_steps, Clock::time_point now) {
  total_steps_ = std::max<int64_t>(1, total_steps);
  last_done_steps_ = done_steps;
  start_time_ = last_output_time_ = older_anchor_time_ = newer_anchor_time_ = now;
  older_anchor_steps_ = newer_anchor_steps_ = done_steps;
  steps_per_s_ = 0.0;
  started_ = true;
  finished_ = false;
  shown_ = false;
}

void ProgressReporter::MeasureRate(int64_t done_steps, Clock::time_point now) {
  if (SecondsBetween(newer_anchor_time_, now) >= kRateWindowS) {
    older_anchor_time_ = newer_anchor_time_;
    older_anchor_steps_ = newer_anchor_steps_;
    newer_anchor_time_ = now;
    newer_anchor_steps_ = done_steps;
  }
  const double elapsed_s = SecondsBetween(older_anchor_time_, now);
  if (elapsed_s > 0.0) steps_per_s_ = static_cast<double>(done_steps - older_anchor_steps_) / elapsed_s;
}

void ProgressReporter::Update(int64_t done_steps, Clock::time_point now) {
  if (!started_ || finished_) return;
  last_done_steps_ = done_steps;
  MeasureRate(done_steps, now);
  const double since_output_s = SecondsBetween(last_output_time_, now);
  if (options_.interactive) {
    if (SecondsBetween(start_time_, now) < options_.show_after_s) return;
    if (shown_ && since_output_s < options_.redraw_interval_s) return;
    Draw(done_steps);
  } else {
    if (since_output_s < options_.line_interval_s) return;
    out_ << PlainLine(done_steps) << '\n' << std::flush;
  }
  last_output_time_ = now;
}

void ProgressReporter::Finish(Clock::time_point now) {
  if (!started_ || finished_) return;
  finished_ = true;
  if (!options_.interactive || !shown_) return;
  MeasureRate(last_done_steps_, now);
  Draw(last_done_steps_);
  out_ << '\n' << std::flush;
  drawn_width_ = 0;
}

void ProgressReporter::ClearLine() {
  if (drawn_width_ == 0) return;
  out_ << '\r' << std::string(static_cast<size_t>(drawn_width_), ' ') << '\r' << std::flush;
  drawn_width_ = 0;
}

void ProgressReporter::Draw(int64_t done_steps) {
  const std::string line = BarLine(done_steps);
  out_ << '\r' << line;
  // A shorter line than the one on screen: blank the rest.
  if (static_cast<int>(line.size()) < drawn_width_) {
    out_ << std::string(static_cast<size_t>(drawn_width_) - line.size(), ' ');
  }
  out_ << std::flush;
  drawn_width_ = std::max(drawn_width_, static_cast<int>(line.size()));
  shown_ = true;
}

double ProgressReporter::EtaSeconds(int64_t remaining_steps, double steps_per_s) {
  if (remaining_steps <= 0) return 0.0;
  if (!std::isfinite(steps_per_s) || steps_per_s <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(remaining_steps) / steps_per_s;
}

std::string ProgressReporter::FormatDuration(double seconds) {
  if (!std::isfinite(seconds)) return "?";
  const long long total = std::llround(std::max(0.0, seconds));
  const long long hours = total / 3600;
  const long long minutes = (total / 60) % 60;
  const long long secs = total % 60;
  char text[48];
  if (hours > 0) {
    std::snprintf(text, sizeof(text), "%lld:%02lld:%02lld", hours, minutes, secs);
  } else {
    std::snprintf(text, sizeof(text), "%lld:%02lld", minutes, secs);
  }
  return text;
}

std::string ProgressReporter::PlainLine(int64_t done_steps) const {
  const double fraction = std::clamp(static_cast<double>(done_steps) / static_cast<double>(total_steps_), 0.0, 1.0);
  return "step " + std::to_string(done_steps) + "/" + std::to_string(total_steps_) + " (" +
         Printf("%.0f", 100.0 * fraction) + "%), " + Printf("%.0f", steps_per_s_) + " steps/s, ETA " +
         FormatDuration(EtaSeconds(total_steps_ - done_steps, steps_per_s_));
}

std::string ProgressReporter::BarLine(int64_t done_steps) const {
  const double fraction = std::clamp(static_cast<double>(done_steps) / static_cast<double>(total_steps_), 0.0, 1.0);
  const std::string steps = "step " + std::to_string(done_steps) + "/" + std::to_string(total_steps_);
  const std::string figures = Printf("%3.0f%%", 100.0 * fraction) + "  " + Printf("%.0f", steps_per_s_) +
                              " steps/s  ETA " + FormatDuration(EtaSeconds(total_steps_ - done_steps, steps_per_s_));
  const int max_columns = std::max(1, options_.width_columns - 1);
  // "steps [bar]  figures": what is left for the bar between its brackets.
  const int bar_columns = std::min(kMaxBarColumns, max_columns - static_cast<int>(steps.size() + figures.size()) - 5);
  std::string line;
  if (bar_columns >= kMinBarColumns) {
    const int filled = static_cast<int>(fraction * bar_columns);
    line = steps + " [" + std::string(static_cast<size_t>(filled), '#') +
           std::string(static_cast<size_t>(bar_columns - filled), '-') + "]  " + figures;
  } else {
    line = steps + "  " + figures;
  }
  if (static_cast<int>(line.size()) > max_columns) line.resize(static_cast<size_t>(max_columns));
  return line;
}

}  // namespace dream::node
