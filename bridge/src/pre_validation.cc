#include "dream/bridge/pre_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "dream/run_status_t.hpp"
#include "dream/world/violation_checker.h"

namespace dream::bridge {
namespace {

std::string Num(double value, int digits = 3) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

// One problem per robot or pair, at the first step it happened; at most ten
// of a kind, as the rest are summarised.
template <typename Key, typename MakeProblem>
void ListFirstSteps(const std::map<Key, int64_t>& first_steps, std::vector<ExportProblem>* problems,
                    MakeProblem make_problem) {
  const size_t kMaxListed = 10;
  size_t listed = 0;
  for (const auto& [key, step] : first_steps) {
    if (listed++ == kMaxListed) break;
    problems->push_back(make_problem(key, step));
  }
}

}  // namespace

std::string ExportProblem::Text() const {
  std::string where;
  if (robot >= 0) where += (rule == "obstacle" || other < 0 ? "robot " : "robots ") + std::to_string(robot);
  if (robot >= 0 && other >= 0) where += (rule == "obstacle" ? " and obstacle " : " and ") + std::to_string(other);
  if (step >= 0) where += (where.empty() ? "" : ", ") + std::string("step ") + std::to_string(step);
  return rule + ": " + (where.empty() ? "" : where + ": ") + problem + ". Fix: " + fix;
}

world::LabVerifierRules::Counts VerifierCounts(const RunTrack& track, const world::WorldParams& world) {
  world::LabVerifierRules::Counts counts;
  counts.num_robots = track.num_robots;
  counts.iterations = std::max<int64_t>(track.last_step(), 0);
  if (track.num_robots < 1) return counts;
  world::ViolationChecker checker(world, track.num_robots);
  std::vector<world::Pose2> poses(static_cast<size_t>(track.num_robots));
  for (int64_t k = 0; k < track.last_step(); ++k) {
    for (int i = 0; i < track.num_robots; ++i) poses[static_cast<size_t>(i)] = track.pose(k, i);
    checker.Check(k, poses, nullptr, track.obstacles[static_cast<size_t>(k)]);
    counts.robots_too_close += static_cast<int64_t>(checker.last_step_events().colliding_pairs.size());
    counts.robots_outside_boundaries += static_cast<int64_t>(checker.last_step_events().out_of_bounds_robot_ids.size());
  }
  return counts;
}

world::LabVerifierRules::Counts VerifierCounts(const run_log::RunLog& log, const world::WorldParams& world) {
  return VerifierCounts(RunTrackOf(log), world);
}

namespace {

/// The lab's limits (robots, duration) and the verifier's rules on what the script will do.
void AddLabLimitProblems(const RunTrack& track, const world::WorldParams& world, int64_t steps,
                         int64_t settle_max_steps, const LabLimits& limits,
                         const std::optional<world::LabVerifierRules::Declaration>& declared,
                         std::vector<ExportProblem>* problems) {
  const int n = track.num_robots;
  if (n < 1 || n > limits.max_robots) {
    problems->push_back(
        {"robots", -1, -1, -1,
         "the run has " + std::to_string(n) + " robots; the Robotarium runs 1 to " + std::to_string(limits.max_robots),
         "set `robots:` to at most " + std::to_string(limits.max_robots) + " in the config and run again"});
  }
  const int64_t iterations = steps + settle_max_steps;
  const double duration_s = static_cast<double>(iterations) * world.time_step_s;
  if (duration_s > limits.max_duration_s) {
    const auto max_steps =
        static_cast<int64_t>(std::floor(limits.max_duration_s / world.time_step_s)) - settle_max_steps;
    problems->push_back({"duration", -1, -1, -1,
                         std::to_string(steps) + " steps + " + std::to_string(settle_max_steps) +
                             " settle steps take " + Num(duration_s, 1) + " s on the lab, over its cap of " +
                             Num(limits.max_duration_s, 0) + " s (iterations x " + Num(world.time_step_s) + " s)",
                         "run at most " + std::to_string(std::max<int64_t>(max_steps, 0)) +
                             " steps (`steps:` in the config, or dream run --steps), or export with fewer "
                             "--settle-steps"});
  }
  // The lab verifier's rules, on what the script will do: ask for the
  // recorded robots and run at most `iterations` steps.
  {
    world::LabVerifierRules rules;
    rules.time_step_s = world.time_step_s;
    rules.max_duration_s = limits.max_duration_s;
    world::LabVerifierRules::Counts counts = VerifierCounts(track, world);
    counts.iterations = iterations;
    const world::LabVerifierRules::Declaration declaration =
        declared.value_or(world::LabVerifierRules::Declaration{n, duration_s});
    for (const world::VerdictReason& reason : rules.Check(declaration, counts)) {
      if (reason.rule == "lab_duration_cap" && duration_s > limits.max_duration_s) continue;  // `duration` says it
      problems->push_back({reason.rule, -1, -1, -1, reason.problem, reason.find_out});
    }
  }
}

/// How the run ended: not finished, robots lost at its end.
void AddEndProblems(const RunTrack& track, const RunEnd& end, std::vector<ExportProblem>* problems) {
  if (!end.seen || end.state != run_status_t::FINISHED) {
    problems->push_back({"finished", -1, -1, track.last_step(),
                         "the run did not finish (" +
                             (end.seen ? end.detail : std::string("no DREAM_STATUS in the log")) +
                             "); its recording stops early",
                         "run the experiment to its end and export that run"});
  }
  for (int id : end.lost_robot_ids) {
    const auto fault = end.robot_faults.find(id);
    if (fault != end.robot_faults.end()) {
      problems->push_back({"lost_robot", id, -1, -1, "its controller failed at " + fault->second,
                           "fix the controller and run again (summary.json robot_faults has the error)"});
    } else {
      problems->push_back({"lost_robot", id, -1, -1,
                           "was lost at the end of the run: its agent fell silent, so the world stopped it",
                           "run again with every robot's agent running to the end"});
    }
  }
}

/// Start poses: inside the arena with the whole robot, far enough apart.
void AddStartPoseProblems(const RunTrack& track, const world::WorldParams& world, const LabLimits& limits,
                          std::vector<ExportProblem>* problems) {
  const int n = track.num_robots;
  const world::Arena& arena = world.arena;
  const double margin = limits.start_wall_margin_m;
  for (int i = 0; i < n; ++i) {
    const world::Pose2& p = track.pose(0, i);
    if (p.x_m < arena.x_min_m + margin || p.x_m > arena.x_max_m - margin || p.y_m < arena.y_min_m + margin ||
        p.y_m > arena.y_max_m - margin) {
      problems->push_back({"start_inside_arena", i, -1, 0,
                           "starts at (" + Num(p.x_m) + ", " + Num(p.y_m) + "), closer than " + Num(margin) +
                               " m to the arena's edge (x in [" + Num(arena.x_min_m, 1) + ", " + Num(arena.x_max_m, 1) +
                               "], y in [" + Num(arena.y_min_m, 1) + ", " + Num(arena.y_max_m, 1) +
                               "]): the lab cannot place the robot there",
                           "move robot " + std::to_string(i) + "'s start pose (initial_poses) at least " + Num(margin) +
                               " m inside the arena"});
    }
  }
  const double d = limits.start_projection_m;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const world::Pose2& a = track.pose(0, i);
      const world::Pose2& b = track.pose(0, j);
      const double gap = std::hypot(a.x_m + d * std::cos(a.theta_rad) - b.x_m - d * std::cos(b.theta_rad),
                                    a.y_m + d * std::sin(a.theta_rad) - b.y_m - d * std::sin(b.theta_rad));
      if (gap < limits.start_spacing_m) {
        problems->push_back(
            {"start_spacing", i, j, 0,
             "start poses are " + Num(gap) + " m apart (measured " + Num(d, 2) +
                 " m ahead of each robot); the lab's start-up routine cannot bring robots closer than " +
                 Num(limits.start_spacing_m, 2) + " m, so the run would likely be rejected",
             "spread the start poses (initial_poses) to at least " + Num(limits.start_spacing_m, 2) + " m apart"});
      }
    }
  }
}

