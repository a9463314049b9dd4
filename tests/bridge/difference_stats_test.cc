// DifferenceStats: the RMS, largest value and its step that run comparisons
// and command agreements report.
#include "dream/bridge/difference_stats.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dream::bridge {
namespace {

TEST(DifferenceStatsTest, NothingTakenIsZeroWithNoStep) {
  const DifferenceStats stats;
  EXPECT_EQ(stats.count(), 0);
  EXPECT_EQ(stats.Rms(), 0.0);
  EXPECT_EQ(stats.max(), 0.0);
  EXPECT_EQ(stats.max_step(), -1);
}

TEST(DifferenceStatsTest, TakesSizesAndKeepsTheFirstStepOfTheLargest) {
  DifferenceStats stats;
  stats.Add(0.0, 10);
  stats.Add(-0.3, 11);  // a negative difference counts by its size
  stats.Add(0.3, 12);   // as large, later: the step stays 11
  stats.Add(0.1, 13);
  EXPECT_EQ(stats.count(), 4);
  EXPECT_DOUBLE_EQ(stats.max(), 0.3);
  EXPECT_EQ(stats.max_step(), 11);
  EXPECT_DOUBLE_EQ(stats.Rms(), std::sqrt((0.09 + 0.09 + 0.01) / 4.0));
}

TEST(DifferenceStatsTest, AllZeroDifferencesNameTheFirstStep) {
  DifferenceStats stats;
  stats.Add(0.0, 5);
  stats.Add(0.0, 6);
  EXPECT_EQ(stats.max_step(), 5);
  EXPECT_EQ(stats.Rms(), 0.0);
}

TEST(DifferenceStatsTest, ANanIsNeverTheLargestButMakesTheRmsNan) {
  DifferenceStats stats;
  stats.Add(std::nan(""), 3);
  EXPECT_EQ(stats.max_step(), -1);
  stats.Add(0.2, 4);
  EXPECT_EQ(stats.max(), 0.2);
  EXPECT_EQ(stats.max_step(), 4);
  EXPECT_TRUE(std::isnan(stats.Rms()));
}

TEST(DifferenceStatsTest, MergingIsTakingEverySampleAgain) {
  DifferenceStats first;
  first.Add(0.2, 0);
  first.Add(0.1, 1);
  DifferenceStats second;
  second.Add(0.5, 7);
  DifferenceStats whole;
  whole.Merge(DifferenceStats{});  // nothing taken changes nothing
  whole.Merge(first);
  whole.Merge(second);
  DifferenceStats one_by_one;
  for (const auto& [difference, step] : {std::pair{0.2, 0}, std::pair{0.1, 1}, std::pair{0.5, 7}}) {
    one_by_one.Add(difference, step);
  }
  EXPECT_EQ(whole.count(), 3);
  EXPECT_EQ(whole.Rms(), one_by_one.Rms());
  EXPECT_EQ(whole.max(), 0.5);
  EXPECT_EQ(whole.max_step(), 7);
}

}  // namespace
}  // namespace dream::bridge
