#include "dream/node/run_recorder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "dream/applied_commands_t.hpp"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/log_reader.h"
#include "dream/radio_message_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/files/atomic_file.h"
#include "dream/node/refused_record.h"
#include "dream/node/run_judge.h"
#include "dream/node/sim_node.h"
#include "run_with_file_size_limit.h"
#include "quiet_bus.h"
#include "scripted_agent.h"
#include "../support/scratch_folder.h"

namespace dream::node {
namespace {

namespace fs = std::filesystem;

class RunRecorderTest : public ::testing::Test {
 protected:
  dream::testing::ScratchFolder folder_{"dream_recorder"};
  const fs::path dir_ = folder_.path();
};

TEST_F(RunRecorderTest, LogAppearsOnlyWhenClosedAndHoldsEveryEvent) {
  const std::string path = (dir_ / "run.lcmlog").string();
  {
    RunRecorder recorder(path, 2);
    const char data[] = "abc";
    for (int i = 0; i < 5; ++i) recorder.Write("CH", 33000 * i, data, 3);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::exists(path + ".part"));
    recorder.Close();
  }
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));
  const auto records = lcm::LogReader::ReadAll(path);
  ASSERT_EQ(records.size(), 5u);
  EXPECT_EQ(records[4].utime, 4 * 33000);
}

