#include "dream/lcm/world_follower.h"

#include <spdlog/spdlog.h>

#include "dream/lcm/run_id.h"

namespace dream::lcm {

void WorldFollower::NoteOtherRun(int64_t run_id) {
  if (other_runs_.size() >= kMaxOtherRuns || !other_runs_.insert(run_id).second) return;
  spdlog::error(
      "another world (run {}) publishes on this LCM URL while this process follows run {}: two "
      "simulators (or a stale one) share the URL. Its messages are ignored; stop it or give each run its own URL",
      RunIdText(run_id), RunIdText(run_id_));
}

WorldFollower::StepDecision WorldFollower::OnPoses(int64_t run_id, int64_t step) {
  if (run_id == 0 || step < 0) {
    ++steps_out_of_sequence_;
    return StepDecision::kIgnore;
  }
  if (!joined()) {
    run_id_ = run_id;
    step_ = step;
    return StepDecision::kNewStep;
  }
  if (run_id != run_id_) {
    NoteOtherRun(run_id);
    return StepDecision::kIgnore;
  }
  if (step == step_) return StepDecision::kResend;
  if (step == step_ - 1) return StepDecision::kIgnore;  // the world resent it before our answer reached it
  const bool short_gap = step > step_ && step - step_ <= kMaxStepGap;
  const bool confirmed = unconfirmed_step_ && step == *unconfirmed_step_ + 1;
  if (short_gap || confirmed) {
    if (confirmed && !short_gap) {
      spdlog::warn("run {}: the world moved from step {} to step {}; following it", RunIdText(run_id_), step_, step);
    }
    step_ = step;
    unconfirmed_step_.reset();
    return StepDecision::kNewStep;
  }
  unconfirmed_step_ = step;
  ++steps_out_of_sequence_;
  if (steps_out_of_sequence_ == 1 || steps_out_of_sequence_ % 100 == 0) {
    spdlog::warn("DREAM_POSES: ignored step {} of run {} while at step {} ({} out of sequence so far)", step,
                 RunIdText(run_id_), step_, steps_out_of_sequence_);
  }
  return StepDecision::kIgnore;
}

bool WorldFollower::InRun(int64_t run_id) {
  if (!joined()) return false;
  if (run_id == run_id_) return true;
  NoteOtherRun(run_id);
  return false;
}

bool WorldFollower::EndsRun(int64_t run_id, int64_t step) { return InRun(run_id) && step >= step_; }

}  // namespace dream::lcm
