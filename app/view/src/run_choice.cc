#include "dream/view/run_choice.h"

#include <algorithm>
#include <utility>

#include "dream/run_status_t.hpp"

namespace dream::view {

static_assert(RunChoice::kOtherWorldShown < RunChoice::kSilence);

namespace {

bool Ended(int state) { return state == run_status_t::FINISHED || state == run_status_t::ABORTED; }

}  // namespace

RunChoice::RunChoice(std::function<Clock::time_point()> now) : now_(std::move(now)) {}

RunChoice::RunHeard& RunChoice::Heard(int64_t run_id, Clock::time_point now) {
  const auto is_it = [run_id](const RunHeard& r) { return r.run_id == run_id; };
  auto run = std::find_if(heard_.begin(), heard_.end(), is_it);
  if (run == heard_.end()) {
    if (heard_.size() < kMaxRunsHeard) {
      run = heard_.emplace(heard_.end());
    } else {
      // The least recently heard run but the followed one makes room.
      run = heard_.end();
      for (auto r = heard_.begin(); r != heard_.end(); ++r) {
        if (r->run_id != follower_.run_id() && (run == heard_.end() || r->order < run->order)) run = r;
      }
      *run = RunHeard{};
    }
    run->run_id = run_id;
    run->first = now;
  }
  run->last = now;
  run->order = ++messages_;
  if (follower_.joined() && run_id == follower_.run_id()) followed_heard_ = now;
  return *run;
}

std::optional<RunChoice::Clock::time_point> RunChoice::OverSince(Clock::time_point now) const {
  if (ended_) return ended_at_;
  if (now - followed_heard_ >= kSilence) return followed_heard_;
  return std::nullopt;
}

bool RunChoice::StartsCleanly(const RunHeard& run, int64_t step, Clock::time_point now) const {
  // A world publishes a step's status just before its poses (and both again
  // while it waits): poses alone, however many, are no world's.
  if (run.status_step != step) return false;
  if (!follower_.joined()) return true;  // nothing drawn yet: any step (a view started mid-run)
  const bool runs_on = run.poses_step >= 0 && step == run.poses_step + 1;
  const std::optional<Clock::time_point> over = OverSince(now);
  // A world waiting at its step 0 (for agents that may never come) gives
  // way to one that runs.
  if (!over) return follower_.step() == 0 && runs_on;
  // Once the followed run is over: a world started after that, at its step
  // 0, or one that waited at step 0 beside it and now runs.
  return (step == 0 && run.first > *over) || (step == 1 && runs_on);
}

RunChoice::Decision RunChoice::OnPoses(int64_t run_id, int64_t step) {
  if (run_id == 0 || step < 0) return Decision::kIgnore;  // no run's (WorldFollower ignores them too)
  const Clock::time_point now = now_();
  if (follower_.joined() && run_id == follower_.run_id()) {
    Heard(run_id, now).poses_step = step;
    const int64_t drawn = follower_.step();
    switch (follower_.OnPoses(run_id, step)) {
      case lcm::WorldFollower::StepDecision::kIgnore:
        return Decision::kIgnore;
      case lcm::WorldFollower::StepDecision::kResend:
        return Decision::kResend;
      case lcm::WorldFollower::StepDecision::kNewStep:
        break;
    }
    if (step >= drawn) return Decision::kNewStep;
    ended_ = false;  // a confirmed step back: the run from its start again (its log played once more)
    return Decision::kStartOver;
  }
  RunHeard& run = Heard(run_id, now);
  const bool clean = run_id == chosen_ || StartsCleanly(run, step, now);
  run.poses_step = step;
  if (!clean) {
    if (follower_.joined()) follower_.OnPoses(run_id, step);  // ignored, and the other world logged once
    return Decision::kIgnore;
  }
  follower_ = lcm::WorldFollower();
  follower_.OnPoses(run_id, step);
  chosen_ = 0;
  ended_ = false;
  followed_heard_ = now;
  return Decision::kStartOver;
}

bool RunChoice::OnStatus(int64_t run_id, int64_t step, int state) {
  if (run_id == 0) return false;
  const Clock::time_point now = now_();
  RunHeard& run = Heard(run_id, now);
  run.status_step = step;
  run.state = state;
  if (!follower_.InRun(run_id)) return false;
  if (Ended(state) && !ended_ && follower_.EndsRun(run_id, step)) {
    ended_ = true;
    ended_at_ = now;
  }
  return true;
}

bool RunChoice::Choose(int64_t run_id) {
  const auto is_it = [run_id](const RunHeard& r) { return r.run_id == run_id; };
  const bool heard = std::any_of(heard_.begin(), heard_.end(), is_it);
  if (!heard || run_id == 0 || (follower_.joined() && run_id == follower_.run_id())) return false;
  chosen_ = run_id;
  return true;
}

bool RunChoice::OnMessageOf(int64_t run_id) {
  if (run_id == 0) return false;
  Heard(run_id, now_());
  return follower_.InRun(run_id);
}

std::optional<ViewFrame::OtherWorld> RunChoice::OtherWorldHeard() const {
  if (!follower_.joined()) return std::nullopt;  // nothing drawn: no second world to speak of
  const Clock::time_point now = now_();
  const RunHeard* latest = nullptr;
  int runs = 0;
  for (const RunHeard& run : heard_) {
    if (run.run_id == follower_.run_id() || now - run.last > kOtherWorldShown || Ended(run.state)) continue;
    ++runs;
    if (latest == nullptr || run.order > latest->order) latest = &run;
  }
  if (latest == nullptr) return std::nullopt;
  return ViewFrame::OtherWorld{latest->run_id, std::max(latest->poses_step, latest->status_step), latest->state, runs};
}

}  // namespace dream::view
