#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dream/world/run_report.h"
#include "dream/world/run_verdict.h"
#include "dream/world/verdict_reason.h"

namespace dream::world {

/// What DREAM makes of a run: the Robotarium simulator's debug() verdict on
/// its poses, plus every other reason the run is not ready for the lab (the
/// lab verifier's rules, lost robots, conflicts, bad messages, an unmet goal).
/// The verdict is the worst of the reasons'; clean when there are none.
class RunJudgement {
 public:
  /// Starts from the official report: one reason per kind of error it counts
  /// (boundary, collision, obstacle: kRejected; actuator: kWarning).
  explicit RunJudgement(RunReport report);

  void Add(VerdictReason reason);
  void Add(const std::vector<VerdictReason>& reasons);

  RunVerdict verdict() const { return verdict_; }
  const std::vector<VerdictReason>& reasons() const { return reasons_; }
  const RunReport& report() const { return report_; }
  /// True when a reason of `rule` is listed.
  bool Has(const std::string& rule) const;

  /// What `dream run` prints: debug()'s text, word for word, when the run
  /// has no reason beyond it; otherwise debug()'s first line, then (rejected)
  /// its error list, and every reason with where to find out more -- never
  /// "will run on the Robotarium" when a reason says otherwise.
  std::string Text() const;

 private:
  RunReport report_;
  RunVerdict verdict_ = RunVerdict::kClean;
  std::vector<VerdictReason> reasons_;
  size_t official_reasons_ = 0;  // the first reasons_, from report_'s counts
};

}  // namespace dream::world
