// lcm::CommandBatch: a DREAM_CMDS message (robot_commands_t) read once for the world and `dream view`:
// refused whole with the reason the world gives, or its entries as the DREAM_CMD_<id> each stands for.
#include "dream/lcm/command_batch.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "dream/robot_commands_t.hpp"
#include "../support/sample_lcm_messages.h"
#include "dream/velocity_command_t.hpp"

namespace dream::lcm {
namespace {

constexpr int kRobots = 3;

robot_commands_t Batch(const std::vector<int32_t>& ids) {
  return testing::CommandBatchOf(ids, /*run_id=*/77, /*agent_id=*/500, /*step=*/2, /*utime=*/66000);
}

std::string ProblemOf(const robot_commands_t& batch, int robots = kRobots) {
  const CommandBatch read(batch, robots);
  EXPECT_EQ(read.size(), 0u) << "a refused message has no entries";
  return read.problem().value_or("(none)");
}

TEST(LcmCommandBatchTest, EachEntryIsItsRobotsCommandFieldByField) {
  const robot_commands_t batch = Batch({2, 0, 1});
  const CommandBatch read(batch, kRobots);
  EXPECT_FALSE(read.problem().has_value());
  ASSERT_EQ(read.size(), 3u);
  for (size_t i = 0; i < read.size(); ++i) {
    const velocity_command_t command = read.Entry(i);
    EXPECT_EQ(command.utime, batch.utime);
    EXPECT_EQ(command.step, batch.step);
    EXPECT_EQ(command.run_id, batch.run_id);
    EXPECT_EQ(command.agent_id, batch.agent_id);
    EXPECT_EQ(command.robot_id, batch.robot_id[i]);
    EXPECT_EQ(command.v, batch.v[i]);
    EXPECT_EQ(command.w, batch.w[i]);
    EXPECT_EQ(command.done, batch.done[i]);
  }
  EXPECT_EQ(read.Entry(2).done, 1);  // robot 1's
  EXPECT_EQ(read.Entry(0).robot_id, 2);
  EXPECT_THROW(read.Entry(3), std::out_of_range);
}

TEST(LcmCommandBatchTest, EntriesForRobotsTheRunDoesNotHaveAreLeftToTheReader) {
  // As DREAM_CMD_7 and DREAM_CMD_-1 would be: the reader's own checks refuse them, entry by entry.
  const robot_commands_t batch = Batch({7, -1});
  const CommandBatch read(batch, kRobots);
  EXPECT_FALSE(read.problem().has_value());
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read.Entry(0).robot_id, 7);
  EXPECT_EQ(read.Entry(1).robot_id, -1);
}

TEST(LcmCommandBatchTest, AnEmptyMessageHasNoEntriesAndNoProblem) {
  const robot_commands_t batch = Batch({});
  const CommandBatch read(batch, kRobots);
  EXPECT_FALSE(read.problem().has_value());
  EXPECT_EQ(read.size(), 0u);
}

TEST(LcmCommandBatchTest, ARobotListedTwiceIsNamed) {
  EXPECT_EQ(ProblemOf(Batch({0, 1, 0})), "robot 0 is listed twice");
  EXPECT_EQ(ProblemOf(Batch({2, 2})), "robot 2 is listed twice");
}

TEST(LcmCommandBatchTest, MoreEntriesThanTheRunsRobotsAreRefused) {
  EXPECT_EQ(ProblemOf(Batch({0, 1, 2, 3})), "4 commands, but this run has 3 robots");
  EXPECT_EQ(ProblemOf(Batch({0}), 0), "1 commands, but this run has 0 robots");
}

TEST(LcmCommandBatchTest, ArraysThatDisagreeWithTheCountAreRefused) {
  robot_commands_t batch = Batch({0, 1});
  batch.num_commands = 3;
  EXPECT_EQ(ProblemOf(batch), "its arrays do not hold num_commands = 3 entries");
  for (int array = 0; array < 4; ++array) {
    robot_commands_t short_one = Batch({0, 1});
    switch (array) {
      case 0:
        short_one.robot_id.pop_back();
        break;
      case 1:
        short_one.v.pop_back();
        break;
      case 2:
        short_one.w.pop_back();
        break;
      default:
        short_one.done.pop_back();
    }
    EXPECT_EQ(ProblemOf(short_one), "its arrays do not hold num_commands = 2 entries") << "array " << array;
  }
}

TEST(LcmCommandBatchTest, HostileCountsAreRefusedWithoutReadingTheArrays) {
  robot_commands_t batch = Batch({0, 1});
  batch.num_commands = std::numeric_limits<int32_t>::max();
  EXPECT_EQ(ProblemOf(batch), "its arrays do not hold num_commands = 2147483647 entries");
  batch.num_commands = std::numeric_limits<int32_t>::min();
  EXPECT_EQ(ProblemOf(batch), "its arrays do not hold num_commands = -2147483648 entries");
  robot_commands_t empty = Batch({});
  empty.num_commands = -1;
  EXPECT_EQ(ProblemOf(empty), "num_commands = -1 is negative");
  // Arrays as long as a lying count: refused on the count, before any entry is looked at.
  robot_commands_t long_one{};
  long_one.num_commands = 100000;
  long_one.robot_id.assign(100000, 0);
  long_one.v.assign(100000, 0.0);
  long_one.w.assign(100000, 0.0);
  long_one.done.assign(100000, 0);
  EXPECT_EQ(ProblemOf(long_one), "100000 commands, but this run has 3 robots");
}

}  // namespace
}  // namespace dream::lcm
