// HostedAgents on a bus of their own: the URL resolved as every command
// resolves it (the command line's --lcm-url, else $LCM_DEFAULT_URL), a bad one
// named before any agent starts.
#include "dream/hosting/hosted_agents.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "dream/run_config/run_config.h"
#include "../support/source_tree.h"

namespace dream::hosting {
namespace {

class HostedAgentsTest : public ::testing::Test {
 protected:
  void TearDown() override { ::unsetenv("LCM_DEFAULT_URL"); }
  const run_config::RunConfig config_ =
      run_config::LoadRunConfigFile(dream::testing::SourceDir() + "/config/go_to_goal.yaml");
};

TEST_F(HostedAgentsTest, AgentsOnTheirOwnBusAreOnTheUrlGivenElseTheEnvironments) {
  ::setenv("LCM_DEFAULT_URL", "udpm://239.255.76.67:7667?ttl=0", 1);
  const HostedAgents given("memq://", config_, {0, 1}, {});
  EXPECT_EQ(given.url(), "memq://");
  ::setenv("LCM_DEFAULT_URL", "memq://", 1);
  const HostedAgents from_environment("", config_, {0}, {});
  EXPECT_EQ(from_environment.url(), "memq://");
  EXPECT_EQ(from_environment.last_step_answered(), -1);
}

TEST_F(HostedAgentsTest, AUrlLcmCannotOpenIsNamed) {
  EXPECT_THROW(HostedAgents("localhost:7667", config_, {0}, {}), std::invalid_argument);
  try {
    HostedAgents agents("nosuchprovider://x", config_, {0}, {});
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nosuchprovider://x"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dream::hosting
