#include "dream/workflows/sweep_table.h"

#include <gtest/gtest.h>

#include <sstream>

namespace dream::workflows {
namespace {

using session::ExperimentGoal;

// A summary.json as dream run writes it (the fields the sweep reads).
nlohmann::json Summary(const std::string& kind, long long steps, long long collisions, double min_distance_m,
                       nlohmann::json metrics_extra) {
  nlohmann::json metrics = {{"kind", kind}, {"min_pairwise_distance_m", min_distance_m}};
  metrics.update(metrics_extra);
  return {
      {"end", "finished"},
      {"verdict", collisions > 0 ? "rejected" : "clean"},
      {"steps", steps},
      {"robots", 3},
      {"robots_done", {0, 1, 2}},
      {"violations",
       {{"boundary_errors", 0}, {"collision_errors", collisions}, {"actuator_errors", 2}, {"obstacle_collisions", 0}}},
      {"metrics", metrics}};
}

// metrics.goal as the kind's rule (FormationSequenceMetrics::JudgeGoal) writes it.
nlohmann::json Goal(bool met, long long completion_step, const std::string& detail) {
  return {{"goal", {{"met", met}, {"completion_step", completion_step}, {"detail", detail}}}};
}

nlohmann::json Circle(long long steps, long long completed_step, int completed, long long collisions, double min_m) {
  return Summary(
      "hrvo_circle", steps, collisions, min_m,
      Goal(completed == 3, completed == 3 ? completed_step : -1, std::to_string(completed) + " of 3 formations"));
}

std::vector<SweepPlan::Run> Runs(uint64_t count) {
  std::vector<uint64_t> seeds;
  for (uint64_t seed = 1; seed <= count; ++seed) seeds.push_back(seed);
  return SweepPlan(seeds, {}).runs();
}

/// SweepRunResult::Judge of a summary.json holding `summary` (none: not an object), read as the sweep reads the file.
SweepRunResult JudgeJson(const SweepPlan::Run& run, int exit_code, bool timed_out, double wall_time_s,
                         const nlohmann::json& summary, const std::string& failure_hint) {
  std::optional<node::RunSummary> typed;
  if (summary.is_object()) typed = node::RunSummary::FromJson(nlohmann::ordered_json(summary), "summary.json");
  return SweepRunResult::Judge(run, exit_code, timed_out, wall_time_s, typed, failure_hint);
}

/// SweepRunResult::Judge of `summary` as `run`'s own dream run writes it:
/// with the run's seed, its config's name and a run id of its own.
SweepRunResult JudgeOwn(const SweepPlan::Run& run, int exit_code, bool timed_out, double wall_time_s,
                        nlohmann::json summary, const std::string& failure_hint) {
  if (summary.is_object()) {
    summary["seed"] = run.seed;
    summary["run"] = "demo_" + run.name;
    summary["run_id"] = "00c0ffee" + std::to_string(1000 + run.index);
  }
  return JudgeJson(run, exit_code, timed_out, wall_time_s, summary, failure_hint);
}

// Issue 37: a summary.json of another run (another seed, another run's name,
// no run id, or a run id two runs share) is no result of this run.
TEST(SweepRunResult, ASummaryOfAnotherRunIsAFailedRowNamingWhy) {
  const auto runs = Runs(3);
  nlohmann::json copied = Circle(1990, 1985, 3, 0, 0.21);
  copied["seed"] = 1;
  copied["run"] = "demo_seed1";
  copied["run_id"] = "1234abcd";
  const SweepRunResult other_seed = JudgeJson(runs[1], 0, false, 1.0, copied, "");
  EXPECT_EQ(other_seed.status, SweepRunResult::Status::kFailed);
  EXPECT_FALSE(other_seed.success);
  EXPECT_EQ(other_seed.problem, "summary.json is not this run's: its seed is 1, the run's 2");
  copied["seed"] = 2;
  EXPECT_EQ(JudgeJson(runs[1], 0, false, 1.0, copied, "").problem,
            "summary.json is not this run's: it is run 'demo_seed1's, not seed2's");
  copied["run"] = "demo_seed2";
  copied.erase("run_id");
  EXPECT_EQ(JudgeJson(runs[1], 0, false, 1.0, copied, "").problem, "summary.json names no run_id");
  copied["run_id"] = "1234abcd";
  EXPECT_TRUE(JudgeJson(runs[1], 0, false, 1.0, copied, "").success);

  std::vector<SweepRunResult> results;
  for (const SweepPlan::Run& run : runs)
    results.push_back(JudgeOwn(run, 0, false, 1.0, Circle(1990, 1985, 3, 0, 0.21), ""));
  nlohmann::json twin = Circle(1990, 1985, 3, 0, 0.21);
  twin["seed"] = 3;
  twin["run"] = "demo_seed3";
  twin["run_id"] = results[0].run_id;
  results[2] = JudgeJson(runs[2], 0, false, 1.0, twin, "");
  ASSERT_TRUE(results[2].success);
  SweepRunResult::RefuseSharedRunIds(results);
  EXPECT_TRUE(results[1].success);
  for (size_t copy : {0u, 2u}) {
    EXPECT_EQ(results[copy].status, SweepRunResult::Status::kFailed);
    EXPECT_FALSE(results[copy].success);
    EXPECT_NE(results[copy].problem.find("one is a copy"), std::string::npos) << results[copy].problem;
  }
  EXPECT_NE(results[0].problem.find("of run seed3"), std::string::npos) << results[0].problem;
}

TEST(SweepRunResult, SuccessNeedsAFinishedAcceptedCollisionFreeRunThatMetItsGoal) {
  const auto runs = Runs(5);
  const SweepRunResult good = JudgeOwn(runs[0], 0, false, 1.0, Circle(1990, 1985, 3, 0, 0.21), "");
  EXPECT_TRUE(good.success);
  EXPECT_EQ(good.goal.completion_step, 1985);
  EXPECT_EQ(good.goal.detail, "3 of 3 formations");
  EXPECT_EQ(good.OutcomeText(), "success");

  const SweepRunResult short_run = JudgeOwn(runs[1], 0, false, 1.0, Circle(500, -1, 2, 0, 0.2), "");
  EXPECT_EQ(short_run.status, SweepRunResult::Status::kRan);
  EXPECT_FALSE(short_run.success);
  EXPECT_EQ(short_run.OutcomeText(), "no success (2 of 3 formations)");

  const SweepRunResult crash = JudgeOwn(runs[2], 3, false, 1.0, Circle(1990, 1985, 3, 4, 0.1), "");
  EXPECT_EQ(crash.status, SweepRunResult::Status::kRan);
  EXPECT_FALSE(crash.success);
  EXPECT_EQ(crash.OutcomeText(), "no success (4 collision errors)");

  const SweepRunResult died = JudgeOwn(runs[3], 134, false, 1.0, nullptr, "");
  EXPECT_EQ(died.status, SweepRunResult::Status::kFailed);
  EXPECT_EQ(died.OutcomeText(), "failed to run (killed by signal 6)");

  const SweepRunResult lost = JudgeOwn(runs[3], 4, false, 1.0, nullptr, "agents never answered");
  EXPECT_EQ(lost.OutcomeText(), "failed to run (exit 4: agents never answered)");
  const SweepRunResult slow = JudgeOwn(runs[3], 130, true, 61.0, Circle(90, -1, 0, 0, 0.3), "");
  EXPECT_EQ(slow.status, SweepRunResult::Status::kFailed);
  EXPECT_EQ(slow.OutcomeText(), "failed to run (timed out after 61 s)");
  const SweepRunResult stopped = JudgeOwn(runs[3], 130, false, 1.0, Circle(90, -1, 0, 0, 0.3), "");
  EXPECT_EQ(stopped.status, SweepRunResult::Status::kInterrupted);
  const SweepRunResult unstarted = JudgeOwn(runs[3], -1, false, 0.0, nullptr, "could not start: disk full");
  EXPECT_EQ(unstarted.OutcomeText(), "failed to run (could not start: disk full)");
  const SweepRunResult no_summary = JudgeOwn(runs[3], 0, false, 1.0, nullptr, "");
  EXPECT_EQ(no_summary.status, SweepRunResult::Status::kFailed);
}

TEST(SweepRunResult, AKindWithoutAGoalIsNeverASuccessButSaysNoGoalDeclared) {
  const auto runs = Runs(2);
  const SweepRunResult clean =
      JudgeOwn(runs[0], 0, false, 1.0, Summary("python", 700, 0, 0.3, nlohmann::json::object()), "");
  EXPECT_EQ(clean.status, SweepRunResult::Status::kRan);
  EXPECT_FALSE(clean.goal.has_criterion);
  EXPECT_FALSE(clean.success);
  EXPECT_EQ(clean.OutcomeText(), "no goal declared");
  EXPECT_EQ(clean.ShortOutcomeText(), "no goal declared");
  EXPECT_EQ(clean.goal.detail, "no goal declared");
  const SweepRunResult crash =
      JudgeOwn(runs[1], 3, false, 1.0, Summary("python", 700, 2, 0.1, nlohmann::json::object()), "");
  EXPECT_EQ(crash.OutcomeText(), "no goal declared (2 collision errors)");

  SweepTable table({}, runs.size());
  table.Add(clean);
  table.Add(crash);
  const std::string md = table.Markdown("no goal", {});
  EXPECT_NE(md.find("| success rate | no goal declared"), std::string::npos) << md;
  EXPECT_EQ(md.find("| success |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| success rate | 0 of"), std::string::npos) << md;
}

TEST(ExperimentGoal, TheKindsOwnJudgementIsReadAndKindsWithoutOneHaveOnlyTheCommonCriteria) {
  auto judge = [](const std::string& kind, nlohmann::json metrics) {
    return ExperimentGoal::Judge(node::RunSummary::FromJson(
        nlohmann::ordered_json(Summary(kind, 900, 0, 0.3, std::move(metrics))), "summary.json"));
  };
  const ExperimentGoal line = judge("line_deployment", Goal(true, 700, "line converged"));
  EXPECT_TRUE(line.has_criterion);
  EXPECT_TRUE(line.met);
  EXPECT_EQ(line.completion_step, 700);
  EXPECT_EQ(line.detail, "line converged");
  EXPECT_FALSE(judge("voronoi_coverage", Goal(false, -1, "not settled")).met);
  const ExperimentGoal mine = judge("my_out_of_tree_kind", nlohmann::json::object());
  EXPECT_FALSE(mine.has_criterion);
  EXPECT_TRUE(mine.met);
  EXPECT_EQ(mine.completion_step, 900);  // every robot reported done at the last step
  // Metrics that could not be computed: not met, and says why.
  const ExperimentGoal broken = judge("go_to_goal", {{"error", "run.lcmlog: cannot open"}});
  EXPECT_TRUE(broken.has_criterion);
  EXPECT_FALSE(broken.met);
  EXPECT_EQ(broken.detail, "no metrics: run.lcmlog: cannot open");
  // A summary without metrics: no kind, nothing to judge by but the common criteria.
  EXPECT_FALSE(ExperimentGoal::Judge(node::RunSummary()).has_criterion);
}

TEST(SweepTable, RowsInPlanOrderAndASummaryOfTheFigures) {
  const auto runs = Runs(5);
  SweepTable table({}, runs.size());
  // Added in the order they finish, not the plan's.
  table.Add(JudgeOwn(runs[2], 3, false, 1.0, Circle(2100, 2090, 3, 4, 0.12), ""));
  table.Add(JudgeOwn(runs[0], 0, false, 1.0, Circle(1990, 1985, 3, 0, 0.21), ""));
  table.Add(JudgeOwn(runs[1], 0, false, 1.0, Circle(2000, 1995, 3, 0, 0.19), ""));
  table.Add(JudgeOwn(runs[3], 4, false, 1.0, nullptr, "world lost"));
  ASSERT_EQ(table.results().size(), 4u);
  EXPECT_EQ(table.results()[0].run.seed, 1u);
  EXPECT_EQ(table.results()[3].run.seed, 4u);

  const SweepSummary s = table.Summary();
  EXPECT_EQ(s.planned, 5u);
  EXPECT_EQ(s.listed, 4u);
  EXPECT_EQ(s.ran, 3u);
  EXPECT_EQ(s.failed, 1u);
  EXPECT_EQ(s.succeeded, 2u);
  EXPECT_DOUBLE_EQ(s.success_rate, 0.5);  // 2 of the 4 that ran or failed to run
  EXPECT_EQ(s.completed, 3u);
  EXPECT_DOUBLE_EQ(s.completion_mean, (1985.0 + 1995.0 + 2090.0) / 3.0);
  EXPECT_EQ(s.completion_min, 1985);
  EXPECT_EQ(s.completion_max, 2090);
  EXPECT_DOUBLE_EQ(s.worst_min_distance_m, 0.12);
  EXPECT_EQ(s.worst_min_distance_run, "seed3");
  EXPECT_EQ(s.violations.collision_errors, 4);
  EXPECT_EQ(s.violations.actuator_errors, 6);

  const std::string md = table.SummaryMarkdown({{"command", "dream sweep a|b"}});
  EXPECT_NE(md.find("| command | dream sweep a\\|b |"), std::string::npos) << md;
  EXPECT_NE(md.find("| runs | 4 of 5 planned: 3 ran, 1 failed to run, 0 interrupted |"), std::string::npos) << md;
  EXPECT_NE(md.find("| success rate | 2 of 4 (50.0 %) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| completion step | mean 2023, min 1985, max 2090 (3 runs completed) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| worst min distance | 0.1200 m (seed3) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| violations, all runs | boundary 0, collision 4, actuator 6, obstacle 0 |"), std::string::npos)
      << md;
}

TEST(SweepTable, CsvHasOneQuotedRowPerRunWithParameterColumns) {
  const SweepPlan plan({1}, {config_overrides::SweepParameter::Parse("controller.goals.0=[0.1, 0.2]")});
  SweepTable table(plan.parameter_keys(), 1);
  table.Add(JudgeOwn(plan.runs()[0], 4, false, 2.5, nullptr, "said \"no\", twice"));
  std::istringstream csv(table.Csv());
  std::string header;
  std::string row;
  std::string extra;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_FALSE(std::getline(csv, extra));
  EXPECT_EQ(header.rfind("run,seed,controller.goals.0,status,success,exit_code,end,verdict,steps,completion_step,"
                         "min_distance_m,",
                         0),
            0u)
      << header;
  EXPECT_EQ(row,
            "seed1_goals.0-0.1-0.2,1,\"[0.1, 0.2]\",failed,false,4,,,0,,,0,0,0,0,,,2.50,"
            "\"exit 4: said \"\"no\"\", twice\"");
}

TEST(SweepTable, MarkdownTableHasAHeaderAndOneLinePerRun) {
  const auto runs = Runs(5);
  SweepTable table({}, 2);
  table.Add(JudgeOwn(runs[0], 0, false, 1.0, Circle(1990, 1985, 3, 0, 0.21), ""));
  table.Add(JudgeOwn(runs[1], 0, false, 1.0, Circle(600, -1, 1, 0, 0.2), ""));
  const std::string md = table.Markdown("Sweep of demo", {});
  EXPECT_EQ(md.rfind("# Sweep of demo\n", 0), 0u);
  EXPECT_NE(md.find("| seed1 | 1 | success | 1990 | 1985 | 0.2100 | 0 | 0 | 2 | 0 | 3 of 3 formations |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| seed2 | 2 | no success | 600 | - | 0.2000 | 0 | 0 | 2 | 0 | 1 of 3 formations |"),
            std::string::npos)
      << md;
}

}  // namespace
}  // namespace dream::workflows