TEST_F(RunRecorderTest, AFolderRemovedAndMadeAgainDuringTheRunKeepsTheNewerRunsLog) {
  // Run A's folder is removed while A runs, made again, and run B records there.
  const fs::path folder = dir_ / "run";
  fs::create_directory(folder);
  const std::string path = (folder / "run.lcmlog").string();
  RunRecorder older(path, 1);
  const char data[] = "abc";
  older.Write("A", 0, data, 3);
  fs::remove_all(folder);
  fs::create_directory(folder);
  RunRecorder newer(path, 1);
  newer.Write("B", 0, data, 3);
  newer.Write("B", 33000, data, 3);
  // Before: A's Close renamed B's .part (by its path) to run.lcmlog while B still wrote it.
  try {
    older.Close();
    FAIL() << "the older run renamed a file it did not write";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is no longer the file this run wrote"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(path + ".part"));
  EXPECT_FALSE(fs::exists(path));
  newer.Close();
  ASSERT_EQ(lcm::LogReader::ReadAll(path).size(), 2u);
  EXPECT_EQ(lcm::LogReader::ReadAll(path)[0].channel, "B");
}

TEST_F(RunRecorderTest, UnwritableFolderIsAClearError) {
  try {
    RunRecorder recorder((dir_ / "missing" / "run.lcmlog").string());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/run.lcmlog"), std::string::npos) << e.what();
  }
}

TEST_F(RunRecorderTest, SimNodeRecordsEveryStepInSimulatedTime) {
  lcm::LcmBus bus("memq://");
  world::UnicycleWorld world(world::WorldParams{}, {{0.0, 0.0, 0.0}, {0.5, 0.5, 1.0}});
  std::vector<std::unique_ptr<testing::ScriptedAgent>> agents;
  for (int id = 0; id < 2; ++id) {
    agents.push_back(
        std::make_unique<testing::ScriptedAgent>(bus, id, 10 + id, [](const robot_poses_t&, velocity_command_t* c) {
          c->v = 0.05;
          return true;
        }));
  }
  const std::string path = (dir_ / "run.lcmlog").string();
  config::SimNodeOptions options;
  options.max_steps = 20;
  options.progress_interval_s = 0;
  {
    RunRecorder recorder(path);
    testing::QuietBus quiet_bus(bus);  // time passes only while the bus is quiet
    SimNode node(quiet_bus, world, &recorder, options);
    node.set_clock(quiet_bus.clock());
    std::atomic<bool> stop{false};
    ASSERT_TRUE(node.Run(stop).ok());
    recorder.Close();
  }
  int64_t expected_step = 0;
  int commands = 0;
  for (const lcm::LogRecord& record : lcm::LogReader::ReadAll(path)) {
    if (record.channel == "DREAM_POSES") {
      robot_poses_t poses;
      ASSERT_EQ(poses.decode(record.data.data(), 0, static_cast<int>(record.data.size())),
                static_cast<int>(record.data.size()));
      EXPECT_EQ(poses.step, expected_step);
      EXPECT_EQ(record.utime, 33000 * expected_step);
      ++expected_step;
    }
    if (record.channel.rfind("DREAM_CMD_", 0) == 0) ++commands;
  }
  EXPECT_EQ(expected_step, 21);  // steps 0..20: the final poses are recorded too
  EXPECT_EQ(commands, 2 * 20);
}

// Issue 23: the world recorded every channel it heard, forged ones included;
// a forged DREAM_APPLIED showed in `dream log echo` as applied, and the run was clean.
TEST_F(RunRecorderTest, RefusedMessagesStayOutOfTheRunLogAndAreKeptApartBounded) {
  lcm::LcmBus bus("memq://");
  world::UnicycleWorld world(world::WorldParams{}, {{0.0, 0.0, 0.0}, {0.5, 0.5, 1.0}});
  constexpr int kMadeUpChannels = 2000;
  const std::vector<uint8_t> junk(8000, 0x5a);
  std::vector<std::unique_ptr<testing::ScriptedAgent>> agents;
  for (int id = 0; id < 2; ++id) {
    agents.push_back(std::make_unique<testing::ScriptedAgent>(
        bus, id, 10 + id, [&, id](const robot_poses_t& poses, velocity_command_t* c) {
          c->v = 0.05;
          if (id != 0) {
            if (poses.step == 2) lcm::Publish(bus, lcm::CommandChannel(1), *c);  // sent twice: kept once
            return true;
          }
          radio_message_t radio{};
          radio.step = poses.step;
          radio.run_id = poses.run_id;
          radio.sender_id = 0;
          radio.agent_id = 10;
          radio.payload = {1, 2, 3};
          radio.payload_size = 3;
          if (poses.step == 2) {
            lcm::Publish(bus, "DREAM_RADIO_0", radio);  // the run's own: kept
            lcm::Publish(bus, "DREAM_RADIO_0", radio);  // a resend of it: not kept twice
          }
          if (poses.step == 4) {  // a flood of the run's own radio: kept up to the per-step limit
            for (uint8_t i = 0; i < 10; ++i) {
              radio.payload = {i};
              radio.payload_size = 1;
              lcm::Publish(bus, "DREAM_RADIO_0", radio);
            }
          }
          if (poses.step != 3) return true;
          applied_commands_t applied{};
          applied.step = poses.step;
          applied.run_id = poses.run_id;
          applied.num_robots = 1;
          applied.applied_agent_id = {666};
          applied.commanded_v = {9.0};
          applied.commanded_w = {0.0};
          applied.conflicts = {0};
          lcm::Publish(bus, lcm::kAppliedChannel, applied);
          lcm::Publish(bus, "DREAM_MEASURED_POSES", poses);
          robot_fault_t fault{};
          fault.run_id = poses.run_id + 1;
          fault.robot_id = 1;
          fault.agent_id = 666;
          fault.detail = "forged";
          lcm::Publish(bus, "DREAM_FAULT_1", fault);
          radio.run_id = poses.run_id + 1;
          lcm::Publish(bus, "DREAM_RADIO_0", radio);  // another run's
          radio.run_id = poses.run_id;
          radio.payload.assign(70000, 1);  // over lcm::MessageLimits: every receiver drops it
          radio.payload_size = 70000;
          lcm::Publish(bus, "DREAM_RADIO_0", radio);
          for (int i = 0; i < kMadeUpChannels; ++i) {
            bus.Publish("MADE_UP_" + std::to_string(i), junk.data(), static_cast<int>(junk.size()));
          }
          return true;
        }));
  }
  const std::string path = (dir_ / "run.lcmlog").string();
  const std::string refused_path = (dir_ / "refused.lcmlog").string();
  config::SimNodeOptions options;
  options.max_steps = 6;
  options.progress_interval_s = 0;
  RunOutcome outcome;
  int64_t run_id = 0;
  {
    RunRecorder recorder(path);
    RefusedRecord refused(refused_path);
    testing::QuietBus quiet_bus(bus);  // time passes only while the bus is quiet
    SimNode node(quiet_bus, world, &recorder, options);
    node.set_clock(quiet_bus.clock());
    node.set_refused_record(&refused);
    run_id = node.run_id();
    std::atomic<bool> stop{false};
    outcome = node.Run(stop);
    recorder.Close();
  }
  ASSERT_TRUE(outcome.ok()) << outcome.reason;
  int applied = 0;
  int radio = 0;
  int commands = 0;
  for (const lcm::LogRecord& record : lcm::LogReader::ReadAll(path)) {
    EXPECT_EQ(record.channel.rfind("MADE_UP_", 0), std::string::npos) << record.channel;
    EXPECT_NE(record.channel, "DREAM_MEASURED_POSES");
    EXPECT_NE(record.channel, "DREAM_FAULT_1");
    if (record.channel == lcm::kAppliedChannel) {
      applied_commands_t message;
      ASSERT_TRUE(lcm::Decode(record.data.data(), static_cast<int>(record.data.size()), &message));
      EXPECT_EQ(message.run_id, run_id);
      EXPECT_EQ(message.num_robots, 2);
      ++applied;
    }
    if (record.channel == "DREAM_RADIO_0") ++radio;
    if (record.channel.rfind("DREAM_CMD_", 0) == 0) ++commands;
  }
  EXPECT_EQ(commands, 2 * 6);  // one per robot and step
  EXPECT_EQ(applied, 6);       // the world's own, one per step
  EXPECT_EQ(radio, 1 + SimNode::kMaxRadioPerRobotPerStep);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_APPLIED"), 1);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_MEASURED_POSES"), 1);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_FAULT_1"), 1);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_RADIO_0"), 2 + 10 - SimNode::kMaxRadioPerRobotPerStep);
  EXPECT_TRUE(outcome.robot_faults.empty());
  // Counted all, named at most RefusedRecord::kMaxChannels, first step kept.
  long counted = 0;
  for (const auto& [channel, seen] : outcome.refused) counted += seen.count;
  EXPECT_EQ(counted, kMadeUpChannels + 5 + 10 - SimNode::kMaxRadioPerRobotPerStep);
  EXPECT_LE(outcome.refused.size(), RefusedRecord::kMaxChannels + 1);
  EXPECT_EQ(outcome.refused.at("DREAM_APPLIED").first_step, 3);
  EXPECT_EQ(outcome.refused.at(RefusedRecord::kOtherChannels).first_step, 3);
  // The refused log keeps the first ones, within its bounds.
  EXPECT_EQ(outcome.refused_log, refused_path);
  const auto refused = lcm::LogReader::ReadAll(refused_path);
  EXPECT_EQ(static_cast<int64_t>(refused.size()), outcome.refused_log_events);
  EXPECT_GT(refused.size(), 4u);
  EXPECT_LE(static_cast<int64_t>(refused.size()), RefusedRecord::kMaxEvents);
  int64_t refused_bytes = 0;
  for (const lcm::LogRecord& record : refused) refused_bytes += static_cast<int64_t>(record.data.size());
  EXPECT_LE(refused_bytes, RefusedRecord::kMaxBytes);
  EXPECT_EQ(refused.front().channel, lcm::kAppliedChannel);
  // The verdict says so, naming channel, count and first step.
  bool said = false;
  for (const world::VerdictReason& reason : OutcomeReasons(outcome)) {
    if (reason.rule != "bad_messages") continue;
    said = true;
    EXPECT_EQ(reason.verdict, world::RunVerdict::kNotReady);
    EXPECT_NE(reason.problem.find("DREAM_APPLIED: 1, the first at step 3"), std::string::npos) << reason.problem;
    EXPECT_NE(reason.find_out.find(refused_path), std::string::npos) << reason.find_out;
  }
  EXPECT_TRUE(said);
}

