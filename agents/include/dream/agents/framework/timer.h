#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dream::agents {

/// The thesis's Timer, without its global list: when each of a robot's parts
/// runs, in steps of 0.033 s. Nothing runs while step <= start_delay_steps;
/// after that a component with period p runs on every step where at least p
/// steps have passed since it last ran (counting from step 0).
class Timer {
 public:
  /// @param periods_steps one period per component, each >= 1.
  /// @throws std::invalid_argument naming the component otherwise.
  Timer(int64_t start_delay_steps, std::vector<int> periods_steps);

  /// Which components run at `step` (in component order); call once per step
  /// with increasing steps.
  const std::vector<bool>& Tick(int64_t step);

 private:
  int64_t start_delay_steps_;
  std::vector<int> periods_steps_;
  std::vector<int64_t> last_run_step_;
  std::vector<bool> due_;
};

}  // namespace dream::agents
