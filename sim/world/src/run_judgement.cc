#include "dream/world/run_judgement.h"

#include <algorithm>

namespace dream::world {
namespace {

const char* const kFindOutViolations =
    "summary.json violations_located says where and when; trajectories.png and dream render RUN mark them";

}  // namespace

RunJudgement::RunJudgement(RunReport report) : report_(std::move(report)) {
  const ViolationCounts& v = report_.violations;
  if (v.boundary_errors > 0) {
    Add({"boundary", RunVerdict::kRejected, std::to_string(v.boundary_errors) + " steps with a robot outside the arena",
         kFindOutViolations});
  }
  if (v.collision_errors > 0) {
    Add({"collision", RunVerdict::kRejected,
         std::to_string(v.collision_errors) + " times robots were too close (pairs x steps)", kFindOutViolations});
  }
  if (v.obstacle_collisions > 0) {
    Add({"obstacle", RunVerdict::kRejected,
         std::to_string(v.obstacle_collisions) + " robot-obstacle overlaps (robots x steps)", kFindOutViolations});
  }
  if (v.actuator_errors > 0) {
    Add({"actuator", RunVerdict::kWarning,
         std::to_string(v.actuator_errors) + " steps with a wheel over its speed limit (saturated, as on the lab)",
         "summary.json violations.actuator_errors"});
  }
  official_reasons_ = reasons_.size();
}

void RunJudgement::Add(VerdictReason reason) {
  verdict_ = std::max(verdict_, reason.verdict);
  reasons_.push_back(std::move(reason));
}

void RunJudgement::Add(const std::vector<VerdictReason>& reasons) {
  for (const VerdictReason& reason : reasons) Add(reason);
}

bool RunJudgement::Has(const std::string& rule) const {
  return std::any_of(reasons_.begin(), reasons_.end(), [&](const VerdictReason& r) { return r.rule == rule; });
}

std::string RunJudgement::Text() const {
  const std::string official = report_.Text();
  if (reasons_.size() == official_reasons_) return official;  // debug()'s own case, word for word
  auto list = [this](size_t from) {
    std::string text;
    for (size_t i = from; i < reasons_.size(); ++i) text += "  - " + reasons_[i].Text() + "\n";
    return text;
  };
  if (report_.verdict == RunVerdict::kRejected) {
    // debug() already says it will not run; add what it cannot see.
    return official + "\nAlso:\n" + list(official_reasons_);
  }
  const size_t first_line_end = official.find("\n\n");
  std::string text = official.substr(0, first_line_end == std::string::npos ? official.size() : first_line_end + 2);
  switch (verdict_) {
    case RunVerdict::kRejected:
      text += "The lab's verifier would refuse this run, your script will NOT run on the Robotarium!\n";
      break;
    case RunVerdict::kNotReady:
      text += "The Robotarium's checks pass on the poses, but this run is NOT ready for the Robotarium:\n";
      break;
    default:  // warnings only (e.g. a robot lost to world.realism's tracker): the lab runs it
      text += "The Robotarium's checks pass on the poses; your script will run on the Robotarium, with warnings:\n";
      break;
  }
  return text + list(0);
}

}  // namespace dream::world
