#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dream::run_log {

/// Where two payloads of one channel first differ, for `dream log diff`:
/// "step 12, robot 3: x 0.5 vs 0.51" -- the step of the first message, the
/// robot (an array index of a pose-like message, or its robot_id/sender_id)
/// and the first field whose value differs, with both values. Payloads that
/// MessageJson cannot decode (another program's type) are described by the
/// first differing byte.
std::string FirstDifference(const std::vector<uint8_t>& first, const std::vector<uint8_t>& second);

}  // namespace dream::run_log
