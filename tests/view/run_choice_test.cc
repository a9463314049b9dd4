#include "dream/view/run_choice.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>

#include "dream/run_status_t.hpp"

namespace dream::view {
namespace {

using Decision = RunChoice::Decision;
constexpr int64_t kRun = 0x7e57;
constexpr int64_t kForged = 0xbad;
constexpr int64_t kSecond = 0x5ec0;

/// A RunChoice on a clock the test moves.
class RunChoiceTest : public ::testing::Test {
 protected:
  /// One step of `run` as a world publishes it: its status, then its poses.
  Decision Step(int64_t run, int64_t step, int state = run_status_t::RUNNING) {
    choice_.OnStatus(run, step, state);
    return choice_.OnPoses(run, step);
  }
  /// The followed run at steps 0..last, ended with a FINISHED status.
  void RunToItsEnd(int64_t run, int64_t last) {
    for (int64_t step = 0; step <= last; ++step) Step(run, step);
    choice_.OnStatus(run, last, run_status_t::FINISHED);
  }

  RunChoice::Clock::time_point now_{};
  RunChoice choice_{[this] { return now_; }};
};

TEST_F(RunChoiceTest, TheFirstRunIsJoinedAtAnyStepOnAWholeStepOfAWorld) {
  EXPECT_EQ(choice_.OnPoses(kForged, 40), Decision::kIgnore);  // one datagram alone: not a run yet
  EXPECT_EQ(choice_.run_id(), 0);
  EXPECT_EQ(Step(kRun, 12), Decision::kStartOver);  // its status, then its poses of the same step
  EXPECT_EQ(choice_.run_id(), kRun);
  EXPECT_EQ(Step(kRun, 13), Decision::kNewStep);
  EXPECT_EQ(choice_.OnPoses(kRun, 13), Decision::kResend);
}

TEST_F(RunChoiceTest, PosesAloneHoweverManyAreNoRun) {
  for (int64_t step = 0; step < 5; ++step) {
    EXPECT_EQ(choice_.OnPoses(kForged, step), Decision::kIgnore);
    EXPECT_EQ(choice_.OnPoses(kForged, step), Decision::kIgnore);
  }
  EXPECT_EQ(choice_.run_id(), 0);
  RunToItsEnd(kRun, 3);
  now_ += std::chrono::seconds(1);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(choice_.OnPoses(kForged + 1, 0), Decision::kIgnore);  // sent again and again
  EXPECT_EQ(choice_.OnPoses(kForged + 1, 1), Decision::kIgnore);
  EXPECT_EQ(choice_.run_id(), kRun);
}

TEST_F(RunChoiceTest, AForgedRunMidRunIsIgnoredAndSaid) {
  for (int64_t step = 0; step < 5; ++step) Step(kRun, step);
  EXPECT_EQ(choice_.OnPoses(kForged, 0), Decision::kIgnore);
  EXPECT_EQ(choice_.OnPoses(kForged, 900), Decision::kIgnore);
  EXPECT_FALSE(choice_.OnStatus(kSecond, 5, run_status_t::FINISHED));
  EXPECT_FALSE(choice_.ended());  // another run's end is not this one's
  EXPECT_EQ(Step(kRun, 5), Decision::kNewStep);
  EXPECT_EQ(choice_.run_id(), kRun);
  const std::optional<ViewFrame::OtherWorld> other = choice_.OtherWorldHeard();
  ASSERT_TRUE(other.has_value());
  EXPECT_EQ(other->run_id, kForged);
  EXPECT_EQ(other->step, 900);
  EXPECT_EQ(other->state, -1);  // no status of it heard
  EXPECT_EQ(other->runs, 1);    // a run that said it ended is no second world
}

TEST_F(RunChoiceTest, AFinishedRunStaysUntilANewWorldStartsFromItsStep0) {
  RunToItsEnd(kRun, 30);
  EXPECT_TRUE(choice_.ended());
  EXPECT_EQ(choice_.OnPoses(kForged, 0), Decision::kIgnore);   // one forged datagram at step 0
  EXPECT_EQ(choice_.OnPoses(kForged, 77), Decision::kIgnore);  // or anywhere
  EXPECT_EQ(choice_.run_id(), kRun);
  EXPECT_EQ(choice_.OtherWorldHeard()->run_id, kForged);
  now_ += RunChoice::kOtherWorldShown + std::chrono::milliseconds(1);
  EXPECT_FALSE(choice_.OtherWorldHeard().has_value());                                  // the forged run is quiet
  EXPECT_EQ(Step(kSecond, 0, run_status_t::WAITING_FOR_AGENTS), Decision::kStartOver);  // a new world
  EXPECT_EQ(choice_.run_id(), kSecond);
  EXPECT_FALSE(choice_.ended());
  EXPECT_FALSE(choice_.OtherWorldHeard().has_value());  // the run that ended is no second world
}

TEST_F(RunChoiceTest, ASecondWorldWaitingBesideTheRunIsTakenOnlyWhenItRunsAfterTheEnd) {
  for (int64_t step = 0; step < 10; ++step) {
    Step(kRun, step);
    EXPECT_EQ(Step(kSecond, 0, run_status_t::WAITING_FOR_AGENTS), Decision::kIgnore);  // its resends
  }
  ASSERT_TRUE(choice_.OtherWorldHeard().has_value());
  EXPECT_EQ(choice_.OtherWorldHeard()->state, run_status_t::WAITING_FOR_AGENTS);
  choice_.OnStatus(kRun, 9, run_status_t::FINISHED);
  // Still waiting: it was there before the end, so its step 0 again is no new start.
  EXPECT_EQ(Step(kSecond, 0, run_status_t::WAITING_FOR_AGENTS), Decision::kIgnore);
  EXPECT_EQ(choice_.run_id(), kRun);
  EXPECT_EQ(Step(kSecond, 1), Decision::kStartOver);  // its agents came: it runs
  EXPECT_EQ(choice_.run_id(), kSecond);
}

TEST_F(RunChoiceTest, ARunWaitingAtItsStep0GivesWayToARunThatRuns) {
  EXPECT_EQ(Step(kSecond, 0, run_status_t::WAITING_FOR_AGENTS), Decision::kStartOver);  // heard first
  EXPECT_EQ(choice_.OnPoses(kForged, 50), Decision::kIgnore);  // one datagram: no run that runs
  EXPECT_EQ(Step(kRun, 0), Decision::kIgnore);
  EXPECT_EQ(Step(kSecond, 0, run_status_t::WAITING_FOR_AGENTS), Decision::kResend);
  EXPECT_EQ(Step(kRun, 1), Decision::kStartOver);  // it runs
  EXPECT_EQ(choice_.run_id(), kRun);
  EXPECT_EQ(Step(kSecond, 0, run_status_t::WAITING_FOR_AGENTS), Decision::kIgnore);
  EXPECT_EQ(Step(kRun, 2), Decision::kNewStep);
}

TEST_F(RunChoiceTest, ASecondWorldRunningBesideTheRunIsNeverTaken) {
  for (int64_t step = 0; step < 10; ++step) {
    Step(kRun, step);
    EXPECT_EQ(Step(kSecond, step), Decision::kIgnore);
  }
  choice_.OnStatus(kRun, 9, run_status_t::FINISHED);
  EXPECT_EQ(Step(kSecond, 10), Decision::kIgnore);  // mid-run: no clean start
  EXPECT_EQ(choice_.run_id(), kRun);
}

TEST_F(RunChoiceTest, ARunSilentFor3SecondsIsOverAndANewWorldIsTaken) {
  for (int64_t step = 0; step < 5; ++step) Step(kRun, step);  // then killed: no FINISHED
  now_ += RunChoice::kSilence - std::chrono::milliseconds(1);
  EXPECT_EQ(Step(kSecond, 0, run_status_t::WAITING_FOR_AGENTS), Decision::kIgnore);  // not silent long enough
  now_ += std::chrono::milliseconds(1);
  EXPECT_EQ(choice_.OnPoses(kSecond, 0), Decision::kStartOver);  // the waiting world's resend
  EXPECT_EQ(choice_.run_id(), kSecond);
}

TEST_F(RunChoiceTest, TheFollowedRunFromItsStartAgainStartsOverOnceConfirmed) {
  RunToItsEnd(kRun, 30);
  EXPECT_EQ(Step(kRun, 0), Decision::kIgnore);  // a step back, not confirmed yet
  EXPECT_EQ(Step(kRun, 1), Decision::kStartOver);
  EXPECT_FALSE(choice_.ended());
  EXPECT_EQ(Step(kRun, 2), Decision::kNewStep);
}

TEST_F(RunChoiceTest, AnotherWorldIsSaidUntilQuietFor2Seconds) {
  Step(kRun, 0);
  choice_.OnPoses(kForged, 3);
  EXPECT_TRUE(choice_.OtherWorldHeard().has_value());
  now_ += RunChoice::kOtherWorldShown;
  EXPECT_TRUE(choice_.OtherWorldHeard().has_value());
  now_ += std::chrono::milliseconds(1);
  EXPECT_FALSE(choice_.OtherWorldHeard().has_value());
}

TEST_F(RunChoiceTest, AFloodOfMadeUpRunsIsBoundedAndChangesNothing) {
  Step(kRun, 0);
  for (int64_t id = 1; id <= 10000; ++id) {
    choice_.OnStatus(kForged + id, 0, run_status_t::WAITING_FOR_AGENTS);
    EXPECT_EQ(choice_.OnPoses(kForged + id, 0), Decision::kIgnore);
  }
  EXPECT_EQ(Step(kRun, 1), Decision::kNewStep);
  ASSERT_TRUE(choice_.OtherWorldHeard().has_value());
  EXPECT_EQ(choice_.OtherWorldHeard()->runs, static_cast<int>(RunChoice::kMaxRunsHeard) - 1);  // the followed one kept
  EXPECT_EQ(choice_.OtherWorldHeard()->run_id, kForged + 10000);
}

TEST_F(RunChoiceTest, TheUsersChoiceIsDrawnFromItsNextPoses) {
  for (int64_t step = 0; step < 5; ++step) {
    Step(kRun, step);
    Step(kSecond, 40 + step);
  }
  EXPECT_FALSE(choice_.Choose(kForged));  // never heard
  EXPECT_FALSE(choice_.Choose(kRun));     // the one drawn
  EXPECT_EQ(choice_.run_id(), kRun);
  EXPECT_TRUE(choice_.Choose(kSecond));
  EXPECT_EQ(Step(kRun, 5), Decision::kNewStep);                   // until the chosen run's next poses
  EXPECT_EQ(choice_.OnPoses(kSecond, 45), Decision::kStartOver);  // whatever its step, status or not
  EXPECT_EQ(choice_.run_id(), kSecond);
  EXPECT_EQ(Step(kRun, 6), Decision::kIgnore);
  EXPECT_EQ(Step(kSecond, 46), Decision::kNewStep);
}

}  // namespace
}  // namespace dream::view