/// Hard errors on the recorded poses: the first step of each kind, per robot or pair.
void AddRecordedViolations(const RunTrack& track, const RunEnd& end, const world::WorldParams& world,
                           std::vector<ExportProblem>* problems) {
  const int n = track.num_robots;
  if (n >= 1) {
    world::ViolationChecker checker(world, n);
    std::vector<world::Pose2> poses(static_cast<size_t>(n));
    std::map<int, int64_t> out_of_bounds;  // robot -> first step
    std::map<std::pair<int, int>, int64_t> collisions;
    std::map<std::pair<int, int>, int64_t> contacts;
    for (int64_t k = 0; k <= track.last_step(); ++k) {
      for (int i = 0; i < n; ++i) poses[static_cast<size_t>(i)] = track.pose(k, i);
      checker.Check(k, poses, nullptr, track.obstacles[static_cast<size_t>(k)]);
      const world::StepEvents& events = checker.last_step_events();
      for (int id : events.out_of_bounds_robot_ids) out_of_bounds.emplace(id, k);
      for (const auto& pair : events.colliding_pairs)
        collisions.emplace(std::make_pair(pair.first_robot_id, pair.second_robot_id), k);
      for (const auto& contact : events.obstacle_contacts)
        contacts.emplace(std::make_pair(contact.robot_id, contact.obstacle_id), k);
    }
    ListFirstSteps(out_of_bounds, problems, [&](int robot, int64_t step) -> ExportProblem {
      const world::Pose2& p = track.pose(step, robot);
      return {"boundary",
              robot,
              -1,
              step,
              "is outside the arena at (" + Num(p.x_m) + ", " + Num(p.y_m) +
                  "): the Robotarium rejects runs with boundary errors",
              "keep the controller's targets inside the arena (or enable its wall check) and run again"};
    });
    ListFirstSteps(collisions, problems, [&](const std::pair<int, int>& pair, int64_t step) -> ExportProblem {
      return {"collision",
              pair.first,
              pair.second,
              step,
              "are closer than " + Num(world.collision_diameter_m) +
                  " m (collision): the Robotarium rejects runs with collisions",
              "make the controller keep robots apart (e.g. HRVO with a larger safety radius) and run again"};
    });
    ListFirstSteps(contacts, problems, [](const std::pair<int, int>& pair, int64_t step) -> ExportProblem {
      return {"obstacle",
              pair.first,
              pair.second,
              step,
              "touches the virtual obstacle, which stands for a real one",
              "make the controller avoid the obstacle (obstacle sensor, buffer) and run again"};
    });
    const int64_t hard = end.violations.hard_errors();
    if (hard > 0 && out_of_bounds.empty() && collisions.empty() && contacts.empty()) {
      problems->push_back(
          {"violations", -1, -1, end.step,
           "the run's status reports " + std::to_string(hard) + " hard errors that its recorded poses do not show",
           "run the experiment again and export the new run"});
    }
  }
}

}  // namespace

