// dream export --calibration's config (CalibrationConfig): the shipped
// config/calibration.yaml is its 8-robot case, so the program, the start
// poses and the step count cannot drift apart; counts outside 1..20 refused.
#include "dream/workflows/calibration_config.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "dream/calibration_drive/calibration_drive.h"
#include "dream/run_config/run_config.h"
#include "../support/source_tree.h"

namespace dream::workflows {
namespace {

run_config::RunConfig Written(int robots) {
  return run_config::LoadRunConfig(config::ConfigNode::LoadString(CalibrationConfig::Text(robots), "written.yaml"));
}

TEST(CalibrationConfigTest, ShippedConfigIsTheEightRobotCase) {
  const run_config::RunConfig shipped =
      run_config::LoadRunConfigFile(dream::testing::SourceDir() + "/config/calibration.yaml");
  const run_config::RunConfig written = Written(8);
  EXPECT_EQ(written.name, "calibration_8");
  EXPECT_EQ(shipped.num_robots, written.num_robots);
  EXPECT_EQ(shipped.sim.max_steps, calibration_drive::CalibrationDrive::Steps());
  EXPECT_EQ(written.sim.max_steps, calibration_drive::CalibrationDrive::Steps());
  EXPECT_TRUE(shipped.sim.stop_when_done);
  EXPECT_TRUE(written.sim.stop_when_done);
  EXPECT_EQ(shipped.controller.Required("kind").AsString(), "calibration_drive");
  EXPECT_EQ(written.controller.Required("kind").AsString(), "calibration_drive");
  ASSERT_EQ(shipped.initial_poses.size(), 8u);
  ASSERT_EQ(written.initial_poses.size(), 8u);
  const std::vector<Eigen::Vector3d> program = calibration_drive::CalibrationDrive::StartPoses(8);
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(shipped.initial_poses[i].x_m, program[i].x(), 1e-9) << i;
    EXPECT_NEAR(shipped.initial_poses[i].y_m, program[i].y(), 1e-9) << i;
    EXPECT_EQ(shipped.initial_poses[i].theta_rad, program[i].z()) << i;
    EXPECT_NEAR(written.initial_poses[i].x_m, program[i].x(), 1e-9) << i;
    EXPECT_NEAR(written.initial_poses[i].y_m, program[i].y(), 1e-9) << i;
  }
}

TEST(CalibrationConfigTest, OneToTwentyRobots) {
  EXPECT_EQ(Written(1).num_robots, 1);
  EXPECT_EQ(Written(20).initial_poses.size(), 20u);
  EXPECT_THROW(CalibrationConfig::Text(0), std::invalid_argument);
  EXPECT_THROW(CalibrationConfig::Text(21), std::invalid_argument);
}

}  // namespace
}  // namespace dream::workflows
