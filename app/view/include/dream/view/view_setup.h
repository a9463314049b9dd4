#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dream/render/arena_overlays.h"
#include "dream/view/frame_rates.h"
#include "dream/view/step_metrics.h"
#include "dream/world/world_params.h"

namespace dream::view {

/// What does not change during a run and the page needs before any frame:
/// the arena, the robots' size, and what the run's config adds (goals,
/// sensor reaches, who hears whom), when a config is known.
struct ViewSetup {
  enum class Mode { kLive, kReplay };
  Mode mode = Mode::kLive;
  /// The arena (boundary checks), the time step and the collision rule.
  world::WorldParams world;
  /// What the run's config adds; empty without a config (live from the bus).
  render::ArenaOverlays overlays;
  /// Live: the run's metrics followed step by step (a new one for each run
  /// drawn), for the page's plots over time; none without a config.
  std::function<std::unique_ptr<StepMetrics>()> metrics;
  /// Live: the robots' commands (the command arrows) only once a page asks
  /// ("commands" on its WebSocket: it shows them), and from then on; what
  /// `dream view` does on udpm, where they are most of the datagrams. The
  /// bus's owner then calls LiveView::TakePageRequests on the bus's thread.
  bool commands_on_request = false;
  /// Where the frames come from, shown on the page (a URL or a run folder).
  std::string source;
  /// Live: frames sent to the browsers a second at most, by the run's speed
  /// (the page draws no more often). `dream view --fps`, `dream run
  /// --view-fps` set one rate (FrameRates::One).
  FrameRates frame_rates;
  /// The run's judgement as its summary.json holds it (the one judge's:
  /// Robotarium errors, the goal, the run's state), for a replay of a run
  /// folder that has one: the page shows it as the verdict at the run's end,
  /// so the view never ends a run with a verdict of its own.
  struct Judged {
    static constexpr size_t kMaxListed = 64;  ///< reasons, and metrics, at most
    std::string verdict;                      ///< clean, warning, not_ready or rejected
    std::vector<std::string> reasons;         ///< "rule: problem" each
    std::string goal;                         ///< "met at step N (...)", "missed (...)", "none declared"
    /// The experiment's metrics (summary.json's metrics: name, value as text),
    /// the ones that are one number, flag or word each.
    std::vector<std::pair<std::string, std::string>> metrics;
  };
  std::optional<Judged> judged;
};

}  // namespace dream::view
