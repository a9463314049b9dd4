#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace dream {
class robot_commands_t;
class velocity_command_t;
}  // namespace dream

namespace dream::lcm {

/// A DREAM_CMDS message (robot_commands_t: every robot's command of a step
/// from one agent) read once, the same way by the world and by `dream view`:
/// either the whole message is refused (problem()), or its entries are the
/// velocity_command_t each stands for on DREAM_CMD_<robot_id[i]>. Whether an
/// entry's robot, run and step are right is the reader's own check, as for
/// that DREAM_CMD_<id>.
class CommandBatch {
 public:
  /// `commands` must outlive the batch; `num_robots` is the run's robot count.
  /// Checks only the counts before it looks at the entries, so a message whose
  /// arrays or count lie costs nothing to refuse.
  CommandBatch(const robot_commands_t& commands, int num_robots);

  /// Why the whole message is refused (its arrays not of num_commands entries,
  /// a negative count, more entries than the run has robots, a robot listed
  /// twice), or nothing.
  const std::optional<std::string>& problem() const { return problem_; }

  /// The entries: 0 when the message is refused.
  size_t size() const { return size_; }

  /// Entry `i` (< size()) as the DREAM_CMD_<id> it stands for: utime, step,
  /// run_id and agent_id the message's.
  velocity_command_t Entry(size_t i) const;

 private:
  static std::optional<std::string> ProblemOf(const robot_commands_t& commands, int num_robots);

  const robot_commands_t& commands_;
  std::optional<std::string> problem_;
  size_t size_ = 0;
};

}  // namespace dream::lcm