// Each test event: channel "CH" and 100 bytes of data, 28 bytes of header.
constexpr int kTestDataBytes = 100;
constexpr int64_t kTestEventBytes = 28 + 2 + kTestDataBytes;

std::vector<uint8_t> TestEventData(int index) {
  return std::vector<uint8_t>(kTestDataBytes, static_cast<uint8_t>(index));
}

/// The log at `path` holds exactly events 0..count-1 as the tests write them.
void ExpectTestEvents(const std::string& path, int64_t count) {
  ASSERT_TRUE(fs::exists(path));
  EXPECT_EQ(static_cast<int64_t>(fs::file_size(path)), count * kTestEventBytes);
  const auto records = lcm::LogReader::ReadAll(path);  // throws on a half event
  ASSERT_EQ(static_cast<int64_t>(records.size()), count);
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(records[static_cast<size_t>(i)].utime, 33000 * i);
    EXPECT_EQ(records[static_cast<size_t>(i)].data, TestEventData(i));
  }
}

class RunRecorderWriteFailureTest : public RunRecorderTest, public ::testing::WithParamInterface<int> {};

// The file size limit stops a write in the middle of an event, wherever stdio
// happens to flush (every event, every 7, or when its buffer fills).
TEST_P(RunRecorderWriteFailureTest, CutsTheLogBackToItsLastWholeEventAndKeepsIt) {
  const int flush_interval_events = GetParam();
  const std::string path = (dir_ / "run.lcmlog").string();
  constexpr rlim_t kLimitBytes = 10000;  // not a multiple of kTestEventBytes
  const int64_t whole_events = static_cast<int64_t>(kLimitBytes) / kTestEventBytes;
  const auto report = testing::RunWithFileSizeLimit(kLimitBytes, [&](testing::ChildReport* out) {
    RunRecorder recorder(path, flush_interval_events);
    int i = 0;
    try {
      for (; i < 1000; ++i) recorder.Write("CH", 33000 * i, TestEventData(i).data(), kTestDataBytes);
    } catch (const std::runtime_error& e) {
      (*out)["error"] = e.what();
    }
    (*out)["failed_at_event"] = std::to_string(i);
    (*out)["failed"] = recorder.failed() ? "yes" : "no";
    (*out)["events_written"] = std::to_string(recorder.events_written());
    (*out)["part_size"] = std::to_string(fs::file_size(path + ".part"));
    try {
      recorder.Write("CH", 0, TestEventData(0).data(), kTestDataBytes);
      (*out)["write_after_failure"] = "accepted";
    } catch (const std::runtime_error& e) {
      (*out)["write_after_failure"] = e.what();
    }
    recorder.Close();  // a failure already reported: no second exception
    (*out)["closed"] = "yes";
  });
  ASSERT_EQ(report.count("child_error"), 0u) << report.at("child_error");
  EXPECT_EQ(report.at("failed"), "yes");
  EXPECT_EQ(report.at("closed"), "yes");
  const std::string& error = report.at("error");
  EXPECT_NE(error.find("writing " + path + ".part failed: File too large"), std::string::npos) << error;
  EXPECT_NE(error.find("keeps the " + std::to_string(whole_events) + " whole events"), std::string::npos) << error;
  EXPECT_GE(std::stoll(report.at("failed_at_event")), whole_events);
  EXPECT_EQ(std::stoll(report.at("events_written")), whole_events);
  EXPECT_EQ(std::stoll(report.at("part_size")), whole_events * kTestEventBytes);
  EXPECT_EQ(report.at("write_after_failure"), error);  // refused, nothing written
  EXPECT_FALSE(fs::exists(path + ".part"));
  ExpectTestEvents(path, whole_events);
}

