#include "dream/view/live_view.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/view/view_server.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

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
  EXPECT_FALSE(live.OnPageMessage("follow 77"));              // no such run heard
  EXPECT_FALSE(live.OnPageMessage("follow 5"));               // the one drawn
  EXPECT_FALSE(live.OnPageMessage("follow -9x"));
  EXPECT_FALSE(live.OnPageMessage("follow "));
  EXPECT_FALSE(live.OnPageMessage("follow 99999999999999999999"));  // past int64
  EXPECT_FALSE(live.OnPageMessage("draw -9"));
  EXPECT_FALSE(live.OnPageMessage(std::string("follow -9\0", 10)));
  EXPECT_TRUE(live.OnPageMessage("follow -9"));
}

// dream run --view: the view followed the run on the bus; its last messages, which no handler
// read once the world stopped, are taken from the run's log (RunLog) and drawn.
TEST(LiveViewTest, TheEndOfARunIsDrawnFromItsLog) {
  testing::TempFolder dir;
  testing::SyntheticRunLog log(dir / "run.lcmlog");
  for (int64_t step = 0; step < 3; ++step) {
    robot_poses_t poses{};
    poses.run_id = 5;
    poses.step = step;
    poses.num_robots = 1;
    poses.x = {0.1 * static_cast<double>(step)};
    poses.y = poses.theta = poses.v = poses.w = {0.0};
    log.MessageOn("DREAM_POSES", poses);
  }
  lcm::LcmBus bus("memq://");
  ViewServer server({"127.0.0.1", 0, false, 4});
  LiveView live(bus, server, ViewSetup{});
  PublishStep(bus, 5, 0, run_status_t::RUNNING);  // the run, followed from its start
  live.PumpOnce();
  const int64_t before = live.frames_sent();
  ASSERT_GE(before, 1);
  live.ShowEndOf(log.Write());
  EXPECT_GT(live.frames_sent(), before);  // step 2, drawn (by ShowEndOf or the pump, whichever took it first)
  try {
    live.ShowEndOf(dir / "missing.lcmlog");
    ADD_FAILURE() << "showed a log that is not there";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir / "missing.lcmlog"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dream::view
