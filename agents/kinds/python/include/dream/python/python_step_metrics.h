#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/kind_api/own_step_metrics.h"

namespace dream::python {

/// A Python controller's own metrics() followed while a run runs (the view's
/// plots), by one long-lived `python3 -I python/dream/follow_metrics.py` a
/// run: the steps go to it in batches over a socket, never waited on (what
/// it has not taken yet waits here), and it evaluates metrics() on the run so
/// far when asked. One evaluation at a time, the next no sooner than
/// kMinInterval and three times the last one's duration after it ends, so
/// the helper takes at most about a quarter of a core however long the run
/// (the first one's duration is not counted: it holds the helper's start-up).
/// After the last step, once Pending() is false, the figures are those
/// PythonRunMetrics::Compute gives for the same steps (summary.json's).
class PythonStepMetrics final : public kind_api::OwnStepMetrics {
 public:
  /// The least time between two evaluations.
  static constexpr std::chrono::milliseconds kMinInterval{100};
  /// The most one evaluation may take (PythonRunMetrics' time-out): then the helper is stopped.
  static constexpr std::chrono::seconds kMaxEvaluation{120};
  /// Pose numbers followed at most (x, y, theta per robot and step), as the view's replay keeps.
  static constexpr int64_t kMaxPoseNumbers = 6'000'000;

  /// Starts the helper for the controller of `spec_json` (the kind's
  /// runtime_spec) on `num_robots` robots.
  /// @throws std::runtime_error naming the script when it is missing or cannot start.
  PythonStepMetrics(const std::string& runtime_dir, const std::string& spec_json, int num_robots);
  /// Ends the helper (killed: it holds nothing worth keeping).
  ~PythonStepMetrics() override;
  PythonStepMetrics(const PythonStepMetrics&) = delete;
  PythonStepMetrics& operator=(const PythonStepMetrics&) = delete;

  void Observe(const kind_api::RunPoses::Step& step) override;
  int64_t Read(std::vector<Figure>* figures) override;
  bool Pending() const override;
  std::string last_error() const override { return last_error_; }
  /// When the next evaluation may be asked for, once a step is new.
  std::chrono::steady_clock::time_point next_ask() const { return next_due_; }

 private:
  void QueueBatch();
  void Send();
  void Receive();
  void TakeAnswer(const std::string& line);
  [[noreturn]] void Stopped(const std::string& why);

  int num_robots_;
  pid_t pid_ = -1;
  int socket_ = -1;  // the helper's stdin and stdout
  int errors_ = -1;  // its stderr: an unlinked temporary file
  // Steps observed and not yet queued: a batch.
  std::vector<int64_t> batch_steps_;
  std::vector<double> batch_poses_;
  std::string outgoing_;  // queued bytes the socket has not taken yet
  std::string incoming_;  // the helper's answer, up to its newline
  int64_t pose_numbers_ = 0;
  int64_t observed_step_ = -1;
  bool observed_any_ = false;
  bool asked_ = false;  // an evaluation under way
  int64_t asked_step_ = -1;
  std::chrono::steady_clock::time_point asked_at_{}, next_due_{};
  int64_t answered_step_ = -1;  // the last step an answer (figures or an error) was about
  int64_t figures_step_ = -1;   // the step figures_ are of
  bool answered_any_ = false;
  bool answered_first_ = false;  // any answer, an error too: later ones time an evaluation alone
  std::vector<Figure> figures_;
  std::string last_error_;
};

}  // namespace dream::python
