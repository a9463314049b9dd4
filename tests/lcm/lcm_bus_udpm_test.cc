// LcmBus over real udpm multicast. Run under tests/integration/netns.sh (a
// private network namespace with LCM_DEFAULT_URL on a ttl=0 group); skipped
// elsewhere so it never sends to a real network.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "dream/lcm/lcm_bus.h"

namespace dream::lcm {
namespace {

std::string PrivateUdpmUrlOrEmpty() {
  const char* namespace_marker = std::getenv("DREAM_TEST_NETNS");
  const char* url = std::getenv("LCM_DEFAULT_URL");
  if (namespace_marker == nullptr || url == nullptr || std::string(url).rfind("udpm://", 0) != 0) return "";
  return url;
}

// Handles messages until `done` holds: a wait on the messages themselves, as a loaded machine can
// take any time to deliver them. The 30 s only turns a message that never comes into a failure.
void HandleUntil(LcmBus& bus, const std::function<bool()>& done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!done() && std::chrono::steady_clock::now() < give_up) bus.HandleSubscriptions(5);
}

// LCM 1.3.1 counts queued messages per subscription and only calls a handler
// whose count is positive. Other processes' start-up self-test packets that
// arrive while this process runs its own self test stay queued afterwards,
// counted for no live subscription; delivered later, they used up a count that
// belonged to a real message, so one subscription (the run recorder's ".*")
// silently missed a message another (the sim's commands) received. The bus
// must deliver every message to every matching handler.
TEST(LcmBusUdpmTest, EveryMatchingHandlerSeesEveryMessageWhileOthersStartUp) {
  const std::string url = PrivateUdpmUrlOrEmpty();
  if (url.empty()) GTEST_SKIP() << "needs udpm in a private network namespace (run under netns.sh)";

  LcmBus neighbour(url);
  std::atomic<bool> starting_up{true};
  // A neighbour process starting up: its self-test packets on the shared group.
  std::thread self_tests([&] {
    const char text[] = "lcm self test";
    while (starting_up.load()) {
      neighbour.Publish("LCM_SELF_TEST", text, sizeof(text) - 1);
      std::this_thread::sleep_for(std::chrono::microseconds(100));  // many, without filling LCM's buffers
    }
  });

  LcmBus bus(url);
  int specific = 0;
  int everything = 0;
  const lcm::Subscription specific_handler =
      bus.Subscribe("DREAM_CMD_[0-9]+", [&](const std::string&, const void*, int) { ++specific; });
  const lcm::Subscription everything_handler = bus.Subscribe(".*", [&](const std::string& channel, const void*, int) {
    if (channel.rfind("DREAM_CMD_", 0) == 0) ++everything;
  });
  starting_up = false;
  self_tests.join();

  constexpr int kMessages = 200;
  const char byte = 0;
  for (int i = 0; i < kMessages; ++i) {
    neighbour.Publish("DREAM_CMD_" + std::to_string(i % 10), &byte, 1);
    if (i % 20 == 19) std::this_thread::sleep_for(std::chrono::milliseconds(1));  // stay within the socket buffer
  }
  HandleUntil(bus, [&] { return specific >= kMessages && everything >= kMessages; });
  EXPECT_EQ(specific, kMessages);
  EXPECT_EQ(everything, kMessages) << "the '.*' subscription missed messages the specific one received";
}

// An agent's bus lets the kernel drop the channels its handlers cannot match
// (the other robots' commands), and still hears every message it wants; a
// handler of everything, or another host given LCM's instance, lifts it.
TEST(LcmBusUdpmTest, TheKernelDropsOnlyChannelsNoHandlerCanMatch) {
  const std::string url = PrivateUdpmUrlOrEmpty();
  if (url.empty()) GTEST_SKIP() << "needs udpm in a private network namespace (run under netns.sh)";

  LcmBus world(url);
  LcmBus agent(url);
  int poses = 0;
  int radio = 0;
  int commands = 0;
  const lcm::Subscription poses_handler =
      agent.Subscribe("DREAM_POSES", [&](const std::string&, const void*, int) { ++poses; });
  const lcm::Subscription radio_handler =
      agent.Subscribe("DREAM_RADIO_.*", [&](const std::string&, const void*, int) { ++radio; });
  EXPECT_EQ(agent.kernel_filter_prefixes(), (std::vector<std::string>{"DREAM_POSES", "DREAM_RADIO_"}));

  constexpr int kSteps = 100;
  const char byte = 0;
  for (int step = 0; step < kSteps; ++step) {
    for (int robot = 0; robot < 10; ++robot) world.Publish("DREAM_CMD_" + std::to_string(robot), &byte, 1);
    world.Publish("DREAM_RADIO_" + std::to_string(step % 10), &byte, 1);
    world.Publish("DREAM_POSES", &byte, 1);
    if (step % 10 == 9) std::this_thread::sleep_for(std::chrono::milliseconds(1));  // stay within the socket buffer
  }
  HandleUntil(agent, [&] { return poses >= kSteps && radio >= kSteps; });
  EXPECT_EQ(poses, kSteps);
  EXPECT_EQ(radio, kSteps);

  {
    const lcm::Subscription everything = agent.Subscribe(".*", [&](const std::string& channel, const void*, int) {
      if (channel.rfind("DREAM_CMD_", 0) == 0) ++commands;
    });
    EXPECT_TRUE(agent.kernel_filter_prefixes().empty()) << "a handler of every channel must hear every channel";
    world.Publish("DREAM_CMD_0", &byte, 1);
    HandleUntil(agent, [&] { return commands >= 1; });
    EXPECT_EQ(commands, 1);
  }
  EXPECT_FALSE(agent.kernel_filter_prefixes().empty()) << "filtered again once the handler of everything is gone";
  (void)agent.c_handle();
  EXPECT_TRUE(agent.kernel_filter_prefixes().empty()) << "another host on LCM's instance subscribes unseen by the bus";
}

}  // namespace
}  // namespace dream::lcm
