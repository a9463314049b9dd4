#include "dream/calibration_drive/calibration_drive.h"

#include <stdexcept>
#include <string>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::calibration_drive {
namespace {

constexpr double kDt = robotarium::RobotariumConstants::kTimeStepSeconds;

struct Segment {
  double seconds;
  agents::UnicycleCommand command;
};

// Each move from rest holds at least 1.5 s (calibrate's steps from rest need
// 45 steps) and every rest lasts 1.5 s (20 steps at rest before a start).
const std::vector<Segment>& Program() {
  static const std::vector<Segment> program = [] {
    std::vector<Segment> segments;
    auto there_and_back = [&segments](double seconds, agents::UnicycleCommand command) {
      segments.push_back({seconds, command});
      segments.push_back({1.5, {}});
      segments.push_back({seconds, {-command.v_mps, -command.w_radps}});
      segments.push_back({1.5, {}});
    };
    segments.push_back({2.0, {}});
    there_and_back(3.0, {0.05, 0.0});
    there_and_back(2.0, {0.1, 0.0});
    // 0.19, not 0.2: 0.2 m/s turns the wheels at exactly their limit.
    there_and_back(1.5, {0.19, 0.0});
    there_and_back(3.0, {0.0, 1.0});
    there_and_back(1.5, {0.0, 2.0});
    there_and_back(2.0, {0.1, 0.5});
    segments.push_back({3.0, {}});
    return segments;
  }();
  return program;
}

int64_t StepsOf(double seconds) { return static_cast<int64_t>(seconds / kDt + 0.5); }

}  // namespace

agents::UnicycleCommand CalibrationDrive::CommandAt(int64_t step) {
  int64_t start = 0;
  for (const Segment& segment : Program()) {
    const int64_t end = start + StepsOf(segment.seconds);
    if (step >= start && step < end) return segment.command;
    start = end;
  }
  return {};
}

int64_t CalibrationDrive::Steps() {
  int64_t steps = 0;
  for (const Segment& segment : Program()) steps += StepsOf(segment.seconds);
  return steps;
}

std::vector<Eigen::Vector3d> CalibrationDrive::StartPoses(int robots) {
  if (robots < 1 || robots > kMaxRobots) {
    throw std::invalid_argument("CalibrationDrive: " + std::to_string(robots) + " robots; 1 to " +
                                std::to_string(kMaxRobots) + " fit the arena");
  }
  // Four columns 0.8 m apart (a robot drives 0.3 m ahead and back, and its
  // arc swings 0.1 m aside), five rows 0.4 m apart.
  std::vector<Eigen::Vector3d> poses;
  for (int i = 0; i < robots; ++i) {
    const int column = i % 4;
    const int row = i / 4;
    poses.emplace_back(-1.3 + 0.8 * column, -0.8 + 0.4 * row, 0.0);
  }
  return poses;
}

}  // namespace dream::calibration_drive
