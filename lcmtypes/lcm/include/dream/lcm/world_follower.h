#pragma once

#include <cstdint>
#include <optional>
#include <set>

namespace dream::lcm {

/// Decides which world messages a follower of one run acts on (an agent
/// host; dream view's RunChoice), so that a stray or forged message cannot
/// steer or freeze its robots, nor redraw the run watched: it follows the run
/// (run_id) it joined with its first DREAM_POSES, and within it takes only
/// the next step, a resend of the current one, or a short forward gap (lost
/// datagrams in real-time mode). A jump further away (or backwards) is taken
/// only once the world confirms it with the step after it, which a single
/// forged datagram cannot do. Statuses and radio messages of other runs are
/// ignored; other runs seen are remembered (a second world on the same URL).
/// Here, below the agents and the view, so both follow a run by one rule.
///
/// LCM has no authentication: this stops mistakes (a second `dream sim`, a
/// stale process) and blind forgeries, not a sender who copies the run id
/// and the next step from the bus.
class WorldFollower {
 public:
  enum class StepDecision {
    kNewStep,  ///< run the robots for this step
    kResend,   ///< the current step again: answer it again, unchanged
    kIgnore,   ///< late duplicate, another run, or an unconfirmed jump
  };

  /// Forward gap accepted without confirmation: one second of Robotarium steps.
  static constexpr int64_t kMaxStepGap = 30;
  /// Other runs remembered, so a flood of run ids cannot grow memory.
  static constexpr size_t kMaxOtherRuns = 16;

  /// For a DREAM_POSES of `run_id` at `step`.
  StepDecision OnPoses(int64_t run_id, int64_t step);
  /// Whether a status, obstacles or radio message of `run_id` belongs to the
  /// run being followed (false before joining any).
  bool InRun(int64_t run_id);
  /// A FINISHED/ABORTED status ends this host's run only if it is of the run
  /// followed and not behind the step the host is at.
  bool EndsRun(int64_t run_id, int64_t step);

  bool joined() const { return run_id_ != 0; }
  int64_t run_id() const { return run_id_; }
  int64_t step() const { return step_; }
  /// Other runs seen on the bus, at most kMaxOtherRuns.
  const std::set<int64_t>& other_runs() const { return other_runs_; }
  /// DREAM_POSES ignored as out of sequence (not counting late duplicates).
  int64_t steps_out_of_sequence() const { return steps_out_of_sequence_; }

 private:
  void NoteOtherRun(int64_t run_id);

  int64_t run_id_ = 0;
  int64_t step_ = -1;
  std::optional<int64_t> unconfirmed_step_;
  std::set<int64_t> other_runs_;
  int64_t steps_out_of_sequence_ = 0;
};

}  // namespace dream::lcm
