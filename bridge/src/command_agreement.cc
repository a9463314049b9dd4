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
    double dv2 = 0.0;
    double dw2 = 0.0;
    for (int64_t k = 0; k < replay.step(); ++k) {
      if (!replay.has_agent_command(k, i)) continue;
      const sim::UnicycleCommand& agent = replay.agent_command(k, i);
      const sim::UnicycleCommand& lab = replay.track().command(k, i);
      const double dv = std::abs(agent.v_mps - lab.v_mps);
      const double dw = std::abs(agent.w_radps - lab.w_radps);
      dv2 += dv * dv;
      dw2 += dw * dw;
      robot.max_v_difference_mps = std::max(robot.max_v_difference_mps, dv);
      robot.max_w_difference_radps = std::max(robot.max_w_difference_radps, dw);
      if (robot.first_different_step < 0 && (dv > kSameTolerance || dw > kSameTolerance)) {
        robot.first_different_step = k;
      }
      ++robot.steps_with_command;
    }
    if (robot.steps_with_command > 0) {
      robot.rms_v_difference_mps = std::sqrt(dv2 / static_cast<double>(robot.steps_with_command));
      robot.rms_w_difference_radps = std::sqrt(dw2 / static_cast<double>(robot.steps_with_command));
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
                     [this](const RobotAgreement& robot) { return robot.steps_with_command == steps_; });
}

int CommandAgreement::WorstRobot() const {
  int worst = -1;
  double worst_difference = -1.0;
  for (const RobotAgreement& robot : robots_) {
    const double difference = std::max(robot.max_v_difference_mps, robot.max_w_difference_radps);
    if (difference > worst_difference) {
      worst = robot.robot;
      worst_difference = difference;
    }
  }
  return worst;
}

nlohmann::ordered_json CommandAgreement::Json() const {
  nlohmann::ordered_json robots = nlohmann::ordered_json::array();
  for (const RobotAgreement& robot : robots_) {
    robots.push_back({{"robot", robot.robot},
                      {"steps_with_command", robot.steps_with_command},
                      {"rms_v_difference_mps", robot.rms_v_difference_mps},
                      {"rms_w_difference_radps", robot.rms_w_difference_radps},
                      {"max_v_difference_mps", robot.max_v_difference_mps},
                      {"max_w_difference_radps", robot.max_w_difference_radps},
                      {"first_different_step", robot.first_different_step}});
  }
  return robots;
}

}  // namespace dream::bridge
