#include <gtest/gtest.h>

#include <lcm/lcm.h>

#include <cstdlib>
#include <stdexcept>
#include <memory>
#include <string>
#include <vector>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/lcm_url.h"
#include "dream/velocity_command_t.hpp"

namespace dream::lcm {
namespace {

void DrainBus(LcmBus& bus) {
  while (bus.HandleSubscriptions(0) > 0) {
  }
}

TEST(LcmBusTest, TypedPublishSubscribeOverMemq) {
  LcmBus bus("memq://");
  BadMessageLog bad;
  std::vector<velocity_command_t> received;
  const Subscription commands = Subscribe<velocity_command_t>(
      bus, "DREAM_CMD_.*", [&](const std::string&, const velocity_command_t& m) { received.push_back(m); }, bad);
  velocity_command_t command{};
  command.step = 7;
  command.robot_id = 3;
  command.v = 0.1;
  command.w = -0.5;
  Publish(bus, CommandChannel(3), command);
  DrainBus(bus);
  ASSERT_EQ(received.size(), 1u);
  EXPECT_EQ(received[0].step, 7);
  EXPECT_EQ(received[0].robot_id, 3);
  EXPECT_DOUBLE_EQ(received[0].w, -0.5);
  EXPECT_EQ(bad.total(), 0);
}

TEST(LcmBusTest, RoutesOfMadeUpChannelsPastTheCapAreNotKeptButStillDelivered) {
  LcmBus bus("memq://");
  int delivered = 0;
  const Subscription flood = bus.Subscribe("FLOOD_.*", [&](const std::string&, const void*, int) { ++delivered; });
  const int channels = static_cast<int>(LcmBus::kMaxRoutedChannels) + 100;
  const char byte = 0;
  for (int i = 0; i < channels; ++i) {
    bus.Publish("FLOOD_" + std::to_string(i), &byte, 1);
    DrainBus(bus);  // memq queues per subscription: keep it short
  }
  bus.Publish("FLOOD_0", &byte, 1);  // a cached route
  DrainBus(bus);
  EXPECT_EQ(delivered, channels + 1);
  EXPECT_EQ(bus.uncached_deliveries(), 100);  // the channels past the cap, matched per message
}

TEST(LcmBusTest, UndecodableMessagesAreCountedPerChannelNotDelivered) {
  LcmBus bus("memq://");
  BadMessageLog bad;
  int delivered = 0;
  const Subscription commands = Subscribe<velocity_command_t>(
      bus, "DREAM_CMD_.*", [&](const std::string&, const velocity_command_t&) { ++delivered; }, bad);
  const char garbage[] = "definitely not a velocity_command_t";
  bus.Publish("DREAM_CMD_1", garbage, sizeof(garbage));
  bus.Publish("DREAM_CMD_1", garbage, 3);
  // A valid message with trailing bytes is not a clean decode either.
  velocity_command_t command{};
  std::vector<uint8_t> bytes(static_cast<size_t>(command.getEncodedSize()) + 4, 0);
  command.encode(bytes.data(), 0, command.getEncodedSize());
  bus.Publish("DREAM_CMD_2", bytes.data(), static_cast<int>(bytes.size()));
  DrainBus(bus);
  EXPECT_EQ(delivered, 0);
  EXPECT_EQ(bad.count("DREAM_CMD_1"), 2);
  EXPECT_EQ(bad.count("DREAM_CMD_2"), 1);
  EXPECT_EQ(bad.total(), 3);
}

TEST(LcmBusTest, ExceptionsInHandlersAreCaughtAndCounted) {
  LcmBus bus("memq://");
  int after = 0;
  const Subscription failing =
      bus.Subscribe("BOOM", [](const std::string&, const void*, int) { throw std::runtime_error("handler bug"); });
  const Subscription after_failing = bus.Subscribe("BOOM", [&](const std::string&, const void*, int) { ++after; });
  const char byte = 1;
  bus.Publish("BOOM", &byte, 1);
  bus.Publish("BOOM", &byte, 1);
  EXPECT_NO_THROW(DrainBus(bus));
  EXPECT_EQ(bus.handler_failures(), 2);
  EXPECT_EQ(after, 2);  // the other subscriber still gets every message
}

TEST(LcmBusTest, ManyMessagesPerStepAreNotDroppedByTheQueue) {
  // LCM's default queue of 30 would drop most of these before the drain.
  LcmBus bus("memq://");
  int received = 0;
  const Subscription commands =
      bus.Subscribe("DREAM_CMD_.*", [&](const std::string&, const void*, int) { ++received; });
  const char byte = 0;
  for (int i = 0; i < 500; ++i) bus.Publish(CommandChannel(i % 50), &byte, 1);
  DrainBus(bus);
  EXPECT_EQ(received, 500);
}

// A memq bus queues messages itself (LCM's memq provider costs three system
// calls per message), with LCM's memq rules: first in, first out; bounded;
// a message nobody wants when it is published is dropped.
TEST(LcmBusTest, MemqMessageNobodyWantsWhenPublishedIsDroppedWithOrWithoutLcm) {
  for (const bool through_lcm : {false, true}) {
    LcmBus bus("memq://");
    if (through_lcm) bus.c_handle();
    const char early = 'e';
    bus.Publish("LATE", &early, 1);
    int heard = 0;
    const Subscription late = bus.Subscribe("LATE", [&](const std::string&, const void*, int) { ++heard; });
    DrainBus(bus);
    EXPECT_EQ(heard, 0) << (through_lcm ? "LCM's memq" : "the bus's own queue") << " delivered a message published "
                        << "before anyone subscribed";
  }
}

TEST(LcmBusTest, MemqQueueKeepsLcmsOrderBoundAndDropRule) {
  LcmBus bus("memq://");
  const char early = 'e';
  bus.Publish("LATE", &early, 1);  // no handler yet: dropped, as LCM drops it
  std::vector<std::string> heard;
  const Subscription late_or_order =
      bus.Subscribe("LATE|ORDER", [&](const std::string& channel, const void* data, int size) {
        heard.push_back(channel + ":" + std::string(static_cast<const char*>(data), static_cast<size_t>(size)));
      });
  EXPECT_EQ(bus.HandleSubscriptions(0), 0) << "the message published before any handler must be gone";
  for (int i = 0; i < LcmBus::kQueueCapacity + 5; ++i) {
    const std::string text = std::to_string(i);
    bus.Publish("ORDER", text.data(), static_cast<int>(text.size()));
  }
  EXPECT_EQ(bus.queue_overflows(), 5);
  EXPECT_EQ(bus.dropped_messages(), 5);  // what a run's summary reports as dropped_messages
  DrainBus(bus);
  ASSERT_EQ(heard.size(), static_cast<size_t>(LcmBus::kQueueCapacity));
  EXPECT_EQ(heard.front(), "ORDER:0");
  EXPECT_EQ(heard.back(), "ORDER:" + std::to_string(LcmBus::kQueueCapacity - 1));
  EXPECT_EQ(bus.HandleSubscriptions(5), 0) << "an empty queue waits for the timeout and handles nothing";
}

// Once another host takes LCM's instance (the embedded Python agents), the
// bus publishes through LCM: that host hears the bus's messages, the bus
// hears the host's, and what was queued before is delivered first.
TEST(LcmBusTest, MemqBusGoesThroughLcmOnceItsInstanceIsShared) {
  LcmBus bus("memq://");
  std::vector<std::string> bus_heard;
  const Subscription bus_side =
      bus.Subscribe("TO_BUS|BOTH", [&](const std::string& channel, const void*, int) { bus_heard.push_back(channel); });
  const char byte = 1;
  bus.Publish("BOTH", &byte, 1);  // queued by the bus itself
  lcm_t* shared = bus.c_handle();
  std::vector<std::string> host_heard;
  lcm_subscription_t* host = lcm_subscribe(
      shared, "BOTH",
      [](const lcm_recv_buf_t*, const char* channel, void* heard) {
        static_cast<std::vector<std::string>*>(heard)->push_back(channel);
      },
      &host_heard);
  ASSERT_NE(host, nullptr);
  bus.Publish("BOTH", &byte, 1);                          // through LCM now
  ASSERT_EQ(lcm_publish(shared, "TO_BUS", &byte, 1), 0);  // the host's message reaches the bus
  DrainBus(bus);
  EXPECT_EQ(bus_heard, (std::vector<std::string>{"BOTH", "BOTH", "TO_BUS"}));
  // LCM's memq hands a message to whoever is subscribed when it is handled, so
  // the host hears the one queued before it subscribed too, as it did when
  // every message went through LCM.
  EXPECT_EQ(host_heard, (std::vector<std::string>{"BOTH", "BOTH"}));
  lcm_unsubscribe(shared, host);
}

TEST(LcmBusTest, OverlappingSubscriptionsEachGetEveryMessage) {
  LcmBus bus("memq://");
  int commands = 0, everything = 0, robot_three = 0;
  const Subscription commands_only =
      bus.Subscribe("DREAM_CMD_.*", [&](const std::string&, const void*, int) { ++commands; });
  const Subscription everything_handler =
      bus.Subscribe(".*", [&](const std::string&, const void*, int) { ++everything; });
  const Subscription robot_three_only =
      bus.Subscribe("DREAM_CMD_3", [&](const std::string&, const void*, int) { ++robot_three; });
  const char byte = 0;
  for (int i = 0; i < 10; ++i) bus.Publish(CommandChannel(i), &byte, 1);
  bus.Publish("DREAM_POSES", &byte, 1);
  bus.Publish("DREAM_CMD_33", &byte, 1);  // the whole name must match, as in LCM
  DrainBus(bus);
  EXPECT_EQ(commands, 11);
  EXPECT_EQ(everything, 12);
  EXPECT_EQ(robot_three, 1);
}

TEST(LcmBusTest, HandlerMaySubscribeWhileItRuns) {
  LcmBus bus("memq://");
  int late = 0;
  bool subscribed = false;
  std::vector<Subscription> late_subscriptions;
  const Subscription first = bus.Subscribe("A", [&](const std::string&, const void*, int) {
    if (subscribed) return;
    subscribed = true;
    late_subscriptions.push_back(bus.Subscribe("B", [&](const std::string&, const void*, int) { ++late; }));
  });
  const char byte = 0;
  bus.Publish("A", &byte, 1);
  DrainBus(bus);
  bus.Publish("B", &byte, 1);
  DrainBus(bus);
  EXPECT_TRUE(subscribed);
  EXPECT_EQ(late, 1);
}

TEST(LcmBusTest, InvalidChannelRegexNamesIt) {
  LcmBus bus("memq://");
  try {
    const Subscription never = bus.Subscribe("DREAM_CMD_(", [](const std::string&, const void*, int) {});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("DREAM_CMD_("), std::string::npos) << e.what();
  }
}

TEST(LcmBusTest, BadUrlNamesTheUrl) {
  try {
    LcmBus bus("nosuchprovider://x");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nosuchprovider://x"), std::string::npos) << e.what();
  }
}

TEST(LcmUrlTest, CommandLineWinsThenEnvironmentThenFallback) {
  ::setenv("LCM_DEFAULT_URL", "memq://", 1);
  EXPECT_EQ(ResolveLcmUrl("udpm://239.255.76.67:7667?ttl=0&recv_buf_size=100"),
            "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=100");
  EXPECT_EQ(ResolveLcmUrl(""), "memq://");
  ::unsetenv("LCM_DEFAULT_URL");
  EXPECT_EQ(ResolveLcmUrl(""), "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304");
  EXPECT_EQ(ResolveLcmUrl("udpm://239.255.76.67:7667"), "udpm://239.255.76.67:7667?recv_buf_size=4194304");
  EXPECT_THROW(ResolveLcmUrl("localhost:7667"), std::invalid_argument);
}

TEST(ChannelsTest, RobotIdFromCommandChannel) {
  EXPECT_EQ(RobotIdFromCommandChannel("DREAM_CMD_0"), 0);
  EXPECT_EQ(RobotIdFromCommandChannel("DREAM_CMD_49"), 49);
  EXPECT_FALSE(RobotIdFromCommandChannel("DREAM_CMD_"));
  EXPECT_FALSE(RobotIdFromCommandChannel("DREAM_CMD_x"));
  EXPECT_FALSE(RobotIdFromCommandChannel("DREAM_CMD_-1"));
  EXPECT_FALSE(RobotIdFromCommandChannel("DREAM_CMD_99999999999"));
  EXPECT_FALSE(RobotIdFromCommandChannel("DREAM_POSES"));
}

// Issue 24: a subscription lasts as long as its handle, so a host that
// subscribes its own members is never called after it is gone.
TEST(LcmBusTest, DestroyingTheSubscriptionStopsItsHandlerOnly) {
  LcmBus bus("memq://");
  int kept = 0;
  int dropped = 0;
  const Subscription keep = bus.Subscribe("CH", [&](const std::string&, const void*, int) { ++kept; });
  auto drop =
      std::make_unique<Subscription>(bus.Subscribe("CH", [&](const std::string&, const void*, int) { ++dropped; }));
  const char byte = 0;
  bus.Publish("CH", &byte, 1);
  DrainBus(bus);
  drop.reset();
  bus.Publish("CH", &byte, 1);
  DrainBus(bus);
  EXPECT_EQ(kept, 2);
  EXPECT_EQ(dropped, 1);
  EXPECT_TRUE(keep.active());
}

TEST(LcmBusTest, AHandlerMayCancelItsOwnSubscriptionWhileItRuns) {
  for (const bool through_lcm : {false, true}) {
    LcmBus bus("memq://");
    if (through_lcm) bus.c_handle();
    int heard = 0;
    Subscription self;
    self = bus.Subscribe("ONCE", [&](const std::string&, const void*, int) {
      ++heard;
      self.Cancel();
    });
    const char byte = 0;
    bus.Publish("ONCE", &byte, 1);
    bus.Publish("ONCE", &byte, 1);
    DrainBus(bus);
    EXPECT_EQ(heard, 1) << (through_lcm ? "LCM's memq" : "the bus's own queue");
    EXPECT_FALSE(self.active());
  }
}

TEST(LcmBusTest, AMovedSubscriptionStaysAndOneOutlivingTheBusIsHarmless) {
  Subscription outliving;
  {
    LcmBus bus("memq://");
    int heard = 0;
    Subscription first = bus.Subscribe("CH", [&](const std::string&, const void*, int) { ++heard; });
    outliving = std::move(first);
    EXPECT_FALSE(first.active());  // NOLINT(bugprone-use-after-move): moved-from is inactive by contract
    const char byte = 0;
    bus.Publish("CH", &byte, 1);
    DrainBus(bus);
    EXPECT_EQ(heard, 1);
  }
  EXPECT_TRUE(outliving.active());
  outliving.Cancel();  // the bus is gone: nothing to do, nothing to crash
  EXPECT_FALSE(outliving.active());
}

}  // namespace
}  // namespace dream::lcm
