#include "dream/view/live_view.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/view/view_server.h"

namespace dream::view {
namespace {

/// One step of a world of one robot, as it publishes it: status, then poses.
void PublishStep(lcm::LcmBus& bus, int64_t run_id, int64_t step, int8_t state) {
  run_status_t status{};
  status.run_id = run_id;
  status.step = step;
  status.state = state;
  status.num_robots = 1;
  robot_poses_t poses{};
  poses.run_id = run_id;
  poses.step = step;
  poses.num_robots = 1;
  poses.x = poses.y = poses.theta = poses.v = poses.w = {0.0};
  lcm::Publish(bus, "DREAM_STATUS", status);
  lcm::Publish(bus, "DREAM_POSES", poses);
  while (bus.HandleSubscriptions(0) > 0) {
  }
}

TEST(LiveViewTest, APageChoosesAnotherRunHeardByItsDecimalId) {
  lcm::LcmBus bus("memq://");
  ViewServer server({"127.0.0.1", 0, false, 4});
  LiveView live(bus, server, ViewSetup{});
  PublishStep(bus, 5, 0, run_status_t::RUNNING);
  PublishStep(bus, -9, 0, run_status_t::WAITING_FOR_AGENTS);  // a run id above 2^63, as frames carry it: "-9"
  EXPECT_FALSE(live.OnPageMessage("follow 77"));  // no such run heard
  EXPECT_FALSE(live.OnPageMessage("follow 5"));   // the one drawn
  EXPECT_FALSE(live.OnPageMessage("follow -9x"));
  EXPECT_FALSE(live.OnPageMessage("follow "));
  EXPECT_FALSE(live.OnPageMessage("follow 99999999999999999999"));  // past int64
  EXPECT_FALSE(live.OnPageMessage("draw -9"));
  EXPECT_FALSE(live.OnPageMessage(std::string("follow -9\0", 10)));
  EXPECT_TRUE(live.OnPageMessage("follow -9"));
}

}  // namespace
}  // namespace dream::view
