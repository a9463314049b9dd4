#include "dream/agents/controller_factory.h"

#include <stdexcept>

#include "dream/agents/go_to_goal_controller.h"

namespace dream::agents {
namespace {

std::string JoinKinds() {
  std::string list;
  for (const std::string& kind : ControllerFactory::Kinds()) list += (list.empty() ? "" : ", ") + kind;
  return list;
}

GoToGoalParams ReadGoToGoal(const config::ConfigNode& section, int robot_id) {
  GoToGoalParams params;
  const config::ConfigNode goals = section.Required("goals");
  const config::ConfigNode goal = goals[static_cast<size_t>(robot_id)];
  const std::vector<double> xy = goal.AsDoubles();
  if (xy.size() != 2) goal.Fail("expected [x, y] in metres, got " + std::to_string(xy.size()) + " numbers");
  params.goal_m = Eigen::Vector2d(xy[0], xy[1]);
  params.gain = section.GetDouble("gain", params.gain);
  params.max_speed_mps = section.GetDouble("max_speed_mps", params.max_speed_mps);
  params.tolerance_m = section.GetDouble("tolerance_m", params.tolerance_m);
  std::string error;
  if (!params.IsValid(&error)) section.Fail(error);
  return params;
}

}  // namespace

std::vector<std::string> ControllerFactory::Kinds() { return {"go_to_goal"}; }

ControllerFactory::ControllerFactory(const config::ConfigNode& section, int num_robots)
    : section_(section), num_robots_(num_robots) {
  kind_ = section_.Required("kind").AsString();
  if (kind_ == "go_to_goal") {
    section_.RejectUnknownKeys({"kind", "goals", "gain", "max_speed_mps", "tolerance_m"});
    const config::ConfigNode goals = section_.Required("goals");
    if (!goals.IsSequence() || goals.size() != static_cast<size_t>(num_robots_)) {
      goals.Fail("expected one [x, y] goal per robot (" + std::to_string(num_robots_) + "), got " +
                 (goals.IsSequence() ? std::to_string(goals.size()) : std::string("no list")));
    }
    for (int id = 0; id < num_robots_; ++id) ReadGoToGoal(section_, id);  // validate all up front
    return;
  }
  section_.Required("kind").Fail("unknown controller kind '" + kind_ + "'; known kinds: " + JoinKinds());
}

std::unique_ptr<Controller> ControllerFactory::Make(int robot_id) const {
  if (robot_id < 0 || robot_id >= num_robots_) {
    throw std::out_of_range("robot " + std::to_string(robot_id) + " is not in this run (robots 0.." +
                            std::to_string(num_robots_ - 1) + ")");
  }
  return std::make_unique<GoToGoalController>(ReadGoToGoal(section_, robot_id));
}

}  // namespace dream::agents
