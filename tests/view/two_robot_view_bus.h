#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/view/bus_frame_collector.h"
#include "dream/world/world_params.h"

namespace dream::view {

/// A view's bus with a world of two robots at rest: the fixture of the tests of what the view
/// draws from the agents' own channels (their commands, their drawings).
class TwoRobotViewBus : public ::testing::Test {
 protected:
  /// The world's step `step` of run `run_id` (obstacles, status, poses), handled.
  void Step(int64_t run_id, int64_t step) {
    robot_poses_t poses{};
    poses.run_id = run_id;
    poses.step = step;
    poses.num_robots = 2;
    poses.x = {0.0, 0.5};
    poses.y = {0.0, 0.0};
    poses.theta = {0.0, 0.0};
    poses.v = {0.0, 0.0};
    poses.w = {0.0, 0.0};
    run_status_t status{};
    status.run_id = run_id;
    status.step = step;
    status.state = run_status_t::RUNNING;
    status.num_robots = 2;
    obstacles_t obstacles{};
    obstacles.run_id = run_id;
    obstacles.step = step;
    lcm::Publish(bus_, "DREAM_OBSTACLES", obstacles);
    lcm::Publish(bus_, "DREAM_STATUS", status);
    lcm::Publish(bus_, "DREAM_POSES", poses);
    Handle();
  }
  /// `message` on `channel`, handled.
  template <typename Message>
  void Send(const std::string& channel, const Message& message) {
    lcm::Publish(bus_, channel, message);
    Handle();
  }
  void Handle() {
    while (bus_.HandleSubscriptions(0) > 0) {
    }
  }

  lcm::LcmBus bus_{"memq://"};
  BusFrameCollector collector_{bus_, world::WorldParams()};
  uint64_t version_ = 0;
  ViewFrame frame_;
};

}  // namespace dream::view
