#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "dream/drawing_t.hpp"
#include "dream/lcm/lcm_interface.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "dream/view/metrics_thread.h"
#include "dream/view/run_choice.h"
#include "dream/view/step_metrics.h"
#include "dream/view/view_frame.h"
#include "dream/view/violation_locator.h"
#include "dream/world/world_params.h"

namespace dream::view {

/// The view's only handler on the bus: it keeps the newest state of the run
/// (poses, measured poses, obstacles, status, radio senders) and nothing
/// older, so it costs a run a decode and a copy per message and never waits
/// for a browser. Frames are taken from another thread (LiveView's pump) at
/// the pace the browsers are drawn.
///
/// The run's verdict: a DREAM_VERDICT of the run drawn, once that run is
/// over (its FINISHED or ABORTED status heard), is the frame's `judged`; a
/// verdict of another run, or of the run drawn while it runs, is refused.
///
/// Violations: when a DREAM_STATUS counts more boundary, collision or
/// obstacle errors than the previous one, the world found them on the poses
/// of the step before (it validates a step's poses, then steps); those
/// poses are checked again (ViolationLocator) to place each violation. The
/// latest kMaxMarks marks are kept.
///
/// One run is drawn (RunChoice: the agents' WorldFollower, and another run
/// only when it starts cleanly once this one is over), so a forged message or
/// a second world on the bus wipes nothing; a run drawn from scratch (a new
/// one, or the same from its start again) starts over. The frame says when
/// another run is heard. Messages that do not decode (lcm::Decode, with the
/// message size limits) are counted and dropped.
class BusFrameCollector {
 public:
  /// Violation marks kept (the latest), so a run colliding every step
  /// cannot grow memory.
  static constexpr size_t kMaxMarks = 64;

  /// Subscribes to DREAM_POSES, DREAM_MEASURED_POSES, DREAM_OBSTACLES,
  /// DREAM_STATUS, DREAM_VERDICT, DREAM_RADIO_<n> and, when `commands`,
  /// DREAM_CMD_<n> and DREAM_CMDS (a script's every robot) on `bus`, until destroyed: one subscription a channel
  /// name, so on udpm the kernel drops every other channel (LcmBus's
  /// ChannelPrefixFilter), the robots' commands included until asked for.
  /// `now` is RunChoice's clock (tests give their own).
  BusFrameCollector(lcm::LcmInterface& bus, const world::WorldParams& world,
                    std::function<RunChoice::Clock::time_point()> now = &RunChoice::Clock::now, bool commands = true);

  /// Subscribes to DREAM_CMD_<n> and DREAM_CMDS too (the command arrows) if
  /// not yet; on the thread that handles the bus.
  void SubscribeCommands();
  /// Whether DREAM_CMD_<n> is subscribed.
  bool hears_commands() const { return command_subscription_.active(); }

  /// The newest frame, when it changed since `*version` (then updated);
  /// false when nothing new arrived. A second world heard, or gone quiet,
  /// changes the frame too. Thread-safe against the handlers.
  bool TakeFrame(ViewFrame* frame, uint64_t* version);

  /// The run's metrics, followed from the next run drawn on (and the run
  /// drawn now, from its next step): a new one from `make` for each run, on
  /// a MetricsThread of its own (the handler only queues each step, once:
  /// not resends), its newest readings in each frame. A kind's code that
  /// throws ends the metrics of that run, said once.
  void FollowMetrics(std::function<std::unique_ptr<StepMetrics>()> make);

  /// Waits until the run drawn's metrics computed every step handed to them
  /// (MetricsThread::WaitUntilComputed), at most `timeout`; true without
  /// metrics. For tests and benchmarks: a frame then carries their figures.
  bool WaitForMetrics(std::chrono::steady_clock::duration timeout);

  /// The user's choice of another run heard (RunChoice::Choose): drawn from
  /// its next poses on. False for a run not heard, or the one drawn.
  bool Follow(int64_t run_id);

