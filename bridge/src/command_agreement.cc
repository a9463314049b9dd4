#include "dream/bridge/command_agreement.h"

#include <algorithm>
#include <cmath>

namespace dream::bridge {

CommandAgreement CommandAgreement::Of(const LabReplayWorld& replay) {
  CommandAgreement agreement;
  agreement.steps_ = replay.step();
  for (int i = 0; i < replay.num_robots(); ++i) {
    RobotAgreement robot;
    robot.robot = i;
    for (int64_t k = 0; k < replay.step(); ++k) {
      if (!replay.has_agent_command(k, i)) continue;
      const world::UnicycleCommand& agent = replay.agent_command(k, i);
      const world::UnicycleCommand& lab = replay.track().command(k, i);
      const double dv = agent.v_mps - lab.v_mps;
      const double dw = agent.w_radps - lab.w_radps;
      robot.v_mps.Add(dv, k);
      robot.w_radps.Add(dw, k);
      if (robot.first_different_step < 0 && (std::abs(dv) > kSameTolerance || std::abs(dw) > kSameTolerance)) {
        robot.first_different_step = k;
      }
    }
    agreement.robots_.push_back(robot);
  }
  return agreement;
}

bool CommandAgreement::Same() const {
  return std::all_of(robots_.begin(), robots_.end(),
                     [](const RobotAgreement& robot) { return robot.first_different_step < 0; });
}

bool CommandAgreement::Complete() const {
  return std::all_of(robots_.begin(), robots_.end(),
                     [this](const RobotAgreement& robot) { return robot.v_mps.count() == steps_; });
}

int CommandAgreement::WorstRobot() const {
  int worst = -1;
  double worst_difference = -1.0;
  for (const RobotAgreement& robot : robots_) {
    const double difference = std::max(robot.v_mps.max(), robot.w_radps.max());
    if (difference > worst_difference) {
      worst = robot.robot;
      worst_difference = difference;
    }
  }
  return worst;
}

DifferenceStats CommandAgreement::OverRobots(DifferenceStats RobotAgreement::*figure) const {
  DifferenceStats all;
  for (const RobotAgreement& robot : robots_) all.Merge(robot.*figure);
  return all;
}

double CommandAgreement::MaxVDifference() const { return OverRobots(&RobotAgreement::v_mps).max(); }

double CommandAgreement::MaxWDifference() const { return OverRobots(&RobotAgreement::w_radps).max(); }

nlohmann::ordered_json CommandAgreement::Json() const {
  nlohmann::ordered_json robots = nlohmann::ordered_json::array();
  for (const RobotAgreement& robot : robots_) {
    robots.push_back({{"robot", robot.robot},
                      {"steps_with_command", robot.v_mps.count()},
                      {"rms_v_difference_mps", robot.v_mps.Rms()},
                      {"rms_w_difference_radps", robot.w_radps.Rms()},
                      {"max_v_difference_mps", robot.v_mps.max()},
                      {"max_w_difference_radps", robot.w_radps.max()},
                      {"first_different_step", robot.first_different_step}});
  }
  return robots;
}

}  // namespace dream::bridge
