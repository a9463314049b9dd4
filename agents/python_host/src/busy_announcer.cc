#include "dream/python_host/busy_announcer.h"

#include <utility>

namespace dream::python_host {

BusyAnnouncer::BusyAnnouncer(std::vector<int> robot_ids, double agent_timeout_s)
    : robot_ids_(std::move(robot_ids)),
      interval_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(kIntervalFraction * agent_timeout_s))) {}

void BusyAnnouncer::StepArrived(int64_t run_id, int64_t step, Clock::time_point now) {
  if (run_id == run_id_ && step <= step_) return;
  if (run_id != run_id_) answered_.clear();  // answers to another run's steps
  run_id_ = run_id;
  step_ = step;
  next_note_ = now + interval_;
}

void BusyAnnouncer::Answered(int robot_id, int64_t step) {
  int64_t& answered = answered_.try_emplace(robot_id, -1).first->second;
  if (step > answered) answered = step;
}

std::vector<int> BusyAnnouncer::Due(Clock::time_point now, const std::set<int>& failed) {
  std::vector<int> pending;
  if (step_ < 0 || now < next_note_) return pending;
  for (int id : robot_ids_) {
    const auto answered = answered_.find(id);
    const bool has_answered = answered != answered_.end() && answered->second >= step_;
    if (!has_answered && failed.count(id) == 0) pending.push_back(id);
  }
  // Answers and faults are for good: a step with none pending has nothing
  // more to say until the next step.
  next_note_ = pending.empty() ? Clock::time_point::max() : now + interval_;
  return pending;
}

}  // namespace dream::python_host
