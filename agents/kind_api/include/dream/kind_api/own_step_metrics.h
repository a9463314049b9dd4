#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dream/kind_api/run_poses.h"

namespace dream::kind_api {

/// A kind's own metrics (ControllerKind::own_metrics) followed while a run
/// runs, for the view's plots: fed every step in order, read at any time.
/// Computing may lag the steps (the python kind's figures come from a helper
/// process that works while the run goes on), so a reading says which step
/// it is of; once Pending() is false it is of the last step observed, and
/// then the figures are what own_metrics gives for those steps.
class OwnStepMetrics {
 public:
  /// A figure: its name and value (a per-step series' value at the step read).
  using Figure = std::pair<std::string, double>;

  virtual ~OwnStepMetrics() = default;
  /// The run's next step.
  /// @throws std::runtime_error when the step cannot be followed (its robots differ from the first step's).
  virtual void Observe(const RunPoses::Step& step) = 0;
  /// The newest figures computed, into `figures` (one-number figures and each
  /// per-step series' last value; per-robot lists are no figure); returns the
  /// step they are of, -1 when none is computed yet. Never waits for a
  /// computation: it only collects one that ended and starts the next when due.
  /// @throws std::runtime_error when the computing stopped for good (its process died).
  virtual int64_t Read(std::vector<Figure>* figures) = 0;
  /// Whether steps observed are not in what Read gives yet.
  virtual bool Pending() const = 0;
  /// The last error of the kind's code (a figure it could not compute at some step), empty when none.
  virtual std::string last_error() const = 0;
};

}  // namespace dream::kind_api
