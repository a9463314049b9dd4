#include "dream/lcm/run_id.h"

#include <cstdio>
#include <cstring>
#include <random>

#include "dream/applied_commands_t.hpp"
#include "dream/drawing_t.hpp"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/message_header.h"

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
  constexpr size_t kRunIdAt = MessageHeader::kRunIdAt;
  if (encoded->size() < kRunIdAt + 8) return false;
  uint64_t fingerprint = 0;
  for (size_t i = 0; i < 8; ++i) fingerprint = (fingerprint << 8) | (*encoded)[i];
  const auto hash = static_cast<int64_t>(fingerprint);
  const bool carries_run_id =
      hash == applied_commands_t::getHash() || hash == drawing_t::getHash() || hash == obstacles_t::getHash() ||
      hash == radio_message_t::getHash() || hash == robot_busy_t::getHash() || hash == robot_commands_t::getHash() ||
      hash == robot_fault_t::getHash() || hash == robot_poses_t::getHash() || hash == run_status_t::getHash() ||
      hash == run_verdict_t::getHash() || hash == velocity_command_t::getHash();
  if (!carries_run_id) return false;
  std::memset(encoded->data() + kRunIdAt, 0, 8);
  return true;
}

namespace {

// Decodes `encoded` as a Message (when its fingerprint says so), lets `clear`
// zero its agent ids, and encodes it back in place.
template <typename Message, typename Clear>
bool Rewrite(std::vector<uint8_t>* encoded, Clear clear) {
  Message message;
  if (!Decode(encoded->data(), static_cast<int>(encoded->size()), &message)) return false;
  clear(&message);
  const int size = message.getEncodedSize();
  std::vector<uint8_t> rewritten(static_cast<size_t>(size));
  if (message.encode(rewritten.data(), 0, size) != size) return false;
  encoded->swap(rewritten);
  return true;
}

}  // namespace

void ClearRandomIds(std::vector<uint8_t>* encoded) {
  if (!ClearRunId(encoded)) return;  // not a dream message that carries ids
  Rewrite<velocity_command_t>(encoded, [](velocity_command_t* m) { m->agent_id = 0; }) ||
      Rewrite<radio_message_t>(encoded, [](radio_message_t* m) { m->agent_id = 0; }) ||
      Rewrite<robot_busy_t>(encoded, [](robot_busy_t* m) { m->agent_id = 0; }) ||
      Rewrite<drawing_t>(encoded, [](drawing_t* m) { m->agent_id = 0; }) ||
      Rewrite<robot_commands_t>(encoded, [](robot_commands_t* m) { m->agent_id = 0; }) ||
      Rewrite<robot_fault_t>(encoded, [](robot_fault_t* m) { m->agent_id = 0; }) ||
      Rewrite<applied_commands_t>(encoded, [](applied_commands_t* m) {
        for (int64_t& id : m->applied_agent_id) id = 0;
      });
}

}  // namespace dream::lcm
