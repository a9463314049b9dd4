#include "dream/world/lab_verifier_rules.h"

#include "dream/world/printf_text.h"

namespace dream::world {
namespace {

std::string Seconds(double seconds) { return PrintfText("%.2f s", seconds); }

// A count the lab's verifier caps, over its cap: "robots were <what> <count>
// times (<counted>); ..." and where to look (summary.json's `summary_key`).
VerdictReason OverVerifierLimit(const std::string& rule, const std::string& what, int64_t count,
                                const std::string& counted, int64_t limit, const std::string& summary_key) {
  return {rule, RunVerdict::kRejected,
          "robots were " + what + " " + std::to_string(count) + " times (" + counted +
              "); the lab's verifier refuses more than " + std::to_string(limit),
          "summary.json violations." + summary_key + "; dream render RUN to see where"};
}

}  // namespace

std::vector<VerdictReason> LabVerifierRules::Check(const Declaration& declared, const Counts& counts) const {
  std::vector<VerdictReason> reasons;
  if (counts.num_robots != declared.num_robots) {
    reasons.push_back({"verifier_robot_count", RunVerdict::kRejected,
                       "the script asks for " + std::to_string(counts.num_robots) + " robots but " +
                           std::to_string(declared.num_robots) + " are declared; the lab's verifier refuses a mismatch",
                       "declare the robot count UPLOAD.txt gives"});
  }
  if (counts.robots_too_close > robots_too_close_limit) {
    reasons.push_back(OverVerifierLimit("verifier_too_close", "too close", counts.robots_too_close, "pairs x steps",
                                        robots_too_close_limit, "collision_errors"));
  }
  if (counts.robots_outside_boundaries > robots_outside_boundaries_limit) {
    reasons.push_back(OverVerifierLimit("verifier_out_of_bounds", "outside the arena", counts.robots_outside_boundaries,
                                        "robots x steps", robots_outside_boundaries_limit, "boundary_errors"));
  }
  const double run_s = static_cast<double>(counts.iterations) * time_step_s;
  if (run_s > duration_factor * declared.duration_s) {
    reasons.push_back({"verifier_duration", RunVerdict::kRejected,
                       std::to_string(counts.iterations) + " iterations take " + Seconds(run_s) + ", over " +
                           PrintfText("%g", duration_factor) + " x the declared " + Seconds(declared.duration_s) +
                           "; the lab's verifier stops such a run",
                       "declare the duration UPLOAD.txt gives"});
  }
  if (declared.duration_s > max_duration_s || run_s > max_duration_s) {
    reasons.push_back({"lab_duration_cap", RunVerdict::kRejected,
                       "the experiment takes " + Seconds(declared.duration_s > run_s ? declared.duration_s : run_s) +
                           " with the export's settle steps, over the lab's cap of " + Seconds(max_duration_s),
                       "fewer steps (`steps:` or --steps) or dream export --settle-steps"});
  }
  return reasons;
}

}  // namespace dream::world
