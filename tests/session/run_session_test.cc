// RunSession: one run from its config to its outputs, on a memq bus with the
// agents in this process (as dream run). The controller is the counting
// plugin (counting_plugin.cc), so the test sees how many factories were built.
#include <dlfcn.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dream/agent_host/agent_host.h"
#include "dream/run_config/run_config.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/channels.h"
#include "dream/robot_poses_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/node/log_append.h"
#include "dream/session/experiment_goal.h"
#include "dream/session/verdict_broadcast.h"
#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/session/run_session.h"
#include "../support/scratch_folder.h"
#include "run_session_fixture.h"

namespace dream::session {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST_F(RunSessionTest, AFolderRemovedAndMadeAgainDuringTheRunIsLeftToTheNewerRun) {
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.1, 1.0, 30)), options);
  ASSERT_NE(session.factory(), nullptr) << session.factory_error();
  lcm::LcmBus bus("memq://");
  const std::unique_ptr<agent_host::AgentHost> host = HostAgents(session, bus);
  // At step 5 the folder is removed and made again, and a newer run writes there.
  const lcm::Subscription folder_swapper =
      bus.Subscribe(lcm::kPosesChannel, [this](const std::string&, const void* data, int size) {
        robot_poses_t poses;
        if (poses.decode(data, 0, size) < 0 || poses.step != 5 || fs::exists(out() + "/summary.json")) return;
        fs::remove_all(out());
        fs::create_directories(out());
        std::ofstream(out() + "/run.lcmlog.part") << "the newer run's log";
        std::ofstream(out() + "/summary.json") << "the newer run's summary";
      });
  const RunResult result = session.Run(bus, {out(), "the folder's config\n"});
  EXPECT_EQ(result.outcome.end, node::RunOutcome::End::kFailed);
  EXPECT_THAT(result.outcome.reason, HasSubstr("is no longer the file this run wrote"));
  EXPECT_FALSE(result.summary_written);
  // Before: the older run renamed the newer run's .part and wrote its summary and picture over the newer's.
  EXPECT_EQ(files::ReadFileText(out() + "/run.lcmlog.part"), "the newer run's log");
  EXPECT_EQ(files::ReadFileText(out() + "/summary.json"), "the newer run's summary");
  EXPECT_FALSE(fs::exists(out() + "/run.lcmlog"));
  EXPECT_FALSE(fs::exists(out() + "/trajectories.png"));
}

TEST_F(RunSessionTest, RunWithAgentsStartsTheAgentsOnceAndARefusedRunStartsNone) {
  RunSession::Options options;
  options.report = &report_;
  RunSession refused(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 5)), options);
  ASSERT_NE(refused.factory(), nullptr) << refused.factory_error();
  RunSession::GivenWorld no_world;
  no_world.make = [](node::RunRecorder&) -> std::unique_ptr<world::World> {
    throw std::runtime_error("the lab's poses cannot be read");
  };
  const int made_before = RobotsMade();
  lcm::LcmBus bus("memq://");
  EXPECT_THROW(refused.RunWithAgents(bus, {out(), "the folder's config\n"}, no_world), std::runtime_error);
  EXPECT_EQ(RobotsMade(), made_before) << "agents were started for a run refused before its first step";

  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 5)), options);
  const std::string second_out = (dir_ / "out2").string();
  fs::create_directories(second_out);
  lcm::LcmBus second_bus("memq://");
  const RunResult result = session.RunWithAgents(second_bus, {second_out, "the folder's config\n"});
  EXPECT_EQ(result.outcome.end, node::RunOutcome::End::kFinished) << result.outcome.reason;
  EXPECT_EQ(RobotsMade() - made_before, 2) << "one agent per robot, started once";
  // A session runs once: a second run is refused before any agent starts.
  EXPECT_THROW(session.RunWithAgents(second_bus, {second_out, "the folder's config\n"}), std::logic_error);
  EXPECT_EQ(RobotsMade() - made_before, 2);
}

