#include "dream/node/progress_reporter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace dream::node {
namespace {

using Clock = ProgressReporter::Clock;

Clock::time_point At(double seconds) {
  return Clock::time_point() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Drives `reporter` like a loop doing `steps_per_s` steps per second from t = 0
/// to `end_s`, one Update per step.
void Drive(ProgressReporter& reporter, int64_t total_steps, double steps_per_s, double end_s) {
  reporter.Start(total_steps, 0, At(0.0));
  const auto steps = static_cast<int64_t>(end_s * steps_per_s);
  for (int64_t k = 1; k <= steps; ++k) reporter.Update(k, At(static_cast<double>(k) / steps_per_s));
}

TEST(ProgressReporterTest, EtaIsRemainingStepsOverRate) {
  EXPECT_DOUBLE_EQ(ProgressReporter::EtaSeconds(3000, 1000.0), 3.0);
  EXPECT_DOUBLE_EQ(ProgressReporter::EtaSeconds(45, 30.0), 1.5);
  EXPECT_DOUBLE_EQ(ProgressReporter::EtaSeconds(0, 0.0), 0.0);  // done: no time left, rate or not
  EXPECT_TRUE(std::isnan(ProgressReporter::EtaSeconds(10, 0.0)));
  EXPECT_TRUE(std::isnan(ProgressReporter::EtaSeconds(10, -1.0)));
  EXPECT_TRUE(std::isnan(ProgressReporter::EtaSeconds(10, std::nan(""))));
}

TEST(ProgressReporterTest, DurationsReadAsClockTimes) {
  EXPECT_EQ(ProgressReporter::FormatDuration(0.0), "0:00");
  EXPECT_EQ(ProgressReporter::FormatDuration(7.4), "0:07");
  EXPECT_EQ(ProgressReporter::FormatDuration(754.0), "12:34");
  EXPECT_EQ(ProgressReporter::FormatDuration(3723.0), "1:02:03");
  EXPECT_EQ(ProgressReporter::FormatDuration(std::nan("")), "?");
  EXPECT_EQ(ProgressReporter::FormatDuration(INFINITY), "?");
}

TEST(ProgressReporterTest, PlainModePrintsALineEveryIntervalWithRateAndEta) {
  std::ostringstream out;
  ProgressReporter::Options options;
  options.line_interval_s = 2.0;
  ProgressReporter reporter(out, options);
  Drive(reporter, 10000, 1000.0, 7.0);  // lines at 2, 4 and 6 s
  reporter.Finish(At(7.0));

  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 3u) << out.str();
  EXPECT_EQ(lines[0], "step 2000/10000 (20%), 1000 steps/s, ETA 0:08");
  EXPECT_EQ(lines[1], "step 4000/10000 (40%), 1000 steps/s, ETA 0:06");
  EXPECT_EQ(lines[2], "step 6000/10000 (60%), 1000 steps/s, ETA 0:04");
  EXPECT_EQ(out.str().find('\r'), std::string::npos);
}

TEST(ProgressReporterTest, RateFollowsTheRecentPace) {
  std::ostringstream out;
  ProgressReporter::Options options;
  options.line_interval_s = 100.0;
  ProgressReporter reporter(out, options);
  reporter.Start(100000, 0, At(0.0));
  // 10 s at 1000 steps/s, then 3 s at 100 steps/s: the rate is the slow one,
  // not the run's average (about 792 steps/s).
  int64_t k = 0;
  for (double t = 0.001; t <= 10.0; t += 0.001) reporter.Update(++k, At(t));
  for (double t = 10.01; t <= 13.0; t += 0.01) reporter.Update(++k, At(t));
  EXPECT_NEAR(reporter.steps_per_second(), 100.0, 2.0);
  EXPECT_TRUE(out.str().empty());
}

TEST(ProgressReporterTest, InteractiveModeRedrawsOneLineAndEndsWithANewline) {
  std::ostringstream out;
  ProgressReporter::Options options;
  options.interactive = true;
  options.width_columns = 100;
  ProgressReporter reporter(out, options);
  Drive(reporter, 3000, 1000.0, 2.0);
  EXPECT_TRUE(reporter.line_on_screen());
  reporter.Finish(At(2.0));
  EXPECT_FALSE(reporter.line_on_screen());

  const std::string text = out.str();
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.front(), '\r');
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find('\n'), text.size() - 1) << "one terminal line, redrawn";
  // From 0.5 s (show_after_s) to 2.0 s at most every 0.1 s, plus the final draw.
  const auto redraws = std::count(text.begin(), text.end(), '\r');
  EXPECT_GE(redraws, 14);
  EXPECT_LE(redraws, 17);
  const std::string last = text.substr(text.rfind('\r') + 1);
  EXPECT_NE(last.find("step 2000/3000 ["), std::string::npos) << last;
  EXPECT_NE(last.find(" 67%  1000 steps/s  ETA 0:01"), std::string::npos) << last;
  EXPECT_LE(last.size() - 1, 99u);
}