  /// Messages that did not decode (forged or foreign), or of the run drawn but broke their
  /// type's rules (a drawing past its bounds, a DREAM_CMDS the world refuses whole), since the start.
  int64_t bad_messages() const;
  /// DREAM_VERDICTs that decoded but were not taken: another run's, or of
  /// the run drawn before it ended.
  int64_t verdicts_refused() const;

  /// The handler, public for the benchmark and the tests: what one message costs.
  void OnMessage(const std::string& channel, const void* data, int size);

 private:
  void OnPoses();  // poses_in_ decoded: the newest poses
  void OnStatus(const run_status_t& status);
  void StartRun(int64_t run_id);
  void OnObstacles();  // obstacles_in_ decoded
  /// drawing_in_ decoded from DREAM_DRAW_<robot>: each robot's newest drawing of the run drawn.
  void OnDrawing(int robot);
  /// command_in_ decoded from DREAM_CMD_<robot>: each robot's newest command of the run drawn.
  void OnCommand(int robot);
  /// commands_in_ decoded from DREAM_CMDS: of the run drawn, refused whole as the world
  /// refuses it (lcm::CommandBatch; a bad message), else each entry as its robot's DREAM_CMD_<id>.
  void OnCommands();
  /// verdict_in_ decoded: kept only when it is the drawn run's and that run is over.
  void OnVerdict();
  /// The new step in poses_ (with obstacles_) to the run's metrics' queue.
  void ObserveMetrics();
  void StartMetrics();

  mutable std::mutex mutex_;
  RunChoice choice_;
  ViolationLocator locator_;
  // Where the handler decodes (on the bus's thread, outside the lock); then
  // swapped with the newest, so it allocates only when a message grows.
  robot_poses_t poses_in_{};
  robot_poses_t measured_in_{};
  obstacles_t obstacles_in_{};
  run_status_t status_in_{};
  run_verdict_t verdict_in_{};
  velocity_command_t command_in_{};
  robot_commands_t commands_in_{};
  drawing_t drawing_in_{};
  std::vector<ViewFrame::Drawn> drawn_;  // by robot; an empty shape list: nothing drawn
  // The newest state, under mutex_.
  uint64_t version_ = 0;
  int64_t run_id_ = 0;
  robot_poses_t poses_{};
  robot_poses_t previous_poses_{};  // the step before poses_: what a status's new counts are about
  robot_poses_t measured_{};
  obstacles_t obstacles_{};
  obstacles_t previous_obstacles_{};
  run_status_t status_{};
  bool status_seen_ = false;
  // The newest status and obstacles of a run not drawn: a run drawn from its
  // first poses on gets them, as they come just before.
  run_status_t unfollowed_status_{};
  obstacles_t unfollowed_obstacles_{};
  std::optional<ViewFrame::OtherWorld> other_world_;  // as last taken
  std::vector<int> radio_senders_;                    // since the last TakeFrame
  // Each robot's newest command (DREAM_CMD_<id>) for a step up to the one drawn; NaN: none yet.
  std::vector<double> command_v_, command_w_;
  std::vector<int64_t> command_step_;
  std::optional<ViewFrame::Judged> judged_;  // the drawn run's DREAM_VERDICT
  int64_t verdicts_refused_ = 0;
  std::deque<ViolationMark> marks_;
  int64_t marks_located_ = 0;
  int64_t bad_messages_ = 0;
  std::function<std::unique_ptr<StepMetrics>()> make_metrics_;
  std::unique_ptr<MetricsThread> metrics_;  // the run drawn's, from its first step seen
  uint64_t metrics_version_ = 0;            // metrics_' readings as last put in a frame
  lcm::LcmInterface& bus_;
  /// Last: unsubscribed first, so the bus never calls a half-destroyed collector.
  std::vector<lcm::Subscription> subscriptions_;
  lcm::Subscription command_subscription_;
  lcm::Subscription commands_subscription_;  // DREAM_CMDS
};

}  // namespace dream::view