TEST_F(RunSessionTest, WritesEveryOutputAndBuildsTheFactoryOnce) {
  const int built_before = FactoriesBuilt();
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 30)), options);
  ASSERT_NE(session.factory(), nullptr) << session.factory_error();
  const RunResult result = RunWithAgents(session);

  // One factory for the agents, the metrics and the picture.
  EXPECT_EQ(FactoriesBuilt() - built_before, 1);
  EXPECT_EQ(result.outcome.end, node::RunOutcome::End::kFinished);
  EXPECT_EQ(result.outcome.steps, 30);
  EXPECT_TRUE(result.summary_written);
  EXPECT_FALSE(result.picture_failed);
  EXPECT_EQ(result.judgement.verdict(), world::RunVerdict::kClean);
  EXPECT_EQ(files::ReadFileText(out() + "/config.yaml"), "the folder's config\n");
  EXPECT_GT(fs::file_size(out() + "/run.lcmlog"), 0u);
  EXPECT_GT(fs::file_size(out() + "/trajectories.png"), 0u);
  const nlohmann::json summary = Summary();
  EXPECT_EQ(summary["steps"], 30);
  EXPECT_EQ(summary["verdict"], "clean");
  EXPECT_EQ(summary["metrics"]["kind"], "session_test_drive");
  EXPECT_EQ(summary["goal"]["judged"], false);  // the kind has no goal of its own
  EXPECT_EQ(summary["violations_located"],
            nlohmann::json({{"listed", nlohmann::json::array()}, {"unlisted", 0}, {"max_listed", 100}}));
  EXPECT_THAT(report_.str(), HasSubstr("log:     " + out() + "/run.lcmlog"));
  EXPECT_THAT(report_.str(), HasSubstr("picture: " + out() + "/trajectories.png"));
  // debug()'s "real seconds" are the lab's; the report says what they are and what the run took.
  EXPECT_THAT(report_.str(), HasSubstr("Your simulation took approximately 0.99 real seconds to execute."));
  EXPECT_THAT(report_.str(), HasSubstr("(real seconds on the lab: 30 steps of 0.033 s; this run took "));
  // One session, one run: a second would overwrite the first's folder.
  lcm::LcmBus again("memq://");
  EXPECT_THROW(session.Run(again, {out(), "another config\n"}), std::logic_error);
  EXPECT_EQ(files::ReadFileText(out() + "/config.yaml"), "the folder's config\n");
  // Nothing left half written.
  for (const auto& entry : fs::directory_iterator(out())) {
    EXPECT_EQ(entry.path().extension() == ".part" || entry.path().string().find(".tmp") != std::string::npos, false)
        << entry.path();
  }
}

TEST_F(RunSessionTest, TheReportSaysWhenRealismIsOn) {
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 10, 10.0, ", realism: lab")), options);
  RunWithAgents(session);
  EXPECT_THAT(report_.str(), HasSubstr("\nrealism: lab (not the official simulator's ideal world"));

  std::ostringstream ideal;  // the official world: no such line
  RunSession::Options ideal_options;
  ideal_options.report = &ideal;
  fs::remove_all(out());
  fs::create_directories(out());
  RunSession ideal_session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 10)), ideal_options);
  RunWithAgents(ideal_session);
  EXPECT_THAT(ideal.str(), HasSubstr("log:     "));
  EXPECT_THAT(ideal.str(), ::testing::Not(HasSubstr("realism:")));
}

// A run declared simulation-only says so once in its report and in summary.json,
// so nobody takes it for a lab-ready run; any other run says sim_only: false.
TEST_F(RunSessionTest, TheReportAndSummarySayWhenARunIsSimOnly) {
  const std::string path = WriteConfig(0.0, 1.0, 10);
  std::ostringstream plain_report;
  RunSession::Options plain_options;
  plain_options.report = &plain_report;
  RunSession plain(run_config::LoadRunConfigFile(path), plain_options);
  RunWithAgents(plain);
  EXPECT_THAT(plain_report.str(), ::testing::Not(HasSubstr("sim-only")));
  EXPECT_EQ(Summary()["sim_only"], false);

  std::ofstream(path, std::ios::app) << "sim_only: true\n";
  fs::remove_all(out());
  fs::create_directories(out());
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(path), options);
  RunWithAgents(session);
  EXPECT_EQ(Summary()["sim_only"], true);
  const std::string report = report_.str();
  const std::string line = "\nsim-only run: 2 robots (`sim_only: true` in " + path +
                           "): it never goes to the Robotarium, whatever debug() says above; dream export refuses it\n";
  EXPECT_THAT(report, HasSubstr(line));
  EXPECT_EQ(report.find("sim-only run"), report.rfind("sim-only run")) << report;  // once
}

