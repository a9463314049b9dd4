#include "dream/view/client_queue.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace dream::view {
namespace {

ClientQueue::Message Text(const std::string& text) { return std::make_shared<const std::string>(text); }

TEST(ClientQueueTest, KeepsOrderWhileThereIsRoom) {
  ClientQueue queue(3);
  queue.Push(Text("a"));
  queue.Push(Text("b"));
  EXPECT_EQ(queue.size(), 2u);
  EXPECT_EQ(*queue.Pop(), "a");
  EXPECT_EQ(*queue.Pop(), "b");
  EXPECT_EQ(queue.Pop(), nullptr);
  EXPECT_EQ(queue.dropped(), 0);
}

TEST(ClientQueueTest, AFullQueueDropsTheOldestAndCountsIt) {
  ClientQueue queue(2);
  for (const char* text : {"1", "2", "3", "4", "5"}) queue.Push(Text(text));
  EXPECT_EQ(queue.size(), 2u);  // never more than its capacity, however many arrive
  EXPECT_EQ(queue.dropped(), 3);
  EXPECT_EQ(*queue.Pop(), "4");  // the newest frames are what a browser should draw
  EXPECT_EQ(*queue.Pop(), "5");
  EXPECT_TRUE(queue.empty());
}

TEST(ClientQueueTest, ACapacityOfOneKeepsOnlyTheNewest) {
  ClientQueue queue(1);
  queue.Push(Text("old"));
  queue.Push(Text("new"));
  EXPECT_EQ(*queue.Pop(), "new");
  EXPECT_EQ(queue.dropped(), 1);
}

TEST(ClientQueueTest, ZeroCapacityIsRefused) { EXPECT_THROW(ClientQueue(0), std::invalid_argument); }

}  // namespace
}  // namespace dream::view
