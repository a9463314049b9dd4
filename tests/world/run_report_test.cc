#include "dream/world/run_report.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace dream::world {
namespace {

using ::testing::HasSubstr;

TEST(RunReportTest, CleanRun) {
  const RunReport report = RunReport::FromViolations(30, ViolationCounts{});
  EXPECT_EQ(report.verdict, RunVerdict::kClean);
  EXPECT_DOUBLE_EQ(report.estimated_duration_s, 0.99);
  EXPECT_EQ(report.Text(),
            "Your simulation took approximately 0.99 real seconds to execute.\n\n"
            "No errors or warnings in your simulation!  Your script will run on the Robotarium!\n\n");
  EXPECT_STREQ(RunVerdictName(report.verdict), "clean");
}

TEST(RunReportTest, ActuatorErrorsOnlyAreAWarningWithAPercentage) {
  ViolationCounts violations;
  violations.actuator_errors = 21;
  const RunReport report = RunReport::FromViolations(61, violations);
  EXPECT_EQ(report.verdict, RunVerdict::kWarning);
  EXPECT_EQ(report.Text(),
            "Your simulation took approximately 2.01 real seconds to execute.\n\n"
            "No hard errors detected, your script will run on the Robotarium!\n\n"
            "WARNING: 21 out of 61 (~34%) timesteps had velocity command(s) exceed actuator limits.\n"
            "         A large percentage of exceeded actuator commands will cause noticeable\n"
            "         differences between this simulation and the physical Robotarium.\n");
}

TEST(RunReportTest, PercentRoundsHalfToEvenLikePython) {
  ViolationCounts violations;
  violations.actuator_errors = 1;
  // 100 * 1 / 8 = 12.5 -> Python's "{:.0f}" prints 12.
  EXPECT_THAT(RunReport::FromViolations(8, violations).Text(), HasSubstr("(~12%)"));
  EXPECT_THAT(RunReport::FromViolations(0, violations).Text(), HasSubstr("1 out of 0 (~100%)"));
}

TEST(RunReportTest, BoundaryOrCollisionErrorsReject) {
  ViolationCounts violations;
  violations.collision_errors = 75;
  violations.boundary_errors = 359;
  violations.actuator_errors = 420;
  const RunReport report = RunReport::FromViolations(420, violations);
  EXPECT_EQ(report.verdict, RunVerdict::kRejected);
  EXPECT_EQ(report.Text(),
            "Your simulation took approximately 13.86 real seconds to execute.\n\n"
            "Errors detected, your script will NOT run on the Robotarium!\n\n"
            "Errors:\n"
            "\t Simulation had 75 time steps where robots were too close (potential collision).\n"
            "\t Simulation had 359 time steps where robots were outside boundaries.\n"
            "\nPlease fix the noted errors in your simulation; otherwise, your experiment will be rejected.\n");
}

TEST(RunReportTest, ObstacleOverlapsAreHardErrors) {
  ViolationCounts violations;
  violations.obstacle_collisions = 4;
  const RunReport report = RunReport::FromViolations(100, violations);
  EXPECT_EQ(report.verdict, RunVerdict::kRejected);
  EXPECT_THAT(report.Text(), HasSubstr("\t Simulation had 4 robot-obstacle overlaps"));
  EXPECT_THAT(report.Text(), ::testing::Not(HasSubstr("too close")));
}

TEST(RunReportTest, DurationUsesTheGivenTimeStep) {
  EXPECT_DOUBLE_EQ(RunReport::FromViolations(100, ViolationCounts{}, 0.01).estimated_duration_s, 1.0);
}

}  // namespace
}  // namespace dream::world
