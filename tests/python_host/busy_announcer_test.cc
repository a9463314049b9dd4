#include "dream/python_host/busy_announcer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <set>
#include <vector>

namespace dream::python_host {
namespace {

using Clock = BusyAnnouncer::Clock;
using std::chrono::milliseconds;

// agent_timeout_s 1 s: notes a quarter of a second apart, from a quarter after the step.
class BusyAnnouncerTest : public ::testing::Test {
 protected:
  const std::set<int> kNoneFailed;
  BusyAnnouncer announcer_{{0, 1}, 1.0};
  Clock::time_point t0_{};
};

TEST_F(BusyAnnouncerTest, NothingIsSaidBeforeAStepNorWithinTheFirstQuarter) {
  EXPECT_TRUE(announcer_.Due(t0_ + milliseconds(900), kNoneFailed).empty());
  announcer_.StepArrived(7, 3, t0_);
  EXPECT_TRUE(announcer_.Due(t0_ + milliseconds(249), kNoneFailed).empty());
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(250), kNoneFailed), (std::vector<int>{0, 1}));
}

TEST_F(BusyAnnouncerTest, NotesRepeatEveryQuarterForTheRobotsStillPending) {
  announcer_.StepArrived(7, 3, t0_);
  announcer_.Answered(1, 3);
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(300), kNoneFailed), std::vector<int>{0});
  EXPECT_TRUE(announcer_.Due(t0_ + milliseconds(400), kNoneFailed).empty())
      << "a quarter has not passed since the last note";
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(560), kNoneFailed), std::vector<int>{0});
  EXPECT_TRUE(announcer_.Due(t0_ + milliseconds(900), {0}).empty()) << "its fault is its answer";
}

TEST_F(BusyAnnouncerTest, AResentStepKeepsItsClockAndANewStepOrRunStartsAgain) {
  announcer_.StepArrived(7, 3, t0_);
  announcer_.StepArrived(7, 3, t0_ + milliseconds(200));  // the world's resend
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(250), kNoneFailed).size(), 2U);
  announcer_.Answered(0, 3);
  announcer_.Answered(1, 3);
  announcer_.StepArrived(7, 4, t0_ + milliseconds(300));
  EXPECT_TRUE(announcer_.Due(t0_ + milliseconds(500), kNoneFailed).empty());
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(550), kNoneFailed).size(), 2U);
  // A new run starts at step 0 again: not "older than step 4".
  announcer_.StepArrived(8, 0, t0_ + milliseconds(1000));
  announcer_.Answered(0, 0);
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(1250), kNoneFailed), std::vector<int>{1});
}

TEST_F(BusyAnnouncerTest, AnAnswerToALaterStepCountsAndAnOlderOneDoesNot) {
  announcer_.StepArrived(7, 5, t0_);
  announcer_.Answered(0, 4);
  announcer_.Answered(1, 6);
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(250), kNoneFailed), std::vector<int>{0});
}

// NextDue is what the host reads without its lock: Due names nobody before it.
TEST_F(BusyAnnouncerTest, NothingIsDueBeforeNextDueAndNothingAfterEveryoneAnswered) {
  EXPECT_EQ(announcer_.NextDue(), Clock::time_point::max()) << "before a step";
  announcer_.StepArrived(7, 3, t0_);
  EXPECT_EQ(announcer_.NextDue(), t0_ + milliseconds(250));
  EXPECT_TRUE(announcer_.Due(announcer_.NextDue() - milliseconds(1), kNoneFailed).empty());
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(260), kNoneFailed).size(), 2U);
  EXPECT_EQ(announcer_.NextDue(), t0_ + milliseconds(510));
  announcer_.Answered(0, 3);
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(510), {1}), std::vector<int>{});
  EXPECT_EQ(announcer_.NextDue(), Clock::time_point::max()) << "every robot answered or failed: none until a step";
  EXPECT_TRUE(announcer_.Due(t0_ + milliseconds(2000), {1}).empty());
  announcer_.StepArrived(7, 4, t0_ + milliseconds(600));
  EXPECT_EQ(announcer_.NextDue(), t0_ + milliseconds(850));
  EXPECT_EQ(announcer_.Due(t0_ + milliseconds(850), {1}), std::vector<int>{0});
}

}  // namespace
}  // namespace dream::python_host
