#include "dream/go_to_goal/go_to_goal_builder.h"
#include "dream/kind_api/field_reader.h"

#include <algorithm>
#include <cmath>

namespace dream::go_to_goal {
namespace {

/// Reports the largest final distance to goal and when everyone had arrived.
class GoToGoalMetrics final : public agents::ExperimentMetrics {
 public:
  /// `goal_tolerance_m` 0: each robot's own tolerance_m.
  GoToGoalMetrics(std::vector<GoToGoalParams> params, double goal_tolerance_m)
      : params_(std::move(params)), goal_tolerance_m_(goal_tolerance_m) {}
  void Observe(const agents::WorldSnapshot& world) override {
    double worst = 0.0;
    bool all_in = true;
    for (size_t i = 0; i < params_.size() && i < world.poses.size(); ++i) {
      const double d = (world.poses[i].head<2>() - params_[i].goal_m).norm();
      worst = std::max(worst, d);
      all_in = all_in && d <= ToleranceOf(i);  // compared in full precision: no rounding
    }
    final_worst_m_ = worst;
    if (all_in && arrived_step_ < 0) arrived_step_ = world.step;
  }
  void Write(agents::MetricsReport* report) const override {
    report->values["final_max_goal_error_m"] = final_worst_m_;
    report->values["all_arrived_step"] = static_cast<double>(arrived_step_);
    // One line when every robot has the same tolerance (the goal asks the worst to be within it).
    bool one_tolerance = !params_.empty();
    for (size_t i = 1; i < params_.size(); ++i) one_tolerance = one_tolerance && ToleranceOf(i) == ToleranceOf(0);
    if (one_tolerance) {
      report->thresholds["final_max_goal_error_m"] = {ToleranceOf(0),
                                                      "goal: within " + agents::GoalJudgement::Metres(ToleranceOf(0))};
    }
  }
  // Goal: every robot within its tolerance at once.
  std::optional<agents::GoalJudgement> JudgeGoal(const agents::MetricsReport& report) const override {
    agents::GoalJudgement goal;
    goal.completion_step = static_cast<int64_t>(report.Value("all_arrived_step"));
    goal.met = goal.completion_step >= 0;
    goal.detail = goal.met ? "all at their goals" : "not all at their goals, worst " + WorstText(report);
    return goal;
  }

 private:
  // The worst final error with the digits that tell it from the tolerance
  // nearest to it, and that tolerance: "0.0200082 m on the logged poses (tolerance 0.02 m, ...)".
  std::string WorstText(const agents::MetricsReport& report) const {
    const double worst = report.Value("final_max_goal_error_m");
    if (params_.empty()) return agents::GoalJudgement::Metres(worst);
    double tolerance = ToleranceOf(0);
    for (size_t i = 0; i < params_.size(); ++i) {
      if (std::abs(ToleranceOf(i) - worst) < std::abs(tolerance - worst)) tolerance = ToleranceOf(i);
    }
    // The logged poses: the true ones in simulation (realism on too), the tracker's in a lab run.
    return agents::GoalJudgement::MetresApart(worst, tolerance) + " on the logged poses (tolerance " +
           agents::GoalJudgement::Metres(tolerance) + ", compared unrounded)";
  }

  double ToleranceOf(size_t robot) const {
    return goal_tolerance_m_ > 0 ? goal_tolerance_m_ : params_[robot].tolerance_m;
  }

  std::vector<GoToGoalParams> params_;
  double goal_tolerance_m_ = 0.0;
  double final_worst_m_ = 0.0;
  int64_t arrived_step_ = -1;
};

}  // namespace

GoToGoalBuilder::GoToGoalBuilder(const config::ConfigNode& section, int num_robots) {
  Section fields;
  kind_api::ReadFields(section, num_robots, &fields);
  for (const Eigen::Vector2d& goal : fields.goals) {
    GoToGoalParams params = fields.robot;
    params.goal_m = goal;
    std::string error;
    if (!params.IsValid(&error)) section.FailAtField(error);
    params_.push_back(params);
  }
  goal_tolerance_m_ = fields.goal_tolerance_m;
}

std::unique_ptr<agents::Robot> GoToGoalBuilder::MakeRobot(int robot_id, const agents::RobotParams& params) const {
  return std::make_unique<GoToGoalRobot>(robot_id, params, params_.at(static_cast<size_t>(robot_id)));
}

std::unique_ptr<agents::ExperimentMetrics> GoToGoalBuilder::MakeMetrics() const {
  return std::make_unique<GoToGoalMetrics>(params_, goal_tolerance_m_);
}

std::vector<std::vector<Eigen::Vector2d>> GoToGoalBuilder::GoalsToDraw() const {
  std::vector<std::vector<Eigen::Vector2d>> goals;
  for (const GoToGoalParams& params : params_) goals.push_back({params.goal_m});
  return goals;
}

}  // namespace dream::go_to_goal