INSTANTIATE_TEST_SUITE_P(FlushIntervals, RunRecorderWriteFailureTest, ::testing::Values(1, 7, 256));

TEST_F(RunRecorderTest, FailureFoundByCloseIsReportedAndTheWholeEventsKept) {
  // Everything fits in stdio's buffer, so the disk refuses it only at Close.
  const std::string path = (dir_ / "run.lcmlog").string();
  constexpr rlim_t kLimitBytes = 1000;
  const auto report = testing::RunWithFileSizeLimit(kLimitBytes, [&](testing::ChildReport* out) {
    RunRecorder recorder(path, 1000);
    for (int i = 0; i < 20; ++i) recorder.Write("CH", 33000 * i, TestEventData(i).data(), kTestDataBytes);
    (*out)["failed_before_close"] = recorder.failed() ? "yes" : "no";
    try {
      recorder.Close();
      (*out)["close"] = "ok";
    } catch (const std::runtime_error& e) {
      (*out)["close"] = e.what();
    }
    (*out)["events_written"] = std::to_string(recorder.events_written());
  });
  ASSERT_EQ(report.count("child_error"), 0u) << report.at("child_error");
  EXPECT_EQ(report.at("failed_before_close"), "no");
  EXPECT_NE(report.at("close").find("File too large"), std::string::npos) << report.at("close");
  const int64_t whole_events = static_cast<int64_t>(kLimitBytes) / kTestEventBytes;
  EXPECT_EQ(std::stoll(report.at("events_written")), whole_events);
  EXPECT_FALSE(fs::exists(path + ".part"));
  ExpectTestEvents(path, whole_events);
}

