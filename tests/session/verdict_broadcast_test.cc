// VerdictBroadcast: the one judge's verdict on DREAM_VERDICT once summary.json
// is written, the run log's last event; published and logged again when
// summary.json changed after it (dream launch's agents' reports); and the log
// writes it goes through (node::AppendLogEvent, node::ReplaceLastLogEvent).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "../support/scratch_folder.h"
#include "dream/files/file_text.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/node/log_append.h"
#include "dream/run_config/run_config.h"
#include "dream/run_verdict_t.hpp"
#include "dream/session/experiment_goal.h"
#include "dream/session/verdict_broadcast.h"
#include "run_session_fixture.h"

namespace dream::session {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// Issue 33: after summary.json is written, the world says the one judge's
// verdict on DREAM_VERDICT, once, and the run's log keeps it as its last event.
TEST_F(RunSessionTest, TheVerdictIsPublishedOnceAfterTheSummaryAndEndsTheLog) {
  RunSession::Options options;
  options.report = &report_;
  // Robot 0 drives into the right wall: rejected (exit code 3).
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.2, 1.5, 60)), options);
  ASSERT_NE(session.factory(), nullptr) << session.factory_error();
  lcm::LcmBus bus("memq://");
  const std::unique_ptr<agent_host::AgentHost> host = HostAgents(session, bus);
  std::vector<run_verdict_t> heard;
  bool summary_there_when_heard = false;
  const lcm::Subscription listener =
      bus.Subscribe(lcm::kVerdictChannel, [&](const std::string&, const void* data, int size) {
        run_verdict_t verdict;
        ASSERT_TRUE(lcm::Decode(data, size, &verdict));
        heard.push_back(verdict);
        summary_there_when_heard = fs::exists(out() + "/summary.json");
      });
  const RunResult result = session.Run(bus, {out(), "the folder's config\n"});
  while (bus.HandleSubscriptions(0) > 0) {
  }  // what is still queued on the memq bus
  ASSERT_EQ(result.judgement.verdict(), world::RunVerdict::kRejected);

  ASSERT_EQ(heard.size(), 1u);
  EXPECT_TRUE(summary_there_when_heard);
  const nlohmann::json summary = Summary();
  const run_verdict_t& verdict = heard[0];
  EXPECT_EQ(lcm::RunIdText(verdict.run_id), summary["run_id"].get<std::string>());
  EXPECT_EQ(verdict.step, summary["steps"].get<int64_t>());
  EXPECT_EQ(verdict.verdict, run_verdict_t::REJECTED);
  EXPECT_EQ(summary["verdict"], "rejected");
  EXPECT_EQ(verdict.exit_code, 3);
  EXPECT_EQ(verdict.goal_text, ExperimentGoal::Text(summary["goal"]));
  for (const auto& reason : summary["verdict_reasons"]) {
    EXPECT_THAT(verdict.reasons, HasSubstr(reason["rule"].get<std::string>() + ": "));
  }

  // The log: every event the recorder wrote, then the verdict's bytes as published;
  // summary.json's log_events counts them all.
  const std::vector<lcm::LogRecord> events = lcm::LogReader::ReadAll(out() + "/run.lcmlog");
  ASSERT_EQ(static_cast<int64_t>(events.size()), summary["log_events"].get<int64_t>());
  EXPECT_EQ(events.back().channel, lcm::kVerdictChannel);
  run_verdict_t logged;
  ASSERT_TRUE(lcm::Decode(events.back().data.data(), static_cast<int>(events.back().data.size()), &logged));
  EXPECT_EQ(logged.run_id, verdict.run_id);
  EXPECT_EQ(logged.reasons, verdict.reasons);
  EXPECT_EQ(events.back().utime, verdict.utime);
  for (size_t i = 0; i + 1 < events.size(); ++i) EXPECT_NE(events[i].channel, lcm::kVerdictChannel);
}

// The DREAM_VERDICT events of a log.
std::vector<run_verdict_t> VerdictsIn(const std::string& log_path) {
  std::vector<run_verdict_t> verdicts;
  for (const lcm::LogRecord& event : lcm::LogReader::ReadAll(log_path)) {
    if (event.channel != lcm::kVerdictChannel) continue;
    EXPECT_TRUE(lcm::Decode(event.data.data(), static_cast<int>(event.data.size()), &verdicts.emplace_back()));
  }
  return verdicts;
}

