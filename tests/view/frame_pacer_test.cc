// FramePacer: the live view's frames slow down only while the run goes
// faster than twice real time (and further beyond ten times), measured over
// half a second of wall time, and a new run starts the measure over.
#include "dream/view/frame_pacer.h"

#include <gtest/gtest.h>

#include <chrono>

namespace dream::view {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

constexpr double kStep = 0.033;
constexpr microseconds kRealTimePeriod{33'333};  // FrameRates' defaults: 30, 10 and 5 a second
constexpr microseconds kFastPeriod{100'000};
constexpr microseconds kVeryFastPeriod{200'000};

TEST(FramePacerTest, DefaultsAreThirtyTenAndFiveFramesASecond) {
  const FrameRates rates;
  EXPECT_EQ(rates.real_time, 30);
  EXPECT_EQ(rates.fast, 10);
  EXPECT_EQ(rates.very_fast, 5);
}

TEST(FramePacerTest, ARunAtRealTimeKeepsTheFullRate) {
  FramePacer pacer(FrameRates{}, kStep);
  const Clock::time_point start{};
  // 30 steps (0.99 s simulated) in each second of wall time, frames every 100 ms.
  for (int i = 0; i <= 30; ++i) {
    EXPECT_EQ(pacer.Next(3 * i, start + milliseconds(100 * i)), kRealTimePeriod) << "frame " << i;
  }
  EXPECT_NEAR(pacer.speed(), 0.99, 1e-9);
}

TEST(FramePacerTest, ARunFasterThanTwiceRealTimeGetsTheFastRateAfterOneWindow) {
  FramePacer pacer(FrameRates{}, kStep);
  const Clock::time_point start{};
  EXPECT_EQ(pacer.Next(0, start), kRealTimePeriod);
  EXPECT_EQ(pacer.Next(20, start + milliseconds(250)), kRealTimePeriod);  // not yet measured
  // 150 steps/s: 4.95 s simulated a wall second.
  EXPECT_EQ(pacer.Next(75, start + milliseconds(500)), kFastPeriod);
  EXPECT_NEAR(pacer.speed(), 4.95, 1e-9);
  // Slowed to real time (paced, or a lockstep run waiting): the full rate again after a window.
  EXPECT_EQ(pacer.Next(85, start + milliseconds(800)), kFastPeriod);
  EXPECT_EQ(pacer.Next(90, start + milliseconds(1000)), kRealTimePeriod);
}

TEST(FramePacerTest, ARunFasterThanTenTimesRealTimeGetsTheVeryFastRate) {
  FramePacer pacer(FrameRates{}, kStep);
  const Clock::time_point start{};
  pacer.Next(0, start);
  // 600 steps/s, a lockstep dream launch of 20 robots: 19.8 s simulated a wall second.
  EXPECT_EQ(pacer.Next(300, start + milliseconds(500)), kVeryFastPeriod);
  // Down to 6x real time: the fast rate.
  EXPECT_EQ(pacer.Next(390, start + milliseconds(1000)), kFastPeriod);
}

TEST(FramePacerTest, TheThresholdsAreTwiceAndTenTimesRealTime) {
  const Clock::time_point start{};
  const auto period_at = [&](int steps_in_half_a_second) {
    FramePacer pacer(FrameRates{}, kStep);
    pacer.Next(0, start);
    return pacer.Next(steps_in_half_a_second, start + milliseconds(500));
  };
  EXPECT_EQ(period_at(30), kRealTimePeriod);   // 0.99 s in 0.5 s: 1.98x
  EXPECT_EQ(period_at(31), kFastPeriod);       // 1.023 s in 0.5 s: 2.05x
  EXPECT_EQ(period_at(151), kFastPeriod);      // 9.97x
  EXPECT_EQ(period_at(152), kVeryFastPeriod);  // 10.03x
}

TEST(FramePacerTest, ANewRunStartsTheMeasureOverAtTheFullRate) {
  FramePacer pacer(FrameRates{}, kStep);
  const Clock::time_point start{};
  pacer.Next(0, start);
  ASSERT_EQ(pacer.Next(1000, start + milliseconds(500)), kVeryFastPeriod);
  // A log played again, or the next run: its step 5 is lower than the last.
  EXPECT_EQ(pacer.Next(5, start + milliseconds(600)), kRealTimePeriod);
  EXPECT_EQ(pacer.speed(), 0.0);
}

TEST(FramePacerTest, OneRateIsKeptWhateverTheRunsSpeedAndClamped) {
  FramePacer pacer(FrameRates::One(15), kStep);
  const Clock::time_point start{};
  pacer.Next(0, start);
  EXPECT_EQ(pacer.Next(1000, start + milliseconds(500)), microseconds(66'666));
  EXPECT_EQ(FrameRates::One(0).real_time, 1);
  EXPECT_EQ(FrameRates::One(500).very_fast, FrameRates::kMax);
}

}  // namespace
}  // namespace dream::view