/// Three robots driving forward, each with its own scripted agent, on `bus`.
std::vector<std::unique_ptr<testing::ScriptedAgent>> ForwardAgents(lcm::LcmInterface& bus) {
  std::vector<std::unique_ptr<testing::ScriptedAgent>> agents;
  for (int id = 0; id < 3; ++id) {
    agents.push_back(
        std::make_unique<testing::ScriptedAgent>(bus, id, 10 + id, [](const robot_poses_t&, velocity_command_t* c) {
          c->v = 0.05;
          return true;
        }));
  }
  return agents;
}

/// Runs a lockstep SimNode recording to `path` under a file size limit; when
/// `big_message_step` >= 0, robot 0's radio sends 60 kB at that step (the
/// run's own message, so it is recorded; a foreign one would be refused).
testing::ChildReport RunSimNodeWithFileSizeLimit(const std::string& path, rlim_t limit_bytes,
                                                 int64_t big_message_step) {
  return testing::RunWithFileSizeLimit(limit_bytes, [&](testing::ChildReport* out) {
    lcm::LcmBus bus("memq://");
    world::UnicycleWorld world(world::WorldParams{}, {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
    lcm::BadMessageLog bad;
    // Subscribed before the agents, so the message is queued before their
    // commands and recorded while the world still waits at that step.
    const lcm::Subscription big_poses = lcm::Subscribe<robot_poses_t>(
        bus, "DREAM_POSES",
        [&](const std::string&, const robot_poses_t& poses) {
          if (poses.step != big_message_step) return;
          radio_message_t radio{};
          radio.step = poses.step;
          radio.run_id = poses.run_id;
          radio.sender_id = 0;
          radio.agent_id = 10;
          radio.payload.assign(60000, 7);
          radio.payload_size = 60000;
          lcm::Publish(bus, "DREAM_RADIO_0", radio);
        },
        bad);
    const auto agents = ForwardAgents(bus);
    config::SimNodeOptions options;
    options.max_steps = 100000;
    options.stop_when_done = false;
    options.progress_interval_s = 0;
    RunRecorder recorder(path);
    testing::QuietBus quiet_bus(bus);  // time passes only while the bus is quiet
    SimNode node(quiet_bus, world, &recorder, options);
    node.set_clock(quiet_bus.clock());
    std::atomic<bool> stop{false};
    const RunOutcome outcome = node.Run(stop);
    recorder.Close();
    (*out)["end"] = EndName(outcome.end);
    (*out)["reason"] = outcome.reason;
    (*out)["steps"] = std::to_string(outcome.steps);
    (*out)["log_events"] = std::to_string(outcome.log_events);
    (*out)["handler_failures"] = std::to_string(outcome.handler_failures);
  });
}

/// The last DREAM_POSES step in the log at `path`, which must read to its end.
int64_t LastLoggedPoseStep(const std::string& path, int64_t expected_events) {
  const auto records = lcm::LogReader::ReadAll(path);
  EXPECT_EQ(static_cast<int64_t>(records.size()), expected_events);
  int64_t last_step = -1;
  for (const lcm::LogRecord& record : records) {
    if (record.channel != "DREAM_POSES") continue;
    robot_poses_t poses;
    EXPECT_EQ(poses.decode(record.data.data(), 0, static_cast<int>(record.data.size())),
              static_cast<int>(record.data.size()));
    last_step = poses.step;
  }
  return last_step;
}

TEST_F(RunRecorderTest, SimNodeEndsTheRunAsFailedWhenItsLogCannotBeWritten) {
  const std::string path = (dir_ / "run.lcmlog").string();
  const auto report = RunSimNodeWithFileSizeLimit(path, 30000, -1);
  ASSERT_EQ(report.count("child_error"), 0u) << report.at("child_error");
  EXPECT_EQ(report.at("end"), "failed");
  const std::string& reason = report.at("reason");
  EXPECT_NE(reason.find("the run log could not be written at step "), std::string::npos) << reason;
  EXPECT_NE(reason.find(path + ".part failed: File too large"), std::string::npos) << reason;
  const int64_t steps = std::stoll(report.at("steps"));
  EXPECT_GT(steps, 10);
  EXPECT_LT(steps, 1000);  // stopped at the failure, not at max_steps
  EXPECT_NE(reason.find("at step " + std::to_string(steps) + ":"), std::string::npos) << reason;
  EXPECT_EQ(report.at("handler_failures"), "0");
  EXPECT_FALSE(fs::exists(path + ".part"));
  // The log reads to its end; it lacks the steps whose events were still in
  // stdio's buffer when the disk refused them, and nothing after the failure.
  const int64_t last_step = LastLoggedPoseStep(path, std::stoll(report.at("log_events")));
  EXPECT_GT(last_step, 0);
  EXPECT_LE(last_step, steps);
  EXPECT_LE(fs::file_size(path), 30000u);
}

// The recorder is the bus's catch-all handler: a failure there must stop the
// run too, not be counted as a handler exception while the run goes on.
TEST_F(RunRecorderTest, WriteFailureInsideAHandlerEndsTheRunAtThatStep) {
  const std::string path = (dir_ / "run.lcmlog").string();
  const auto report = RunSimNodeWithFileSizeLimit(path, 50000, 5);
  ASSERT_EQ(report.count("child_error"), 0u) << report.at("child_error");
  EXPECT_EQ(report.at("end"), "failed");
  EXPECT_EQ(report.at("steps"), "5");
  EXPECT_NE(report.at("reason").find("at step 5: writing " + path + ".part failed: File too large"), std::string::npos)
      << report.at("reason");
  EXPECT_EQ(report.at("handler_failures"), "0");
  EXPECT_EQ(LastLoggedPoseStep(path, std::stoll(report.at("log_events"))), 5);
}

TEST_F(RunRecorderTest, AtomicFileReplacesWholeContent) {
  const std::string path = (dir_ / "summary.json").string();
  files::WriteFileAtomically(path, "first");
  files::WriteFileAtomically(path, "second");
  std::ifstream in(path);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "second");
  EXPECT_THROW(files::WriteFileAtomically((dir_ / "no" / "x.json").string(), "x"), std::runtime_error);
}

}  // namespace
}  // namespace dream::node