// dream launch: its agents' reports made the verdict worse after the world published and
// logged it; the bus hears summary.json's verdict again and the log's last event becomes it,
// so a viewer, live or of the log, ends on it.
TEST_F(RunSessionTest, AVerdictMadeWorseAfterTheRunIsPublishedAgainAndReplacesTheLogs) {
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.0, 1.0, 20)), options);
  ASSERT_EQ(RunWithAgents(session).judgement.verdict(), world::RunVerdict::kClean);
  const std::string log = out() + "/run.lcmlog";
  const size_t events_before = lcm::LogReader::ReadAll(log).size();
  const world::VerdictReason refused{"agent_bad_messages", world::RunVerdict::kNotReady, "the agents refused 2",
                                     "summary.json agents"};
  ASSERT_EQ(session.Reporter().AddReasons(out(), "agents", {{"bad_messages", {{"DREAM_POSES", 2}}}}, {refused}),
            world::RunVerdict::kNotReady);
  lcm::LcmBus bus("memq://");
  std::vector<run_verdict_t> heard;
  const lcm::Subscription listener =
      bus.Subscribe(lcm::kVerdictChannel, [&](const std::string&, const void* data, int size) {
        run_verdict_t verdict;
        ASSERT_TRUE(lcm::Decode(data, size, &verdict));
        heard.push_back(verdict);
      });
  const std::optional<run_verdict_t> changed =
      VerdictBroadcast::RewriteLoggedVerdict(out() + "/summary.json", 0.033, kExitNotReady, log);
  ASSERT_TRUE(changed.has_value());
  EXPECT_TRUE(heard.empty());  // the caller publishes
  VerdictBroadcast::Publish(bus, *changed);
  while (bus.HandleSubscriptions(0) > 0) {
  }
  ASSERT_EQ(heard.size(), 1u);
  const nlohmann::json summary = Summary();
  EXPECT_EQ(lcm::RunIdText(heard[0].run_id), summary["run_id"].get<std::string>());
  EXPECT_EQ(heard[0].verdict, run_verdict_t::NOT_READY);
  EXPECT_EQ(heard[0].exit_code, kExitNotReady);
  EXPECT_EQ(heard[0].utime, 20 * 33000);
  EXPECT_THAT(heard[0].reasons, HasSubstr("agent_bad_messages: the agents refused 2"));
  EXPECT_EQ(heard[0].goal_text, ExperimentGoal::Text(summary["goal"]));

  // The log: as many events as summary.json counts, one verdict, the last, the one published.
  const std::vector<lcm::LogRecord> events = lcm::LogReader::ReadAll(log);
  EXPECT_EQ(events.size(), events_before);
  EXPECT_EQ(static_cast<int64_t>(events.size()), summary["log_events"].get<int64_t>());
  EXPECT_EQ(events.back().channel, lcm::kVerdictChannel);
  const std::vector<run_verdict_t> logged = VerdictsIn(log);
  ASSERT_EQ(logged.size(), 1u);
  EXPECT_EQ(logged[0].verdict, run_verdict_t::NOT_READY);
  EXPECT_EQ(logged[0].exit_code, kExitNotReady);
  EXPECT_EQ(logged[0].reasons, heard[0].reasons);

  // Asked again with nothing changed: neither the log nor the bus hears it twice.
  const std::string bytes = files::ReadFileText(log);
  EXPECT_FALSE(VerdictBroadcast::RewriteLoggedVerdict(out() + "/summary.json", 0.033, kExitNotReady, log));
  EXPECT_EQ(files::ReadFileText(log), bytes);
  EXPECT_THROW(VerdictBroadcast::RewriteLoggedVerdict(out() + "/none.json", 0.033, kExitNotReady, log),
               std::runtime_error);
}

