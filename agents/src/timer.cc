#include "dream/agents/framework/timer.h"

#include <stdexcept>

namespace dream::agents {

Timer::Timer(int64_t start_delay_steps, std::vector<int> periods_steps)
    : start_delay_steps_(start_delay_steps),
      periods_steps_(std::move(periods_steps)),
      last_run_step_(periods_steps_.size(), 0),
      due_(periods_steps_.size(), false) {
  if (start_delay_steps_ < 0) {
    throw std::invalid_argument("start_delay_steps must be >= 0, got " + std::to_string(start_delay_steps_));
  }
  for (size_t i = 0; i < periods_steps_.size(); ++i) {
    if (periods_steps_[i] < 1) {
      throw std::invalid_argument("period of component " + std::to_string(i) + " must be >= 1 step, got " +
                                  std::to_string(periods_steps_[i]));
    }
  }
}

const std::vector<bool>& Timer::Tick(int64_t step) {
  for (size_t i = 0; i < periods_steps_.size(); ++i) {
    due_[i] = step > start_delay_steps_ && step - last_run_step_[i] >= periods_steps_[i];
    if (due_[i]) last_run_step_[i] = step;
  }
  return due_;
}

}  // namespace dream::agents
