// Replays the official Robotarium V2 simulator's recorded runs
// (tests/data/robotarium_v2_reference.csv, made by
// tests/robotarium_reference/generate_reference.py) through UnicycleWorld.
//
// Tolerance: the velocity path (saturation) is plain + - * / and matches
// numpy bit for bit, so error counts must be identical. Poses go through
// sin/cos/atan2; numpy >= 1.22 on AVX-512 machines uses SIMD (SVML) versions
// that differ from glibc's by about one ulp, and those differences add up
// over the steps (~1e-16 per step, hundreds of steps). 1e-12 m/rad bounds
// that with a wide margin while still catching any formula difference (a
// wrong step order or offset shows up at 1e-3 or more). The generator keeps
// every pose more than 1e-10 away from the boundary and collision
// thresholds, so these tiny differences cannot flip a count.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dream/world/run_report.h"
#include "dream/world/unicycle_world.h"
#include "../support/source_tree.h"

namespace dream::world {
namespace {

constexpr double kPoseTolerance = 1e-12;

struct RecordedCommand {
  int robot_id = 0;
  UnicycleCommand command;
};

struct Scenario {
  std::string name;
  int num_robots = 0;
  int num_steps = 0;
  // poses[k] = get_poses() at step k, k = 0 .. num_steps.
  std::vector<std::vector<Pose2>> poses;
  std::vector<std::vector<RecordedCommand>> commands;
  // Cumulative {boundary, collision, actuator} after step k.
  std::vector<ViolationCounts> errors;
  std::string debug_text;
};

std::vector<std::string> SplitCsv(const std::string& line, std::size_t max_fields) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (fields.size() + 1 < max_fields) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string::npos) break;
    fields.push_back(line.substr(start, comma - start));
    start = comma + 1;
  }
  fields.push_back(line.substr(start));
  return fields;
}

double ParseDouble(const std::string& text) {
  // strtod rounds correctly, so Python's repr comes back as the same double.
  return std::strtod(text.c_str(), nullptr);
}

std::vector<Scenario> LoadFixture(const std::string& path, std::string* commit) {
  std::ifstream file(path);
  EXPECT_TRUE(file.good()) << "cannot open " << path;
  std::vector<Scenario> scenarios;
  std::string line;
  while (std::getline(file, line)) {
    if (line.rfind("# official commit: ", 0) == 0) *commit = line.substr(19);
    if (line.empty() || line[0] == '#') continue;
    const std::string kind = line.substr(0, line.find(','));
    if (kind == "debug") {
      scenarios.back().debug_text += line.substr(6) + "\n";
      continue;
    }
    const std::vector<std::string> f = SplitCsv(line, 16);
    if (kind == "scenario") {
      Scenario scenario;
      scenario.name = f.at(1);
      scenario.num_robots = std::stoi(f.at(2));
      scenario.num_steps = std::stoi(f.at(3));
      scenario.poses.assign(static_cast<std::size_t>(scenario.num_steps) + 1,
                            std::vector<Pose2>(static_cast<std::size_t>(scenario.num_robots)));
      scenario.commands.resize(static_cast<std::size_t>(scenario.num_steps));
      scenario.errors.resize(static_cast<std::size_t>(scenario.num_steps));
      scenarios.push_back(std::move(scenario));
    } else if (kind == "pose") {
      const auto step = static_cast<std::size_t>(std::stoi(f.at(1)));
      const auto robot = static_cast<std::size_t>(std::stoi(f.at(2)));
      scenarios.back().poses.at(step).at(robot) = {ParseDouble(f.at(3)), ParseDouble(f.at(4)), ParseDouble(f.at(5))};
    } else if (kind == "cmd") {
      scenarios.back()
          .commands.at(static_cast<std::size_t>(std::stoi(f.at(1))))
          .push_back({std::stoi(f.at(2)), {ParseDouble(f.at(3)), ParseDouble(f.at(4))}});
    } else if (kind == "errors") {
      ViolationCounts& counts = scenarios.back().errors.at(static_cast<std::size_t>(std::stoi(f.at(1))));
      counts.boundary_errors = std::stoll(f.at(2));
      counts.collision_errors = std::stoll(f.at(3));
      counts.actuator_errors = std::stoll(f.at(4));
    } else if (kind != "end") {
      ADD_FAILURE() << "unknown record: " << line;
    }
  }
  return scenarios;
}

class RobotariumReferenceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scenarios_ = LoadFixture(dream::testing::SourceDir() + "/tests/data/robotarium_v2_reference.csv", &commit_);
  }
  std::vector<Scenario> scenarios_;
  std::string commit_;
};

TEST_F(RobotariumReferenceTest, FixtureHasAllScenarios) {
  ASSERT_EQ(scenarios_.size(), 4u);
  EXPECT_EQ(scenarios_[0].name, "mixed");
  EXPECT_EQ(commit_.size(), 40u) << "fixture should name the official commit: " << commit_;
  // The scenarios exercise every rule the world reproduces.
  const ViolationCounts& mixed = scenarios_[0].errors.back();
  EXPECT_GT(mixed.boundary_errors, 0);
  EXPECT_GT(mixed.collision_errors, 0);
  EXPECT_GT(mixed.actuator_errors, 0);
}

TEST_F(RobotariumReferenceTest, ReplayMatchesTheOfficialSimulator) {
  WorldParams params;
  // The Python simulator holds velocities forever; the hardware timeout is ours.
  params.command_timeout_s = std::numeric_limits<double>::infinity();
  for (const Scenario& scenario : scenarios_) {
    SCOPED_TRACE("scenario " + scenario.name);
    UnicycleWorld world(params, scenario.poses[0]);
    double max_error = 0.0;
    for (int k = 0; k <= scenario.num_steps; ++k) {
      const auto step = static_cast<std::size_t>(k);
      for (int i = 0; i < scenario.num_robots; ++i) {
        const Pose2& expected = scenario.poses[step][static_cast<std::size_t>(i)];
        const Pose2& actual = world.poses()[static_cast<std::size_t>(i)];
        const double error = std::max({std::abs(actual.x_m - expected.x_m), std::abs(actual.y_m - expected.y_m),
                                       std::abs(actual.theta_rad - expected.theta_rad)});
        max_error = std::max(max_error, error);
        ASSERT_LE(error, kPoseTolerance) << "step " << k << " robot " << i;
      }
      if (k == scenario.num_steps) break;
      for (const RecordedCommand& recorded : scenario.commands[step]) {
        world.SetCommand(recorded.robot_id, recorded.command);
      }
      world.Step();
      ASSERT_EQ(world.violations(), scenario.errors[step])
          << "step " << k << ": boundary " << world.violations().boundary_errors << " collision "
          << world.violations().collision_errors << " actuator " << world.violations().actuator_errors;
    }
    EXPECT_EQ(RunReport::FromViolations(world.step(), world.violations()).Text(), scenario.debug_text);
    RecordProperty(scenario.name + "_max_pose_error", std::to_string(max_error));
    std::cout << "[ reference ] " << scenario.name << ": " << scenario.num_robots << " robots, " << scenario.num_steps
              << " steps, max |pose difference| = " << max_error << "\n";
  }
}

}  // namespace
}  // namespace dream::world
