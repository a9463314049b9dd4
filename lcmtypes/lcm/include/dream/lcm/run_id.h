#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dream::lcm {

/// A new run's identifier: random, so a second world or a stale process of
/// an earlier run on the same LCM URL can be told apart; never 0, which
/// messages use for "no run" (e.g. commands recorded from a lab's files).
int64_t NewRunId();

/// A run id as 16 hex digits, as logs and summary.json print it (JSON numbers
/// above 2^53 lose digits in most readers).
std::string RunIdText(int64_t run_id);

/// Zeroes the run id in an encoded DREAM message that carries one (every
/// type but rectangle_obstacle_t: right after the fingerprint, utime and
/// step); other bytes are left alone. For comparing two runs' logs, which
/// differ in their ids by design. Returns whether it zeroed one.
bool ClearRunId(std::vector<uint8_t>* encoded);

/// ClearRunId, and zeroes the sending agents' ids too (velocity_command_t,
/// radio_message_t, robot_fault_t, applied_commands_t: each agent process
/// draws its own at random), by decoding and encoding again; bytes that do
/// not decode are left as they are. Two runs of one seed are then equal
/// byte for byte (dream log diff).
void ClearRandomIds(std::vector<uint8_t>* encoded);

}  // namespace dream::lcm
