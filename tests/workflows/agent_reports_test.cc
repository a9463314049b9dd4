// AgentReports: what dream launch's agents refused, read together (and the
// reports removed), one missing report listed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../bridge/bridge_test_support.h"
#include "dream/workflows/agent_reports.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

void WriteReport(const std::string& out_dir, int robot, const std::string& json) {
  const std::string path = AgentReports::PathFor(out_dir, robot);
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << json;
}

TEST(AgentReportsTest, ReportsAreAddedUpAndRemovedAndAMissingOneListed) {
  const std::string out = bridge::testing::NewFolder("agent_reports");
  WriteReport(out, 0,
              R"({"bad_messages": {"DREAM_POSES": 2}, "bad_message_first": {"DREAM_POSES": "step 3: did not decode"},
                  "other_runs": ["00ab"], "steps_out_of_sequence": 0})");
  WriteReport(out, 2, R"({"bad_messages": {"DREAM_POSES": 1}, "other_runs": [], "steps_out_of_sequence": 4})");
  const AgentReports reports = AgentReports::Read(out, 3);
  EXPECT_EQ(reports.section["bad_messages"]["DREAM_POSES"], 3);
  EXPECT_EQ(reports.section["steps_out_of_sequence"], 4);
  EXPECT_EQ(reports.section["reports_missing"], nlohmann::ordered_json::array({1}));
  EXPECT_THAT(reports.problem, HasSubstr("the agents refused 3 message(s): DREAM_POSES: 3, first refused: step 3: "
                                         "did not decode (the agent of robot 0)"));
  EXPECT_THAT(reports.problem, HasSubstr("heard 1 other run(s), ignored 4 step(s) out of sequence"));
  EXPECT_FALSE(fs::exists(fs::path(AgentReports::PathFor(out, 0)).parent_path()));
}

TEST(AgentReportsTest, AgentsThatRefusedNothingAreNoProblem) {
  const std::string out = bridge::testing::NewFolder("agent_reports_clean");
  WriteReport(out, 0, R"({"bad_messages": {}, "other_runs": [], "steps_out_of_sequence": 0})");
  const AgentReports reports = AgentReports::Read(out, 1);
  EXPECT_EQ(reports.problem, "");
  EXPECT_EQ(reports.section["reports_missing"], nlohmann::ordered_json::array());
}

}  // namespace
}  // namespace dream::workflows
