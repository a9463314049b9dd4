#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace dream::node {

/// Shows how far a long loop (the steps of a run) has come, on a stream the
/// caller chooses, in one of two styles:
///
/// - interactive (a terminal): one line redrawn in place with '\r' — steps, a
///   bar, percent, steps/s and ETA — at most every redraw_interval_s, only
///   once the loop has lasted show_after_s (quick loops show nothing), never
///   wider than the terminal, and ended with a newline by Finish();
/// - plain (a file or a pipe): one line every line_interval_s, for logs.
///
/// The rate is measured over the last few seconds, so it follows a run that
/// speeds up or slows down; the ETA is to `total_steps`, an upper bound when
/// the loop may end early (a run ends when every robot is done).
///
/// Not thread-safe: call it from the loop's thread. Anything else written to
/// the same terminal while the bar is up must call ClearLine() first (the
/// CLI's log sink does), or it lands in the middle of the bar.
class ProgressReporter {
 public:
  using Clock = std::chrono::steady_clock;

  struct Options {
    bool interactive = false;
    /// Plain: a line this often, wall seconds. Must be > 0.
    double line_interval_s = 2.0;
    /// Interactive: at most one redraw this often (10 Hz).
    double redraw_interval_s = 0.1;
    /// Interactive: no bar for loops that end sooner than this.
    double show_after_s = 0.5;
    /// Interactive: the terminal's width; lines use at most width - 1 columns
    /// (a full-width line would wrap on some terminals).
    int width_columns = 80;
  };

  /// @param out must outlive the reporter.
  ProgressReporter(std::ostream& out, Options options);

  /// Starts timing a loop of `total_steps` steps (>= 1) at `now`; the loop has
  /// done `done_steps` already (they do not count towards the rate).
  void Start(int64_t total_steps, int64_t done_steps, Clock::time_point now);
  /// The loop has done `done_steps` of total_steps by `now`. Cheap when there
  /// is nothing to draw: call it every step.
  void Update(int64_t done_steps, Clock::time_point now);
  /// The loop is over: an interactive bar on screen is drawn a last time and
  /// ended with a newline. Idempotent; nothing happens before Start().
  void Finish(Clock::time_point now);
  /// Erases the bar from the terminal line, if it is drawn, so other output
  /// can be written; the next redraw puts it back.
  void ClearLine();

  /// True while an interactive bar is on the terminal line (not yet ended).
  bool line_on_screen() const { return drawn_width_ > 0; }
  /// The measured rate, steps per second (0 until a step was measured).
  double steps_per_second() const { return steps_per_s_; }

  /// Seconds to do `remaining_steps` at `steps_per_s`; NaN while the rate is
  /// unknown (<= 0 or not finite), 0 when nothing remains.
  static double EtaSeconds(int64_t remaining_steps, double steps_per_s);
  /// "0:07", "12:34", "1:02:03"; "?" when `seconds` is NaN or infinite.
  static std::string FormatDuration(double seconds);

  /// The interactive line: "step 1200/3000 [#####-----]  40%  28512 steps/s  ETA 0:03",
  /// the bar shrunk (or dropped, then the text cut) to fit width_columns - 1.
  std::string BarLine(int64_t done_steps) const;
  /// The plain line: "step 1200/3000 (40%), 28512 steps/s, ETA 0:03".
  std::string PlainLine(int64_t done_steps) const;

 private:
  void MeasureRate(int64_t done_steps, Clock::time_point now);
  void Draw(int64_t done_steps);

  std::ostream& out_;
  Options options_;
  bool started_ = false;
  bool finished_ = false;
  bool shown_ = false;  // the bar was drawn at least once
  int64_t total_steps_ = 1;
  int64_t last_done_steps_ = 0;
  Clock::time_point start_time_;
  Clock::time_point last_output_time_;
  // The rate is measured between two anchors about one window apart: the
  // older one is at most two windows old.
  Clock::time_point older_anchor_time_;
  int64_t older_anchor_steps_ = 0;
  Clock::time_point newer_anchor_time_;
  int64_t newer_anchor_steps_ = 0;
  double steps_per_s_ = 0.0;
  int drawn_width_ = 0;  // characters of the bar on screen; 0: none
};

}  // namespace dream::node
