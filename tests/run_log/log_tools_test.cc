// What `dream log` says of a log, without a process: two logs compared
// (LogDifference), a log echoed as JSON (LogEcho) and counted per channel
// (LogChannelCounts).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "dream/run_log/log_channel_counts.h"
#include "dream/run_log/log_difference.h"
#include "dream/run_log/log_echo.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::run_log {
namespace {

using testing::SyntheticRunLog;
using testing::TempFolder;

const std::regex kEveryChannel(".*");

TEST(LogDifferenceTest, EqualLogsAreTheSame) {
  TempFolder folder;
  const std::string a = SyntheticRunLog::TwoRobots(folder / "a.lcmlog", 5).Write();
  const std::string b = SyntheticRunLog::TwoRobots(folder / "b.lcmlog", 5).Write();
  const LogDifference difference = LogDifference::Compare({a, a}, {b, b}, kEveryChannel, false);
  EXPECT_TRUE(difference.same());
  EXPECT_TRUE(difference.differences().empty());
}

TEST(LogDifferenceTest, NamesTheStepRobotAndFieldThatDiffer) {
  TempFolder folder;
  const std::string a = SyntheticRunLog(folder / "a.lcmlog").Poses(0, {{0, 0, 0}, {1, 1, 0}}).Write();
  const std::string b = SyntheticRunLog(folder / "b.lcmlog").Poses(0, {{0, 0, 0}, {1, 1.5, 0}}).Write();
  const LogDifference difference = LogDifference::Compare({a, a}, {b, b}, kEveryChannel, false);
  ASSERT_EQ(difference.differences().size(), 1u);
  EXPECT_EQ(difference.differences()[0], "DREAM_POSES: message 0 differs first at step 0, robot 1: y 1.0 vs 1.5");
}

TEST(LogDifferenceTest, NamesAChannelOnlyOneLogHasAndCountsThatDiffer) {
  TempFolder folder;
  const std::string a = SyntheticRunLog(folder / "a.lcmlog").Poses(0, {{0, 0, 0}}).Poses(1, {{1, 0, 0}}).Write();
  const std::string b = SyntheticRunLog(folder / "b.lcmlog").Poses(0, {{0, 0, 0}}).Radio(0, 0).Write();
  const LogDifference difference = LogDifference::Compare({a, a}, {b, b}, kEveryChannel, false);
  EXPECT_FALSE(difference.same());
  EXPECT_EQ(difference.differences(), (std::vector<std::string>{"DREAM_POSES: 2 messages in " + a + ", 1 in " + b,
                                                                "DREAM_RADIO_0: only in " + b}));
  // Only the channels asked for are compared.
  EXPECT_TRUE(LogDifference::Compare({a, a}, {b, b}, std::regex("DREAM_POSES"), false).differences().size() == 1u);
  EXPECT_TRUE(LogDifference::Compare({a, a}, {b, b}, std::regex("DREAM_STATUS"), false).same());
}

TEST(LogDifferenceTest, AResendCountsOnceUnlessRaw) {
  TempFolder folder;
  const std::string once = SyntheticRunLog(folder / "once.lcmlog").Poses(0, {{0, 0, 0}}).Write();
  const std::string twice =
      SyntheticRunLog(folder / "twice.lcmlog").Poses(0, {{0, 0, 0}}).Poses(0, {{0, 0, 0}}).Write();
  EXPECT_TRUE(LogDifference::Compare({once, once}, {twice, twice}, kEveryChannel, false).same());
  EXPECT_FALSE(LogDifference::Compare({once, once}, {twice, twice}, kEveryChannel, true).same());
}

TEST(LogDifferenceTest, AMissingLogIsAnErrorNamingIt) {
  TempFolder folder;
  const std::string a = SyntheticRunLog::TwoRobots(folder / "a.lcmlog", 2).Write();
  try {
    LogDifference::Compare({a, a}, {folder / "missing", "missing"}, kEveryChannel, false);
    FAIL() << "compared with a missing log";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(folder / "missing"), std::string::npos) << e.what();
  }
}

TEST(LogEchoTest, PrintsEachMessageAsOneJsonLineUpToTheLimit) {
  TempFolder folder;
  const std::string log = SyntheticRunLog::TwoRobots(folder / "run.lcmlog", 4).Write();
  std::ostringstream out;
  std::ostringstream problems;
  LogEcho::Print({log, std::regex("DREAM_POSES"), "DREAM_POSES", 3}, out, problems);
  std::istringstream lines(out.str());
  std::string line;
  int count = 0;
  while (std::getline(lines, line)) {
    EXPECT_EQ(line.rfind("{\"channel\":\"DREAM_POSES\",\"utime\":", 0), 0u) << line;
    EXPECT_NE(line.find("\"type\":\"robot_poses_t\""), std::string::npos) << line;
    ++count;
  }
  EXPECT_EQ(count, 3);
  EXPECT_EQ(problems.str(), "");
}

TEST(LogEchoTest, SkipsForeignChannelsAndSaysWhenNoChannelMatched) {
  TempFolder folder;
  const std::string log = SyntheticRunLog(folder / "run.lcmlog").Poses(0, {{0, 0, 0}}).Other("OTHER").Write();
  std::ostringstream out;
  std::ostringstream problems;
  LogEcho::Print({log, std::regex("OTHER"), "OTHER", 0}, out, problems);
  EXPECT_EQ(out.str(), "");
  EXPECT_EQ(problems.str(), "skipped 1 events on channels of no DREAM type: OTHER (1)\n");

  std::ostringstream none;
  LogEcho::Print({log, std::regex("NOPE"), "NOPE", 0}, out, none);
  EXPECT_EQ(none.str(), log + ": no event on a channel matching 'NOPE' (channels: DREAM_POSES, OTHER)\n");
}

TEST(LogChannelCountsTest, CountsEventsAndBytesPerChannel) {
  TempFolder folder;
  const std::string log = SyntheticRunLog(folder / "run.lcmlog").Poses(0, {{0, 0, 0}}).Poses(3, {{1, 0, 0}}).Write();
  const LogChannelCounts counts = LogChannelCounts::Read(log);
  EXPECT_EQ(counts.path(), log);
  EXPECT_EQ(counts.events(), 2);
  EXPECT_DOUBLE_EQ(counts.seconds(), 3 * 0.033);
  ASSERT_EQ(counts.channels().size(), 1u);
  EXPECT_EQ(counts.channels().at("DREAM_POSES").events, 2);
  EXPECT_GT(counts.channels().at("DREAM_POSES").bytes, 0);
}

TEST(LogChannelCountsTest, AnEmptyLogIsAnError) {
  TempFolder folder;
  const std::string log = SyntheticRunLog(folder / "run.lcmlog").Write();
  EXPECT_THROW(LogChannelCounts::Read(log), std::runtime_error);
}

}  // namespace
}  // namespace dream::run_log
