// The command lines dream spy and dream replay start: LCM's windows on the URL
// every command resolves, a log played on a private port, the player's URL as
// a word of its own.
#include "dream/workflows/lcm_tool_commands.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace dream::workflows {
namespace {

using Words = std::vector<std::string>;

class LcmToolCommandsTest : public ::testing::Test {
 protected:
  void SetUp() override { ::unsetenv("LCM_DEFAULT_URL"); }
  void TearDown() override { ::unsetenv("LCM_DEFAULT_URL"); }
};

TEST_F(LcmToolCommandsTest, TheSpyWatchesTheUrlEveryCommandResolves) {
  ::setenv("LCM_DEFAULT_URL", "udpm://239.255.76.67:7667?ttl=1", 1);
  const std::vector<Words> live = LcmToolCommands::Spy("a.jar:b.jar", "", "");
  ASSERT_EQ(live.size(), 2u);
  EXPECT_EQ(live[0], (Words{"java", "-cp", "a.jar:b.jar", "lcm.spy.Spy",
                            "--lcm-url=udpm://239.255.76.67:7667?ttl=1&recv_buf_size=4194304"}));
  EXPECT_TRUE(live[1].empty());  // no log, no player
  EXPECT_EQ(LcmToolCommands::Spy("a.jar", "", "memq://")[0].back(), "--lcm-url=memq://");
}

TEST_F(LcmToolCommandsTest, ALogIsPlayedForTheSpyOnAPrivateLoopbackPortUnlessAUrlIsGiven) {
  ::setenv("LCM_DEFAULT_URL", "memq://", 1);  // a live run's URL: the log must not go there
  const std::vector<Words> played = LcmToolCommands::Spy("a.jar", "runs/x/run.lcmlog", "");
  const std::string url = std::string(LcmToolCommands::kPrivateLogUrl) + "&recv_buf_size=4194304";
  EXPECT_EQ(played[0].back(), "--lcm-url=" + url);
  EXPECT_EQ(played[1], (Words{"lcm-logplayer", "--lcm-url=" + url, "runs/x/run.lcmlog"}));
  const std::vector<Words> given = LcmToolCommands::Spy("a.jar", "run.lcmlog", "udpm://239.255.76.67:7700?ttl=0");
  EXPECT_EQ(given[1][1], "--lcm-url=udpm://239.255.76.67:7700?ttl=0&recv_buf_size=4194304");
}

TEST_F(LcmToolCommandsTest, ThePlayerTakesTheUrlAsAWordOfItsOwnAndMayStartPaused) {
  const std::string url = LcmToolCommands::Url("udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(url, "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304");
  EXPECT_EQ(
      LcmToolCommands::Player("lcm.jar", "run.lcmlog", url, false),
      (Words{"java", "-Xmx64m", "-Xms32m", "-cp", "lcm.jar", "lcm.logging.LogPlayer", "--lcm-url", url, "run.lcmlog"}));
  const Words paused = LcmToolCommands::Player("lcm.jar", "run.lcmlog", url, true);
  EXPECT_EQ(paused[paused.size() - 2], "--paused");
  EXPECT_EQ(LcmToolCommands::Url(""), "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304");
  EXPECT_THROW(LcmToolCommands::Url("localhost:7667"), std::invalid_argument);
}

}  // namespace
}  // namespace dream::workflows
