#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "dream/lcm/world_follower.h"
#include "dream/view/view_frame.h"

namespace dream::view {

/// Which run dream view draws. It follows one run by the agents' rule
/// (lcm::WorldFollower: the run joined, its next steps, resends, short gaps,
/// far jumps once the next step confirms them), so a forged DREAM_POSES of a
/// made-up run, or a second world on the bus, neither replaces the run drawn
/// nor wipes the violations located in it.
///
/// A run is taken only on a whole step of a world: its DREAM_STATUS of the
/// step heard just before the step's poses (a world publishes both, and
/// again while it waits), so poses alone, however many, are no run. Another
/// run is taken only when it starts cleanly, once the followed run is over
/// (a FINISHED or ABORTED status of it, or kSilence without a message of
/// it): at its step 0 if it was first heard after that, or at its step 1
/// right after its step 0 (a world that waited beside the followed run and
/// now runs). So a finished run stays drawn until a new one starts. The
/// first run is joined at any step (a view started mid-run). A followed run
/// still at its step 0 (waiting for agents) gives way to a run heard at two
/// steps in a row: the one that runs, not the idle one, is drawn. And the
/// user may choose another run heard (Choose): its next poses are drawn.
///
/// Runs heard are remembered (at most kMaxRunsHeard, the least recently
/// heard forgotten first) so the page can say that a second world is on the
/// bus. The clock is injected: tests decide when a run went silent.
class RunChoice {
 public:
  using Clock = std::chrono::steady_clock;
  enum class Decision {
    kIgnore,     ///< not drawn: another run, out of sequence, or not confirmed yet
    kResend,     ///< the step drawn, again
    kNewStep,    ///< the followed run's next step
    kStartOver,  ///< a run drawn from scratch: the first, a new one, or the followed one from its start again
  };
  /// A followed run without a message for this long is over: a world
  /// publishes at least every resend_interval_s (0.25 s) while it waits.
  static constexpr Clock::duration kSilence = std::chrono::seconds(3);
  /// Another run is reported this long after its last message (shorter than
  /// kSilence: a followed run gone silent is not reported once another is taken).
  static constexpr Clock::duration kOtherWorldShown = std::chrono::seconds(2);
  /// Runs remembered, so a flood of made-up run ids cannot grow memory.
  static constexpr size_t kMaxRunsHeard = 16;

  explicit RunChoice(std::function<Clock::time_point()> now = &Clock::now);

  /// A DREAM_POSES of `run_id` at `step`.
  Decision OnPoses(int64_t run_id, int64_t step);
  /// A DREAM_STATUS: whether it is the followed run's (to draw). A FINISHED
  /// or ABORTED one of the followed run, not behind its step, ends it.
  bool OnStatus(int64_t run_id, int64_t step, int state);
  /// DREAM_OBSTACLES or DREAM_MEASURED_POSES: whether they are the followed run's.
  bool OnMessageOf(int64_t run_id);

  /// The user's choice: `run_id`, a run heard and not followed, is drawn
  /// from its next DREAM_POSES on, whatever its step. False (and nothing
  /// chosen) for a run not heard, or the one followed.
  bool Choose(int64_t run_id);

  /// The other run heard last within kOtherWorldShown, and how many were;
  /// runs whose last status said FINISHED or ABORTED are not counted.
  std::optional<ViewFrame::OtherWorld> OtherWorldHeard() const;
  /// The run followed; 0 before any.
  int64_t run_id() const { return follower_.run_id(); }
  /// Whether the followed run reported its end.
  bool ended() const { return ended_; }

 private:
  struct RunHeard {
    int64_t run_id = 0;
    Clock::time_point first;
    Clock::time_point last;
    /// When heard last, counted in messages: which is the latest, and the
    /// least recent, whatever the clock's grain.
    uint64_t order = 0;
    int64_t poses_step = -1;   ///< its newest DREAM_POSES' step; -1: none
    int64_t status_step = -1;  ///< its newest DREAM_STATUS' step; -1: none
    int state = -1;            ///< its newest DREAM_STATUS' state; -1: none
  };

  RunHeard& Heard(int64_t run_id, Clock::time_point now);
  /// Since when the followed run is over (its end, or its last message when
  /// silent); nullopt while it goes on.
  std::optional<Clock::time_point> OverSince(Clock::time_point now) const;
  /// Whether `run`'s poses at `step` start it cleanly (before they are noted).
  bool StartsCleanly(const RunHeard& run, int64_t step, Clock::time_point now) const;

  std::function<Clock::time_point()> now_;
  lcm::WorldFollower follower_;
  bool ended_ = false;
  Clock::time_point ended_at_;
  Clock::time_point followed_heard_;  ///< the followed run's last message
  std::vector<RunHeard> heard_;       ///< at most kMaxRunsHeard
  int64_t chosen_ = 0;                ///< the user's choice, until its poses come; 0: none
  uint64_t messages_ = 0;             ///< messages heard: RunHeard::order
};

}  // namespace dream::view
