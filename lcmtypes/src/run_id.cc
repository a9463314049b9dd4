#include "dream/lcm/run_id.h"

#include <cstdio>
#include <cstring>
#include <random>

#include "dream/applied_commands_t.hpp"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::lcm {

int64_t NewRunId() {
  std::random_device source;
  uint64_t id = 0;
  while (id == 0) id = (static_cast<uint64_t>(source()) << 32) | source();
  return static_cast<int64_t>(id);
}

std::string RunIdText(int64_t run_id) {
  char text[24];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(run_id));
  return text;
}

bool ClearRunId(std::vector<uint8_t>* encoded) {
  constexpr size_t kRunIdAt = 8 + 8 + 8;  // fingerprint, utime, step
  if (encoded->size() < kRunIdAt + 8) return false;
  uint64_t fingerprint = 0;
  for (size_t i = 0; i < 8; ++i) fingerprint = (fingerprint << 8) | (*encoded)[i];
  const auto hash = static_cast<int64_t>(fingerprint);
  const bool carries_run_id =
      hash == applied_commands_t::getHash() || hash == obstacles_t::getHash() || hash == radio_message_t::getHash() ||
      hash == robot_fault_t::getHash() || hash == robot_poses_t::getHash() || hash == run_status_t::getHash() ||
      hash == velocity_command_t::getHash();
  if (!carries_run_id) return false;
  std::memset(encoded->data() + kRunIdAt, 0, 8);
  return true;
}

}  // namespace dream::lcm
