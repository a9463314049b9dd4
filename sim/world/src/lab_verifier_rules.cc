#include "dream/world/lab_verifier_rules.h"

#include "dream/world/printf_text.h"

namespace dream::sim {
namespace {

std::string Seconds(double seconds) { return PrintfText("%.2f s", seconds); }

}  // namespace

std::vector<VerdictReason> LabVerifierRules::Check(const Declaration& declared, const Counts& counts) const {
  std::vector<VerdictReason> reasons;
  if (counts.num_robots != declared.num_robots) {
    reasons.push_back({"verifier_robot_count", RunVerdict::kRejected,
                       "the script asks for " + std::to_string(counts.num_robots) + " robots but " +
                           std::to_string(declared.num_robots) +
                           " are declared; the lab's verifier refuses a mismatch",
                       "declare the robot count UPLOAD.txt gives"});
  }
  if (counts.robots_too_close > robots_too_close_limit) {
    reasons.push_back({"verifier_too_close", RunVerdict::kRejected,
                       "robots were too close " + std::to_string(counts.robots_too_close) +
                           " times (pairs x steps); the lab's verifier refuses more than " +
                           std::to_string(robots_too_close_limit),
                       "summary.json violations.collision_errors; dream render RUN to see where"});
  }
  if (counts.robots_outside_boundaries > robots_outside_boundaries_limit) {
    reasons.push_back({"verifier_out_of_bounds", RunVerdict::kRejected,
                       "robots were outside the arena " + std::to_string(counts.robots_outside_boundaries) +
                           " times (robots x steps); the lab's verifier refuses more than " +
                           std::to_string(robots_outside_boundaries_limit),
                       "summary.json violations.boundary_errors; dream render RUN to see where"});
  }
  const double run_s = static_cast<double>(counts.iterations) * time_step_s;
  if (run_s > duration_factor * declared.duration_s) {
    reasons.push_back({"verifier_duration", RunVerdict::kRejected,
                       std::to_string(counts.iterations) + " iterations take " + Seconds(run_s) + ", over " +
                           PrintfText("%g", duration_factor) + " x the declared " +
                           Seconds(declared.duration_s) + "; the lab's verifier stops such a run",
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

}  // namespace dream::sim
