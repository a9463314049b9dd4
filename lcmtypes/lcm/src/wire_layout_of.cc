#include "dream/lcm/wire_layout_of.h"

#include "dream/applied_commands_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/lcm/message_limits.h"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/velocity_command_t.hpp"

// Each layout follows its .lcm file field by field (lcmtypes/dream/). A test
// encodes messages with every count and checks the layout accepts exactly
// their bytes, so a changed .lcm file without a changed layout fails there.
namespace dream::lcm {
namespace {

constexpr int kInt8 = 1;
constexpr int kInt32 = 4;
constexpr int kInt64 = 8;
constexpr int kDouble = 8;
// rectangle_obstacle_t, nested without its fingerprint: id, then six doubles.
constexpr int kRectangleObstacle = kInt32 + 6 * kDouble;

// What every dream message starts with: its fingerprint, then utime, step and run_id.
template <typename Message>
WireLayout MessageStart() {
  return WireLayout(Message::getHash()).Fixed(kInt64 + kInt64 + kInt64);
}

}  // namespace

template <>
const WireLayout& WireLayoutOf<applied_commands_t>() {
  static const WireLayout layout = MessageStart<applied_commands_t>()
                                       .Count(MessageLimits::kRobots)
                                       .Array(kInt64)   // applied_agent_id
                                       .Array(kDouble)  // commanded_v
                                       .Array(kDouble)  // commanded_w
                                       .Array(kInt32);  // conflicts
  return layout;
}

template <>
const WireLayout& WireLayoutOf<drawing_t>() {
  static const WireLayout layout = MessageStart<drawing_t>()
                                       .Fixed(kInt32)  // robot_id
                                       .AgentId()
                                       .Fixed(kInt32)  // clipped
                                       .Count(drawing_t::MAX_SHAPES)
                                       .Array(kInt8)    // kind
                                       .Array(kInt32)   // rgba
                                       .Array(kDouble)  // width
                                       .Array(kDouble)  // size
                                       .Array(kInt8)    // fill
                                       .Array(kInt32)   // point_count
                                       .Array(kInt32)   // text_length
                                       .Count(drawing_t::MAX_POINTS)
                                       .Array(kDouble)  // x
                                       .Array(kDouble)  // y
                                       .Count(drawing_t::MAX_ALL_TEXT_BYTES)
                                       .Array(kInt8);  // text
  return layout;
}

template <>
const WireLayout& WireLayoutOf<obstacles_t>() {
  static const WireLayout layout =
      MessageStart<obstacles_t>().Count(MessageLimits::kObstacles).Array(kRectangleObstacle);
  return layout;
}

template <>
const WireLayout& WireLayoutOf<radio_message_t>() {
  static const WireLayout layout = MessageStart<radio_message_t>()
                                       .Fixed(kInt32)  // sender_id
                                       .AgentId()
                                       .Count(MessageLimits::kRadioPayloadBytes)
                                       .Array(kInt8);
  return layout;
}

template <>
const WireLayout& WireLayoutOf<robot_busy_t>() {
  static const WireLayout layout = MessageStart<robot_busy_t>()
                                       .Fixed(kInt32)             // robot_id
                                       .AgentId()                 //
                                       .Fixed(kInt32 + kDouble);  // call_robot_id, call_s
  return layout;
}

template <>
const WireLayout& WireLayoutOf<robot_commands_t>() {
  static const WireLayout layout = MessageStart<robot_commands_t>()
                                       .AgentId()
                                       .Count(MessageLimits::kRobots)
                                       .Array(kInt32)    // robot_id
                                       .Array(kDouble)   // v
                                       .Array(kDouble)   // w
                                       .BooleanArray();  // done
  return layout;
}

template <>
const WireLayout& WireLayoutOf<robot_fault_t>() {
  static const WireLayout layout = MessageStart<robot_fault_t>()
                                       .Fixed(kInt32)  // robot_id
                                       .AgentId()
                                       .String(MessageLimits::kDetailBytes);
  return layout;
}

template <>
const WireLayout& WireLayoutOf<robot_poses_t>() {
  static const WireLayout layout = MessageStart<robot_poses_t>()
                                       .Count(MessageLimits::kRobots)
                                       .Array(kDouble)   // x
                                       .Array(kDouble)   // y
                                       .Array(kDouble)   // theta
                                       .Array(kDouble)   // v
                                       .Array(kDouble);  // w
  return layout;
}

template <>
const WireLayout& WireLayoutOf<run_status_t>() {
  static const WireLayout layout =
      MessageStart<run_status_t>()
          .Fixed(kInt8 + kInt32)  // state, num_robots
          // boundary, collision, actuator errors, obstacle collisions, rejected commands, conflicts
          .Fixed(6 * kInt64)
          .Count(MessageLimits::kRobots)
          .Array(kInt32)  // lost_robot_ids
          .String(MessageLimits::kDetailBytes);
  return layout;
}

template <>
const WireLayout& WireLayoutOf<run_verdict_t>() {
  static const WireLayout layout = MessageStart<run_verdict_t>()
                                       .Fixed(kInt8 + kInt8 + kInt32 + kInt64)  // verdict, goal, exit code, step met
                                       .String(MessageLimits::kDetailBytes)     // goal_text
                                       .String(MessageLimits::kDetailBytes);    // reasons
  return layout;
}

template <>
const WireLayout& WireLayoutOf<velocity_command_t>() {
  static const WireLayout layout = MessageStart<velocity_command_t>()
                                       .Fixed(kInt32)  // robot_id
                                       .AgentId()
                                       .Fixed(kDouble + kDouble)  // v, w
                                       .Boolean();                // done
  return layout;
}

}  // namespace dream::lcm
