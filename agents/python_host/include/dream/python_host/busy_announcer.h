#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace dream::python_host {

/// When a Python host tells the world that its robots' answers to a step are
/// held up (DREAM_BUSY_<id>, robot_busy_t). The host's watchdog ends a long
/// call (a raise at 0.8 of the world's agent_timeout_s, a kill after it), and
/// the world would call a robot silent at 1.0: two clocks, and on a starved
/// machine the fault could come after the world's deadline. The note closes that race:
/// from a quarter of agent_timeout_s after the step reached the host, every
/// quarter, it names each robot of the host that has neither answered the
/// step nor failed, so the world waits for the host's own verdict (the
/// robot's command or its fault) while the host is alive to give it. The
/// same holds the world's start while the host loads and sets robots up
/// (bounded on the host's side by PythonHostProcess's kill fractions).
/// Not thread-safe: its owner guards it. Times are given, so tests need no clock.
class BusyAnnouncer {
 public:
  using Clock = std::chrono::steady_clock;
  /// Notes start this fraction of agent_timeout_s after the step, and repeat as often.
  static constexpr double kIntervalFraction = 0.25;

  BusyAnnouncer(std::vector<int> robot_ids, double agent_timeout_s);

  /// The world's step (of run `run_id`) reached the host at `now`; a resend
  /// of the step it has changes nothing.
  void StepArrived(int64_t run_id, int64_t step, Clock::time_point now);
  /// `robot_id` answered `step` (its command was sent).
  void Answered(int robot_id, int64_t step);
  /// The robots to say busy for at `now` (empty: none yet, or none due),
  /// leaving out `failed`: the robots whose fault the owner sent (their answer, for good).
  std::vector<int> Due(Clock::time_point now, const std::set<int>& failed);
  /// Before this, Due names no robot (Clock::time_point::max(): none until the
  /// next step): what lets the owner skip its lock on the loop's quiet passes.
  Clock::time_point NextDue() const { return next_note_; }

 private:
  std::vector<int> robot_ids_;
  Clock::duration interval_;
  int64_t run_id_ = 0;
  int64_t step_ = -1;
  Clock::time_point next_note_ = Clock::time_point::max();
  std::map<int, int64_t> answered_;
};

}  // namespace dream::python_host
