#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "dream/lcm/lcm_interface.h"
#include "dream/view/frame_pacer.h"
#include "dream/view/bus_frame_collector.h"
#include "dream/view/view_server.h"
#include "dream/view/view_setup.h"

namespace dream::view {

/// A run on the bus, drawn live: a BusFrameCollector on `bus` and a pump
/// thread that, at most setup.frame_rates' rate for the run's speed (FramePacer), encodes the newest frame
/// (with who hears whom, when the setup knows) and broadcasts it. The bus
/// is handled by its owner (dream view's loop, or the simulator's own loop
/// in dream run --view): the view adds a handler, never a wait. A page may
/// choose another run heard on the bus: it sends "follow <run id>" (the id
/// in decimal, as frames carry it) on its WebSocket (OnPageMessage).
class LiveView {
 public:
  /// Subscribes on `bus` and starts the pump. `bus` and `server` must outlive
  /// it, and `bus` must not be handled once it is gone (LcmInterface has no
  /// unsubscribe: its handler stays registered).
  LiveView(lcm::LcmInterface& bus, ViewServer& server, ViewSetup setup);
  /// Stops the pump (after one last frame, so the end of a run is shown).
  ~LiveView();
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  /// Encodes and broadcasts the newest frame if it changed; what the pump runs.
  void PumpOnce();
  /// Shows the end of the run recorded at `log_path` (its last obstacles,
  /// status and poses), for a run on this process's memq bus, whose last
  /// messages no handler reads once the world stops (dream run --view).
  /// @throws std::runtime_error naming the file when it cannot be read.
  void ShowEndOf(const std::string& log_path);
  /// What a page sent: "follow <run id>" draws that run (BusFrameCollector::Follow);
  /// "commands": it shows the command arrows (see ViewSetup::commands_on_request);
  /// anything else is ignored. Returns whether it was a request taken.
  bool OnPageMessage(const std::string& message);
  /// What pages asked that takes the bus's thread: the commands subscribed
  /// once a page asked for them. For the bus's owner, between handlings.
  void TakePageRequests();
  /// Frames broadcast so far.
  int64_t frames_sent() const { return frames_sent_.load(); }
  const BusFrameCollector& collector() const { return collector_; }

 private:
  void AddRadioLinks(ViewFrame* frame);

  ViewServer& server_;
  ViewSetup setup_;
  BusFrameCollector collector_;
  FramePacer pacer_;
  uint64_t version_ = 0;
  ViewFrame frame_;
  std::atomic<int64_t> frames_sent_{0};
  std::atomic<bool> stop_{false};
  std::atomic<bool> commands_asked_{false};
  std::thread pump_;
};

}  // namespace dream::view