TEST(ProgressReporterTest, InteractiveModeShowsNothingForAQuickLoop) {
  std::ostringstream out;
  ProgressReporter::Options options;
  options.interactive = true;
  ProgressReporter reporter(out, options);
  Drive(reporter, 300, 1000.0, 0.3);
  reporter.Finish(At(0.3));
  EXPECT_TRUE(out.str().empty());
}

TEST(ProgressReporterTest, BarFitsTheTerminalWidth) {
  for (int columns : {20, 40, 60, 80, 200}) {
    std::ostringstream out;
    ProgressReporter::Options options;
    options.interactive = true;
    options.width_columns = columns;
    ProgressReporter reporter(out, options);
    Drive(reporter, 100000, 5000.0, 1.0);
    const std::string line = reporter.BarLine(5000);
    EXPECT_LE(static_cast<int>(line.size()), columns - 1) << line;
    EXPECT_EQ(line.rfind("step 5000/100000", 0), 0u) << line;
    if (columns >= 80) {
      // A bar of 5% of its width filled.
      const size_t open = line.find('[');
      const size_t close = line.find(']');
      ASSERT_NE(open, std::string::npos) << line;
      const std::string bar = line.substr(open + 1, close - open - 1);
      EXPECT_EQ(std::count(bar.begin(), bar.end(), '#'), static_cast<long>(bar.size() * 5 / 100)) << line;
    }
  }
}

TEST(ProgressReporterTest, ClearLineBlanksTheBarAndTheNextUpdateRedrawsIt) {
  std::ostringstream out;
  ProgressReporter::Options options;
  options.interactive = true;
  ProgressReporter reporter(out, options);
  Drive(reporter, 3000, 1000.0, 1.0);
  ASSERT_TRUE(reporter.line_on_screen());
  out.str("");
  reporter.ClearLine();
  EXPECT_FALSE(reporter.line_on_screen());
  const std::string cleared = out.str();
  ASSERT_GE(cleared.size(), 3u);
  EXPECT_EQ(cleared.front(), '\r');
  EXPECT_EQ(cleared.back(), '\r');
  EXPECT_EQ(cleared.find_first_not_of(" \r"), std::string::npos) << "only blanks";
  reporter.ClearLine();  // nothing on screen: nothing written
  EXPECT_EQ(out.str(), cleared);
  reporter.Update(1200, At(1.2));
  EXPECT_TRUE(reporter.line_on_screen());
}

TEST(ProgressReporterTest, NothingBeforeStart) {
  std::ostringstream out;
  ProgressReporter::Options options;
  options.interactive = true;
  ProgressReporter reporter(out, options);
  reporter.Update(10, At(5.0));
  reporter.Finish(At(5.0));
  EXPECT_TRUE(out.str().empty());
}

TEST(ProgressReporterTest, PlainModeRefusesAZeroInterval) {
  std::ostringstream out;
  ProgressReporter::Options options;
  options.line_interval_s = 0.0;
  EXPECT_THROW(ProgressReporter(out, options), std::invalid_argument);
}

}  // namespace
}  // namespace dream::node
