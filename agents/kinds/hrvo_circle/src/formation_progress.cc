#include "dream/hrvo_circle/formation_progress.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "dream/agents/framework/byte_reader.h"
#include "dream/agents/framework/byte_writer.h"

namespace dream::hrvo_circle {

FormationProgress::FormationProgress(int num_robots, int num_formations) : num_formations_(num_formations) {
  if (num_robots < 1) throw std::invalid_argument("num_robots must be >= 1, got " + std::to_string(num_robots));
  if (num_formations < 1) {
    throw std::invalid_argument("num_formations must be >= 1, got " + std::to_string(num_formations));
  }
  states_.assign(static_cast<size_t>(num_robots), 0);
}

bool FormationProgress::Merge(const std::vector<uint8_t>& payload) {
  agents::ByteReader reader(payload);
  if (reader.Int32() != static_cast<int32_t>(states_.size()) || !reader.ok()) return false;
  // Decode everything before touching states_: a bad tail must not leave a half merge.
  scratch_.resize(states_.size());
  for (int& value : scratch_) {
    value = reader.Int32();
    if (!reader.ok() || value < 0 || value > num_formations_) return false;
  }
  if (!reader.done()) return false;
  for (size_t i = 0; i < states_.size(); ++i) states_[i] = std::max(states_[i], scratch_[i]);
  return true;
}

void FormationProgress::Set(int robot_id, int state) {
  if (robot_id < 0 || robot_id >= static_cast<int>(states_.size())) {
    throw std::out_of_range("robot id " + std::to_string(robot_id) + " out of range");
  }
  if (state < 0 || state > num_formations_) throw std::out_of_range("state " + std::to_string(state) + " out of range");
  states_[static_cast<size_t>(robot_id)] = state;
}

int FormationProgress::MinState() const { return *std::min_element(states_.begin(), states_.end()); }

std::vector<uint8_t> FormationProgress::Encode() const {
  agents::ByteWriter writer;
  writer.Int32(static_cast<int32_t>(states_.size()));
  for (int value : states_) writer.Int32(value);
  return writer.Take();
}

}  // namespace dream::hrvo_circle
