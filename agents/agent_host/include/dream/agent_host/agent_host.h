#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "dream/agents/framework/robot_agent.h"
#include "dream/agents/framework/world_snapshot.h"
#include "dream/drawing_t.hpp"
#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/lcm/world_follower.h"
#include "dream/radio_message_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream {
class obstacles_t;
class robot_poses_t;
}  // namespace dream

namespace dream::agent_host {

/// Runs the agents of one or more robots against whichever world is on the
/// bus (simulator or bridge): it never knows which.
///
/// Reads DREAM_POSES (the step trigger), DREAM_OBSTACLES, DREAM_STATUS and
/// every DREAM_RADIO_<id>; writes DREAM_RADIO_<id>, DREAM_DRAW_<id> (what the
/// robot drew, when it changed; clipped drawings logged once per reason) and
/// DREAM_CMD_<id> for each hosted robot. Lockstep contract: each DREAM_POSES of step k is answered
/// with every hosted robot's command for step k, its radio message (if any)
/// sent just before. A repeated DREAM_POSES for a step already answered (the
/// world resends while it waits) gets the same messages again without running
/// the robot twice, so runs stay deterministic. Bad messages from the world
/// or from neighbours are counted and dropped, never fatal: those that do not
/// decode as LCM types here (bad_messages()), and radio payloads a hosted
/// robot could not decode (bad_radio_payloads(i), by the sender's channel).
/// Both are logged the first time on a channel and then every 100th; the
/// payload totals once more per robot when the host is destroyed. Radio
/// messages from senders outside the run (ids past DREAM_POSES' count) are
/// counted as bad too, so forged senders cannot grow the mailboxes.
///
/// The host follows the run it joined (WorldFollower): messages of another
/// run, steps out of sequence and radio messages from the future are ignored,
/// so one forged datagram cannot freeze, end or jam the robots.
class AgentHost {
 public:
  /// @param agent_id identifies this host to the world (two hosts may not
  ///        drive one robot); any value unique per process.
  AgentHost(lcm::LcmInterface& lcm, std::vector<std::unique_ptr<agents::RobotAgent>> agents, int64_t agent_id);
  /// Logs each robot's total of undecodable radio payloads, if any.
  ~AgentHost();
  AgentHost(const AgentHost&) = delete;
  AgentHost& operator=(const AgentHost&) = delete;

  /// The robot count of the config the agents were built from: DREAM_POSES
  /// of a world with another count are refused as bad messages and never
  /// joined (agents started with another experiment's config would
  /// otherwise drive its robots), and Run() names the mismatch when that was
  /// all it heard. Without it, any count is followed.
  void ExpectWorldOfRobots(int num_robots) { expected_robots_ = num_robots; }

  /// Handles messages until the world reports FINISHED or ABORTED, `stop` is
  /// set, or no DREAM_POSES arrived for `idle_timeout_s` of wall time.
  /// Returns true when the world ended the run, false otherwise.
  bool Run(const std::atomic<bool>& stop, double idle_timeout_s);

  bool world_finished() const { return world_finished_; }
  int64_t last_step_answered() const { return last_step_answered_; }
  const lcm::BadMessageLog& bad_messages() const { return bad_messages_; }
  const lcm::WorldFollower& follower() const { return follower_; }
  const std::string& end_detail() const { return end_detail_; }
  const agents::RobotAgent& agent(size_t i) const { return *robots_.at(i).agent; }
  /// Radio payloads hosted robot `i` (in the order given) dropped because
  /// they did not decode, by the sender's channel DREAM_RADIO_<id>
  /// (kUnknownSenderChannel when the robot did not say whose it was).
  const lcm::BadMessageLog& bad_radio_payloads(size_t i) const { return robots_.at(i).bad_radio_payloads; }
  static constexpr const char* kUnknownSenderChannel = "DREAM_RADIO_<unknown sender>";

 private:
  struct RobotSlot {
    std::unique_ptr<agents::RobotAgent> agent;
    std::string command_channel;
    std::string radio_channel;
    velocity_command_t last_command{};
    std::optional<radio_message_t> last_radio;
    std::string draw_channel;
    /// This step's drawing, sent with its command (and again with a resend).
    std::optional<drawing_t> last_drawing;
    /// What the robot drew last time it drew: a drawing like it is not sent again.
    agents::Drawing drawn;
    std::set<std::string> clip_reasons_logged;
    lcm::BadMessageLog bad_radio_payloads;
    /// Why the host gave the robot up (its controller broke the contract),
    /// said once on DREAM_FAULT_<id>; empty while it is answered.
    std::string fault;
  };

  void OnPoses(const std::string& channel, const robot_poses_t& poses);
  void OnObstacles(const std::string& channel, const obstacles_t& obstacles);
  void OnStatus(const std::string& channel, const run_status_t& status);
  void OnRadio(const std::string& channel, const radio_message_t& message);
  /// Runs the robot for this step; false when its controller failed (the
  /// host then says so on DREAM_FAULT_<id> and stops answering for it).
  bool Answer(RobotSlot& robot, const robot_poses_t& poses);
  void Fail(RobotSlot& robot, const robot_poses_t& poses, const std::string& detail);
  /// Keeps `drawing` as the robot's message for this step when it differs from what it drew last.
  void TakeDrawing(RobotSlot& robot, const robot_poses_t& poses, agents::Drawing drawing);
  /// Hands a radio message of the followed run to every hosted robot, or
  /// counts it as bad when it was sent at a step not yet reached.
  void Deliver(const std::string& channel, const radio_message_t& message);
  /// Logs the payloads the robot counted as bad since the last call.
  static void ReportBadRadioPayloads(RobotSlot& robot);

  lcm::LcmInterface& lcm_;
  std::vector<RobotSlot> robots_;
  int64_t agent_id_;
  lcm::BadMessageLog bad_messages_;
  agents::WorldSnapshot world_;
  bool world_finished_ = false;
  std::string end_detail_;
  int64_t last_step_answered_ = -1;
  bool saw_poses_since_check_ = false;
  lcm::WorldFollower follower_;
  int64_t obstacles_run_id_ = 0;      // run of world_.obstacles
  int expected_robots_ = -1;          // -1: any
  int last_other_world_robots_ = -1;  // the count of the last refused world
  /// Radio messages heard before the first DREAM_POSES (a neighbour may
  /// answer step 0 first); delivered on joining if of the joined run.
  std::vector<std::pair<std::string, radio_message_t>> radio_before_joining_;
  /// Last: unsubscribed first, before anything the handlers use is gone.
  std::vector<lcm::Subscription> subscriptions_;
};

}  // namespace dream::agent_host
