#pragma once

#include "dream/lcm/wire_layout.h"

namespace dream {
class applied_commands_t;
class drawing_t;
class obstacles_t;
class radio_message_t;
class robot_busy_t;
class robot_commands_t;
class robot_fault_t;
class robot_poses_t;
class run_status_t;
class run_verdict_t;
class velocity_command_t;
}  // namespace dream

namespace dream::lcm {

/// The wire layout of `Message`, one of the dream types, with the counts
/// bounded by MessageLimits. Only the specialisations below exist: a new
/// type must get one (lcm::Decode will not compile without it).
template <typename Message>
const WireLayout& WireLayoutOf();

template <>
const WireLayout& WireLayoutOf<applied_commands_t>();
template <>
const WireLayout& WireLayoutOf<drawing_t>();
template <>
const WireLayout& WireLayoutOf<obstacles_t>();
template <>
const WireLayout& WireLayoutOf<radio_message_t>();
template <>
const WireLayout& WireLayoutOf<robot_busy_t>();
template <>
const WireLayout& WireLayoutOf<robot_commands_t>();
template <>
const WireLayout& WireLayoutOf<robot_fault_t>();
template <>
const WireLayout& WireLayoutOf<robot_poses_t>();
template <>
const WireLayout& WireLayoutOf<run_status_t>();
template <>
const WireLayout& WireLayoutOf<run_verdict_t>();
template <>
const WireLayout& WireLayoutOf<velocity_command_t>();

}  // namespace dream::lcm
