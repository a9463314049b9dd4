#pragma once

#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "dream/lcm/lcm_bus.h"
#include "dream/python_embedded/python_agent_host.h"
#include "dream/python_host/busy_announcer.h"
#include "dream/python_host/relay_link.h"

namespace dream::python_host {

/// Python controllers in a process of their own (`dream-agent-shared --python-host`,
/// in its own process group), relayed to and from a bus of this one over a
/// socket: nothing a controller does can take the command hosting it down or
/// hide from it. os._exit() or a crash ends only that process: its robots are
/// lost, each with a fault naming the exit code or signal (and the line, from
/// Python's faulthandler, which it sets up). A call stuck outside Python (a
/// long time.sleep, a blocking read, C code), which the process's own
/// watchdog cannot stop, is timed here through the call cell the two share:
/// kKillAfterRaiseFraction of the world's agent_timeout_s (loading and
/// setup(): of its start_timeout_s) after the watchdog raised in it, or at
/// kKillUnraisedFraction when it never could, the process group is killed
/// and its robots are lost, the stuck one with the line it was stuck on. Its signal handlers are its
/// own, and whatever it forks belongs to its group: the group is killed
/// (SIGKILL after kGraceS) when this object goes, so no process outlives it.
///
/// The relay forwards the world's DREAM_POSES, DREAM_OBSTACLES and
/// DREAM_STATUS and the other agents' DREAM_RADIO_<id> to the process, and
/// its DREAM_CMD_<id>, DREAM_RADIO_<id> and DREAM_FAULT_<id> back, in order.
/// While a long call holds its robots' answers up, it says so on
/// DREAM_BUSY_<id> (BusyAnnouncer), so the world waits for this object's
/// verdict on the call instead of racing it.
class PythonHostProcess final : public python_embedded::PythonAgentHost {
 public:
  struct Limits {
    /// The world's agent_timeout_s and start_timeout_s (0: the defaults).
    double agent_timeout_s = 0.0;
    double start_timeout_s = 0.0;
    /// The host ends after this long without a step of its run (0: never;
    /// it ends when this object goes).
    double idle_timeout_s = 0.0;
  };
  /// In the check before a run (no world to wait), a call is ended at this
  /// fraction of its limit: after the process's own watchdog (0.8, which
  /// stops a call running Python code with the line it was on).
  static constexpr double kKillFraction = 0.9;
  /// In a run, a call still running this fraction of its limit after the
  /// watchdog raised ControllerTimeout in it (the cell says so) is ended: the
  /// raise had its chance, and the world waits meanwhile (DREAM_BUSY_<id>).
  static constexpr double kKillAfterRaiseFraction = 0.5;
  /// A call the watchdog never raised in (its thread starved, or blocked) is
  /// ended at this fraction of its limit (the world holds at most 10).
  static constexpr double kKillUnraisedFraction = 3.0;
  /// A stuck call's traceback is awaited at most this fraction of its limit
  /// (it comes at once unless the child is starved): the world's hold from
  /// the last DREAM_BUSY_<id> note, a quarter old at most, covers it.
  static constexpr double kTraceWaitFraction = 0.25;
  /// In the check before a run: its own bound, so the check ends within
  /// start_timeout_s (kKillFraction plus this).
  static constexpr double kCheckTraceWaitFraction = 0.05;
  /// How long the process gets to end by itself before SIGKILL.
  static constexpr double kGraceS = 1.0;

  /// Loads the controller's module and class and checks its own keys, in a
  /// process of its own. @throws config::ConfigError naming file, line and
  /// key, also when loading the module ends or hangs the process;
  /// std::runtime_error when Python cannot start or the check is interrupted
  /// (`stop` set: Ctrl-C).
  static void Check(const std::string& spec_json, double start_timeout_s, const std::atomic<bool>& stop);

  /// Starts the process for the agents of `robot_ids` and relays `bus`;
  /// returns at once (loading and setup() run there, bounded as above).
  PythonHostProcess(lcm::LcmBus& bus, const std::string& spec_json, const std::vector<int>& robot_ids, int64_t agent_id,
                    const Limits& limits);
  ~PythonHostProcess() override;
  PythonHostProcess(const PythonHostProcess&) = delete;
  PythonHostProcess& operator=(const PythonHostProcess&) = delete;

  /// Handles `bus` until the process ends (dream agent): true when the
  /// world ended the run. `stop` ends the process (SIGTERM, then SIGKILL).
  bool Run(lcm::LcmBus& bus, const std::atomic<bool>& stop, double idle_timeout_s) override;
  bool world_finished() const override;
  int64_t last_step_answered() const override;
  std::string end_detail() const override;
  std::string ReportJson() const override;

 private:
  using Clock = std::chrono::steady_clock;
  /// The world's step the faults this object sends belong to.
  struct Step {
    int64_t utime = 0;
    int64_t step = -1;
    int64_t run_id = 0;
  };

  void OnBusMessage(const std::string& channel, const void* data, int size);
  void RelayLoop();
  void HandleFrame(const RelayLink::Frame& frame);
  /// Notes what `frame` says (with mutex_); true when it is to be published.
  bool Take(const RelayLink::Frame& frame);
  /// Tells the world which robots' answers a long call holds up (BusyAnnouncer).
  void SayBusy(Clock::time_point now);
  /// The stuck call's description when the call in the cell ran too long.
  std::string StuckCall(Clock::time_point now);
  /// Ends the process group (SIGUSR1 first when `trace`, for the line), reaps
  /// it, and reports every robot not yet failed as lost: with `why`, or as
  /// ended by itself (`exit_text`) unless it ended as asked.
  void EndProcess(const std::string& why, const std::string& exit_text, bool trace);
  void PublishFaults(const std::string& culprit_detail, int64_t culprit, const std::string& others_detail);
  bool Ended() const;

  lcm::LcmBus& bus_;
  std::vector<int> robot_ids_;
  int64_t agent_id_;
  Limits limits_;
  std::string module_path_;
  pid_t pid_ = -1;
  std::unique_ptr<RelayLink> link_;
  int trace_fd_ = -1;
  int wake_fd_ = -1;
  std::atomic<int64_t>* cell_ = nullptr;
  std::thread relay_;
  std::atomic<bool> quit_{false};
  lcm::Subscription subscription_;  // to the bus's messages for the host; cancelled first when destroyed
  Clock::time_point started_;
  // busy_.NextDue(), stored under mutex_ whenever busy_ changes, read without
  // it: SayBusy's quiet passes (the most) take no lock.
  std::atomic<Clock::rep> busy_due_from_{Clock::time_point::max().time_since_epoch().count()};

  mutable std::mutex mutex_;  // guards what follows
  std::string outbox_;        // frames for the process, not yet written
  bool ready_ = false;
  bool ended_ = false;
  bool done_received_ = false;
  bool world_finished_ = false;
  int64_t last_step_answered_ = -1;
  std::string end_detail_;
  std::string report_json_ = "{}";
  std::string error_;
  std::set<int> failed_;  // robots whose fault the process sent
  BusyAnnouncer busy_;    // which robots' answers to the step are held up
  Step world_step_;       // the latest DREAM_POSES forwarded
  Step answered_step_;    // the step of the process's latest answer (its run)
  std::string trace_;     // faulthandler's output so far
  int64_t watched_token_ = 0;
  Clock::time_point watched_since_;
  int64_t raised_token_ = 0;       // the latest call the watchdog was seen to raise in
  Clock::time_point raised_seen_;  // when that was first seen
};

}  // namespace dream::python_host