TEST_F(RunSessionTest, QuietPrintsNoReportForACleanRunAndTheWholeReportOtherwise) {
  RunSession::Options options;
  options.report = &report_;
  options.quiet = true;
  RunSession clean(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 10)), options);
  EXPECT_EQ(RunWithAgents(clean).judgement.verdict(), world::RunVerdict::kClean);
  EXPECT_EQ(report_.str(), "");

  // Robot 0 drives into the right wall: rejected, and -q still says so.
  fs::remove_all(out());
  fs::create_directories(out());
  RunSession rejected(run_config::LoadRunConfigFile(WriteConfig(0.2, 1.5, 60)), options);
  const RunResult result = RunWithAgents(rejected);
  ASSERT_EQ(result.judgement.verdict(), world::RunVerdict::kRejected);
  EXPECT_THAT(report_.str(), HasSubstr(result.judgement.Text()));
}

TEST_F(RunSessionTest, ReasonsFoundAfterTheRunAreAddedByTheSameWriter) {
  // What dream launch does with its agents' reports once the simulator wrote the summary.
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 20)), options);
  ASSERT_EQ(RunWithAgents(session).judgement.verdict(), world::RunVerdict::kClean);
  const nlohmann::json before = Summary();
  const std::string picture_before = files::ReadFileText(out() + "/trajectories.png");

  // Nothing refused: the section is added, the verdict and picture stay.
  EXPECT_EQ(session.Reporter().AddReasons(out(), "agents", {{"bad_messages", nlohmann::json::object()}}, {}),
            world::RunVerdict::kClean);
  EXPECT_EQ(Summary()["verdict"], "clean");
  EXPECT_EQ(Summary()["agents"]["bad_messages"], nlohmann::json::object());
  EXPECT_EQ(files::ReadFileText(out() + "/trajectories.png"), picture_before);

  const world::VerdictReason refused{"agent_bad_messages", world::RunVerdict::kNotReady, "the agents refused 2",
                                     "summary.json agents"};
  EXPECT_EQ(session.Reporter().AddReasons(out(), "agents", {{"bad_messages", {{"DREAM_POSES", 2}}}}, {refused}),
            world::RunVerdict::kNotReady);
  const nlohmann::json after = Summary();
  EXPECT_EQ(after["verdict"], "not_ready");
  EXPECT_EQ(after["verdict_reasons"].back()["rule"], "agent_bad_messages");
  EXPECT_EQ(after["verdict_reasons"].back()["verdict"], "not_ready");
  EXPECT_EQ(after["agents"]["bad_messages"]["DREAM_POSES"], 2);
  // Everything else as the run wrote it, and the picture says the new verdict.
  for (const auto& [key, value] : before.items()) {
    if (key != "verdict" && key != "verdict_reasons") {
      EXPECT_EQ(after[key], value) << key;
    }
  }
  EXPECT_NE(files::ReadFileText(out() + "/trajectories.png"), picture_before);

  // A summary that holds no verdict, or one that is none of the four, is named, not guessed at.
  files::WriteFileAtomically(out() + "/summary.json", R"({"verdict_reasons": []})");
  try {
    session.Reporter().AddReasons(out(), "agents", {}, {refused});
    ADD_FAILURE() << "a summary without a verdict was amended";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(out() + "/summary.json: has no verdict"));
  }
  files::WriteFileAtomically(out() + "/summary.json", R"({"verdict": "fine", "verdict_reasons": []})");
  try {
    session.Reporter().AddReasons(out(), "agents", {}, {refused});
    ADD_FAILURE() << "a summary with an unknown verdict was amended";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(out() + "/summary.json: verdict: expected one of clean, warning, not_ready, "
                                            "rejected, got \"fine\""));
  }
}

