// LogWorkflow: dream log's info, diff and echo printed, on a simulated run's log.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include "dream/workflows/log_workflow.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string LogOfSimulatedRun() { return testing::SimulatedRun() + "/run.lcmlog"; }

TEST(LogWorkflowTest, InfoPrintsEveryChannelsEvents) {
  std::ostringstream out;
  LogWorkflow(out).Info(LogOfSimulatedRun());
  EXPECT_THAT(out.str(), StartsWith(LogOfSimulatedRun() + ": "));
  EXPECT_THAT(out.str(), HasSubstr(" s of log time\n"));
  EXPECT_THAT(out.str(), HasSubstr("\n  DREAM_POSES: "));
  EXPECT_THAT(out.str(), HasSubstr("\n  DREAM_CMD_7: "));
}

TEST(LogWorkflowTest, DiffOfALogWithItselfIsSame) {
  std::ostringstream out;
  const std::string log = LogOfSimulatedRun();
  EXPECT_TRUE(LogWorkflow(out).Diff(log, "a", log, "b", std::regex("DREAM_.*"), "DREAM_.*", false));
  EXPECT_EQ(out.str(), "same (channels matching 'DREAM_.*')\n");
}

TEST(LogWorkflowTest, EchoPrintsAtMostTheLimit) {
  std::ostringstream out;
  std::ostringstream problems;
  LogWorkflow(out, problems).Echo(LogOfSimulatedRun(), std::regex("DREAM_CMD_0"), "DREAM_CMD_0", 2);
  const std::string lines = out.str();
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 2) << lines;
  EXPECT_THAT(lines, StartsWith("{\"channel\":\"DREAM_CMD_0\""));
  EXPECT_EQ(problems.str(), "");
}

}  // namespace
}  // namespace dream::workflows