std::vector<ExportProblem> PreValidate(const RunTrack& track, const RunEnd& end, const world::WorldParams& world,
                                       int64_t settle_max_steps, const LabLimits& limits, int64_t experiment_steps,
                                       const std::optional<world::LabVerifierRules::Declaration>& declared) {
  std::vector<ExportProblem> problems;
  const int64_t steps = experiment_steps < 0 ? track.last_step() : experiment_steps;
  AddLabLimitProblems(track, world, steps, settle_max_steps, limits, declared, &problems);
  AddEndProblems(track, end, &problems);
  AddStartPoseProblems(track, world, limits, &problems);
  AddRecordedViolations(track, end, world, &problems);
  return problems;
}

std::vector<std::string> StartUpWarnings(const RunTrack& track, const LabLimits& limits) {
  std::vector<std::string> warnings;
  if (track.last_step() < 0) return warnings;
  int crowded_robot = -1;
  int most = 0;
  for (int i = 0; i < track.num_robots; ++i) {
    int neighbours = 0;
    for (int j = 0; j < track.num_robots; ++j) {
      if (j != i && std::hypot(track.pose(0, i).x_m - track.pose(0, j).x_m,
                               track.pose(0, i).y_m - track.pose(0, j).y_m) < limits.crowd_radius_m) {
        ++neighbours;
      }
    }
    if (neighbours > most) {
      most = neighbours;
      crowded_robot = i;
    }
  }
  if (most >= limits.crowd_neighbours) {
    warnings.push_back("start poses are crowded (robot " + std::to_string(crowded_robot) + " has " +
                       std::to_string(most) + " others within " + Num(limits.crowd_radius_m, 2) +
                       " m): the lab's start-up routine may deadlock before step 0 and the lab would then "
                       "reject the run; try it with dream check-submission in the official simulator, or "
                       "spread the start poses");
  }
  return warnings;
}

}  // namespace dream::bridge