// A launch whose agents refused nothing: the log's verdict is summary.json's already and stays.
TEST_F(RunSessionTest, AVerdictSummaryJsonStillSaysIsNeitherLoggedNorPublishedAgain) {
  RunSession::Options options;
  options.report = &report_;
  RunSession session(run_config::LoadRunConfigFile(WriteConfig(0.2, 1.5, 60)), options);  // rejected
  const RunResult result = RunWithAgents(session);
  ASSERT_EQ(result.judgement.verdict(), world::RunVerdict::kRejected);
  const std::string log = out() + "/run.lcmlog";
  const std::string bytes = files::ReadFileText(log);
  EXPECT_FALSE(VerdictBroadcast::RewriteLoggedVerdict(out() + "/summary.json", 0.033, kExitRejected, log));
  EXPECT_EQ(files::ReadFileText(log), bytes);
  // Another exit code than the world's (the launch's): the log says the launch's.
  const std::optional<run_verdict_t> changed =
      VerdictBroadcast::RewriteLoggedVerdict(out() + "/summary.json", 0.033, kExitRunFailed, log);
  ASSERT_TRUE(changed.has_value());
  EXPECT_EQ(changed->exit_code, kExitRunFailed);
  const std::vector<run_verdict_t> logged = VerdictsIn(log);
  ASSERT_EQ(logged.size(), 1u);
  EXPECT_EQ(logged[0].exit_code, kExitRunFailed);
  EXPECT_EQ(logged[0].verdict, run_verdict_t::REJECTED);
}

TEST(LogAppend, AnEventGoesOnlyToALogThatExistsAndIsAFile) {
  dream::testing::ScratchFolder folder("dream_log_append_test");
  const std::string missing = (folder.path() / "run.lcmlog").string();
  const uint8_t bytes[3] = {1, 2, 3};
  EXPECT_THROW(node::AppendLogEvent(missing, 0, lcm::kVerdictChannel, 0, bytes, 3), std::runtime_error);
  EXPECT_FALSE(fs::exists(missing));  // never made
  fs::create_directories(folder.path() / "a_folder");
  EXPECT_THROW(node::AppendLogEvent((folder.path() / "a_folder").string(), 0, lcm::kVerdictChannel, 0, bytes, 3),
               std::runtime_error);
  { std::ofstream(missing) << ""; }
  node::AppendLogEvent(missing, 0, lcm::kVerdictChannel, 42, bytes, 3);
  node::AppendLogEvent(missing, 1, lcm::kVerdictChannel, 43, bytes, 2);
  const std::vector<lcm::LogRecord> events = lcm::LogReader::ReadAll(missing);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].utime, 42);
  EXPECT_EQ(events[1].data, (std::vector<uint8_t>{1, 2}));
}

TEST(LogAppend, OnlyALogEndingOnTheChannelHasItsLastEventReplaced) {
  dream::testing::ScratchFolder folder("dream_log_replace_test");
  const std::string log = (folder.path() / "run.lcmlog").string();
  const uint8_t bytes[3] = {1, 2, 3};
  EXPECT_THROW(node::ReplaceLastLogEvent(log, lcm::kVerdictChannel, 0, bytes, 3), std::runtime_error);  // none
  { std::ofstream(log) << ""; }
  node::AppendLogEvent(log, 0, lcm::kStatusChannel, 40, bytes, 3);
  node::AppendLogEvent(log, 1, lcm::kVerdictChannel, 42, bytes, 3);
  node::ReplaceLastLogEvent(log, lcm::kVerdictChannel, 43, bytes, 1);
  std::vector<lcm::LogRecord> events = lcm::LogReader::ReadAll(log);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].channel, lcm::kStatusChannel);
  EXPECT_EQ(events[1].channel, lcm::kVerdictChannel);
  EXPECT_EQ(events[1].utime, 43);
  EXPECT_EQ(events[1].data, (std::vector<uint8_t>{1}));
  // A log that ends on another channel is refused by name and left as it was.
  node::AppendLogEvent(log, 2, lcm::kStatusChannel, 44, bytes, 2);
  const std::string before = files::ReadFileText(log);
  try {
    node::ReplaceLastLogEvent(log, lcm::kVerdictChannel, 45, bytes, 3);
    ADD_FAILURE() << "a log ending on DREAM_STATUS had its last event replaced";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(log + ": its last event is on DREAM_STATUS"));
  }
  EXPECT_EQ(files::ReadFileText(log), before);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()), 1);  // no temporary left
}

}  // namespace
}  // namespace dream::session
