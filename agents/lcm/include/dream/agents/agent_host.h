#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dream/agents/controller.h"
#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/run_status_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream {
class robot_poses_t;
}

namespace dream::agents {

/// One robot driven by this host.
struct HostedRobot {
  int robot_id = 0;
  std::unique_ptr<Controller> controller;
};

/// Runs the controllers of one or more robots against whichever world is on
/// the bus (simulator or bridge): it never knows which.
///
/// Reads DREAM_POSES (the step trigger) and DREAM_STATUS; writes
/// DREAM_CMD_<id> for each hosted robot. Lockstep contract: every DREAM_POSES
/// of step k is answered with each robot's command for step k. A repeated
/// DREAM_POSES for a step already answered (the world resends when it waits)
/// gets the same command again, without running the controller twice, so runs
/// stay deterministic.
class AgentHost {
 public:
  /// @param agent_id identifies this host to the world (two hosts may not
  ///        drive one robot); any value unique per process.
  AgentHost(lcm::LcmInterface& lcm, std::vector<HostedRobot> robots, int64_t agent_id);

  /// Handles messages until the world reports FINISHED or ABORTED, `stop` is
  /// set, or no DREAM_POSES arrived for `idle_timeout_s` of wall time.
  /// Returns true when the world ended the run, false otherwise.
  bool Run(const std::atomic<bool>& stop, double idle_timeout_s);

  /// True once DREAM_STATUS said FINISHED or ABORTED.
  bool world_finished() const { return world_finished_; }
  int64_t last_step_answered() const { return last_step_answered_; }
  const lcm::BadMessageLog& bad_messages() const { return bad_messages_; }
  const std::string& end_detail() const { return end_detail_; }

 private:
  struct RobotSlot {
    int robot_id = 0;
    std::string channel;
    std::unique_ptr<Controller> controller;
    int64_t answered_step = -1;
    velocity_command_t last_command{};
  };

  void OnPoses(const std::string& channel, const robot_poses_t& poses);
  void OnStatus(const std::string& channel, const run_status_t& status);

  lcm::LcmInterface& lcm_;
  std::vector<RobotSlot> robots_;
  int64_t agent_id_;
  lcm::BadMessageLog bad_messages_;
  bool world_finished_ = false;
  std::string end_detail_;
  int64_t last_step_answered_ = -1;
  bool saw_poses_since_check_ = false;
};

}  // namespace dream::agents
