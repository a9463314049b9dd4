// FramePacer: the live view's frames slow to the fast rate only while the run
// goes faster than twice real time, measured over half a second of wall time,
// and a new run starts the measure over.
#include "dream/view/frame_pacer.h"

#include <gtest/gtest.h>

#include <chrono>

namespace dream::view {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

constexpr double kStep = 0.033;

TEST(FramePacerTest, ARunAtRealTimeKeepsTheFullRate) {
  FramePacer pacer(30, 10, kStep);
  const Clock::time_point start{};
  // 30 steps (0.99 s simulated) in each second of wall time, frames every 100 ms.
  for (int i = 0; i <= 30; ++i) {
    EXPECT_EQ(pacer.Next(3 * i, start + milliseconds(100 * i)), microseconds(33'333)) << "frame " << i;
  }
  EXPECT_FALSE(pacer.fast());
}

TEST(FramePacerTest, ARunFasterThanTwiceRealTimeGetsTheFastRateAfterOneWindow) {
  FramePacer pacer(30, 10, kStep);
  const Clock::time_point start{};
  EXPECT_EQ(pacer.Next(0, start), microseconds(33'333));
  EXPECT_EQ(pacer.Next(100, start + milliseconds(250)), microseconds(33'333));  // not yet measured
  // 600 steps/s: 20 s simulated a wall second.
  EXPECT_EQ(pacer.Next(300, start + milliseconds(500)), microseconds(100'000));
  EXPECT_TRUE(pacer.fast());
  // Slowed to real time (paced, or a lockstep run waiting): the full rate again after a window.
  EXPECT_EQ(pacer.Next(310, start + milliseconds(800)), microseconds(100'000));
  EXPECT_EQ(pacer.Next(320, start + milliseconds(1000)), microseconds(33'333));
  EXPECT_FALSE(pacer.fast());
}

TEST(FramePacerTest, JustOverTwiceRealTimeIsFastAndJustUnderIsNot) {
  const Clock::time_point start{};
  FramePacer under(30, 10, kStep);
  under.Next(0, start);
  under.Next(30, start + milliseconds(500));  // 0.99 s in 0.5 s: 1.98x
  EXPECT_FALSE(under.fast());
  FramePacer over(30, 10, kStep);
  over.Next(0, start);
  over.Next(31, start + milliseconds(500));  // 1.023 s in 0.5 s: 2.05x
  EXPECT_TRUE(over.fast());
}

TEST(FramePacerTest, ANewRunStartsTheMeasureOverAtTheFullRate) {
  FramePacer pacer(30, 10, kStep);
  const Clock::time_point start{};
  pacer.Next(0, start);
  pacer.Next(1000, start + milliseconds(500));
  ASSERT_TRUE(pacer.fast());
  // A log played again, or the next run: its step 5 is lower than the last.
  EXPECT_EQ(pacer.Next(5, start + milliseconds(600)), microseconds(33'333));
  EXPECT_FALSE(pacer.fast());
}

TEST(FramePacerTest, OneRateGivenTwiceIsKeptWhateverTheRunsSpeed) {
  FramePacer pacer(15, 15, kStep);
  const Clock::time_point start{};
  pacer.Next(0, start);
  EXPECT_EQ(pacer.Next(1000, start + milliseconds(500)), microseconds(66'666));
  EXPECT_TRUE(pacer.fast());
}

}  // namespace
}  // namespace dream::view