TEST_F(RunSessionTest, ARobotLeavingTheArenaIsRejectedAndCountedAsTheLabsVerifierWould) {
  RunSession::Options options;
  options.report = &report_;
  // Robot 0 starts 0.1 m from the right wall and drives into it.
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.2, 1.5, 60)), options);
  const RunResult result = RunWithAgents(session);
  EXPECT_EQ(result.outcome.end, node::RunOutcome::End::kFinished);
  EXPECT_EQ(result.judgement.verdict(), world::RunVerdict::kRejected);
  EXPECT_TRUE(result.judgement.Has("boundary")) << result.judgement.Text();
  const nlohmann::json summary = Summary();
  EXPECT_EQ(summary["verdict"], "rejected");
  EXPECT_THAT(report_.str(), HasSubstr(result.judgement.Text()));
  // Where and when: one entry, robot 0 outside from the first step the world
  // counted to the last (each of those steps one boundary error).
  const nlohmann::json& located = summary["violations_located"];
  ASSERT_EQ(located["listed"].size(), 1u) << located.dump();
  const nlohmann::json& entry = located["listed"][0];
  EXPECT_EQ(entry["kind"], "boundary");
  EXPECT_EQ(entry["robots"], nlohmann::json::array({0}));
  const int64_t first = entry["first_step"].get<int64_t>();
  const int64_t last = entry["last_step"].get<int64_t>();
  EXPECT_GT(first, 0);
  EXPECT_EQ(last - first + 1, summary["violations"]["boundary_errors"].get<int64_t>());
  EXPECT_GT(entry["position"][0].get<double>(), 1.6);  // just past the right wall
  EXPECT_NEAR(entry["position"][1].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(located["unlisted"], 0);
}

TEST_F(RunSessionTest, ARunWithoutAgentsFailsWithASummaryAndNoPicture) {
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 30, 0.2)), options);
  lcm::LcmBus bus("memq://");
  const RunResult result = session.Run(bus, {out(), "x\n"});
  EXPECT_EQ(result.outcome.end, node::RunOutcome::End::kStartTimeout);
  EXPECT_EQ(result.outcome.steps, 0);
  EXPECT_TRUE(result.summary_written);
  EXPECT_FALSE(result.picture_failed);  // none was due
  EXPECT_FALSE(fs::exists(out() + "/trajectories.png"));
  EXPECT_TRUE(fs::exists(out() + "/run.lcmlog"));
  EXPECT_EQ(Summary()["steps"], 0);
}

TEST_F(RunSessionTest, ASummaryThatCannotBeWrittenIsReportedAndNothingElseIsClaimed) {
  // A folder where summary.json should go: the rename onto it fails.
  fs::create_directories(fs::path(out()) / "summary.json" / "occupied");
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 10)), options);
  const RunResult result = RunWithAgents(session);
  EXPECT_EQ(result.outcome.end, node::RunOutcome::End::kFinished);
  EXPECT_FALSE(result.summary_written);
  EXPECT_EQ(report_.str(), "");  // no verdict, no paths: the outputs are incomplete
  EXPECT_FALSE(fs::exists(out() + "/trajectories.png"));
}

TEST_F(RunSessionTest, AStopRequestEndsTheRunAsInterruptedWithItsOutputs) {
  const std::atomic<bool> stop(true);
  RunSession::Options options;
  options.report = &report_;
  options.stop = &stop;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 30)), options);
  const RunResult result = RunWithAgents(session);
  EXPECT_EQ(result.outcome.end, node::RunOutcome::End::kInterrupted);
  EXPECT_TRUE(result.summary_written);
  EXPECT_EQ(Summary()["end"], "interrupted");
}

TEST_F(RunSessionTest, AFactoryThatCannotBeBuiltIsRememberedNotThrown) {
  const std::string path = WriteConfig(0.0, 1.0, 10);
  std::ofstream(path, std::ios::app) << "# the kind below is unknown\n";
  std::string text = files::ReadFileText(path);
  text.replace(text.find("session_test_drive"), std::string("session_test_drive").size(), "no_such_kind");
  std::ofstream(path, std::ios::trunc) << text;
  const RunSession session(run_config::LoadRunConfigFile(path));
  EXPECT_EQ(session.factory(), nullptr);
  EXPECT_THAT(session.factory_error(), HasSubstr("no_such_kind"));
}

}  // namespace
}  // namespace dream::session
