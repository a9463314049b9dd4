// A seeded mutation driver: real encoded messages and a small run log,
// mutated a few thousand times in a fixed order, through every decoder and
// every log reader. Nothing may crash, allocate more than the bytes justify,
// or fail other than with a clean error. (The same seeds give the same
// mutations on every machine, so a failure here can be replayed.)
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <random>
#include <stdexcept>

#include "allocation_watch.h"
#include "dream/bridge/run_track.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/log_reader.h"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/node/run_recorder.h"
#include "dream/render/run_geometry.h"
#include "dream/run_log/run_log.h"
#include "dream/velocity_command_t.hpp"
#include "fuzz_scale.h"
#include "sample_messages.h"

namespace dream::testing {
namespace {

constexpr uint32_t kSeed = 20261123;
// Counts for CI; DREAM_FUZZ_SCALE multiplies both (fuzz_scale.h).
constexpr int kMutationsPerMessage = 5000;  // x 11 types, each through 11 decoders
constexpr int kLogMutations = 3000;         // each through LogReader, RunLog and its views
// A decoded message may hold what its bytes hold; the rest is bookkeeping.
constexpr size_t kAllocationSlackBytes = 64 * 1024;

/// Byte-level mutations a fuzzer would make, with counts an attacker picks.
class Mutator {
 public:
  explicit Mutator(uint32_t seed) : random_(seed) {}

  std::vector<uint8_t> Mutate(std::vector<uint8_t> bytes) {
    const int rounds = Below(3) + 1;
    for (int i = 0; i < rounds; ++i) MutateOnce(&bytes);
    return bytes;
  }

 private:
  int Below(size_t n) { return n == 0 ? 0 : static_cast<int>(random_() % n); }

  void MutateOnce(std::vector<uint8_t>* bytes) {
    static const uint32_t kInteresting[] = {0x10000000, 0xFFFFFFFF, 0x7FFFFFFF, 0x80000000,
                                            0x06666667, 0x00000000, 0x00000033, 0x00010001};
    const size_t size = bytes->size();
    const auto at = static_cast<size_t>(Below(size));
    switch (Below(7)) {
      case 0:
        if (size > 0) (*bytes)[at] ^= static_cast<uint8_t>(1u << Below(8));
        break;
      case 1:
        if (size > 0) (*bytes)[at] = static_cast<uint8_t>(random_());
        break;
      case 2:
        if (size >= 4) {
          const size_t word = static_cast<size_t>(Below(size - 3));
          const uint32_t value = kInteresting[Below(std::size(kInteresting))];
          for (size_t i = 0; i < 4; ++i) (*bytes)[word + i] = static_cast<uint8_t>(value >> (24 - 8 * i));
        }
        break;
      case 3:
        bytes->resize(at);
        break;
      case 4: {
        std::vector<uint8_t> inserted(static_cast<size_t>(Below(16) + 1));
        for (uint8_t& byte : inserted) byte = static_cast<uint8_t>(random_());
        bytes->insert(bytes->begin() + static_cast<std::ptrdiff_t>(at), inserted.begin(), inserted.end());
        break;
      }
      case 5: {
        const size_t count = std::min(size - at, static_cast<size_t>(Below(32) + 1));
        bytes->erase(bytes->begin() + static_cast<std::ptrdiff_t>(at),
                     bytes->begin() + static_cast<std::ptrdiff_t>(at + count));
        break;
      }
      default: {
        const size_t count = std::min(size - at, static_cast<size_t>(Below(64) + 1));
        const std::vector<uint8_t> chunk(bytes->begin() + static_cast<std::ptrdiff_t>(at),
                                         bytes->begin() + static_cast<std::ptrdiff_t>(at + count));
        bytes->insert(bytes->begin() + static_cast<std::ptrdiff_t>(Below(size)), chunk.begin(), chunk.end());
        break;
      }
    }
  }

  std::mt19937 random_;
};

/// A run log as `dream run` records it: per step obstacles, poses, status,
/// then each robot's radio message and command; a fault and FINISHED at the end.
std::vector<uint8_t> SmallRunLog(const std::string& path) {
  node::RunRecorder recorder(path);
  const auto write = [&recorder](const std::string& channel, int64_t utime, const std::vector<uint8_t>& bytes) {
    recorder.Write(channel, utime, bytes.data(), static_cast<int>(bytes.size()));
  };
  constexpr int kRobots = 3;
  for (int64_t step = 0; step < 12; ++step) {
    const int64_t utime = step * 33000;
    obstacles_t obstacles{};
    obstacles.utime = utime;
    obstacles.step = step;
    obstacles.num_obstacles = 1;
    obstacles.obstacles.resize(1);
    obstacles.obstacles[0].width = obstacles.obstacles[0].height = 0.2;
    write(lcm::kObstaclesChannel, utime, Encoded(obstacles));
    robot_poses_t poses{};
    poses.utime = utime;
    poses.step = step;
    poses.num_robots = kRobots;
    poses.x = {-0.5 + 0.01 * static_cast<double>(step), 0.0, 0.5};
    poses.y = {0.0, 0.3, -0.3};
    poses.theta = poses.v = poses.w = std::vector<double>(kRobots, 0.0);
    write(lcm::kPosesChannel, utime, Encoded(poses));
    run_status_t status{};
    status.utime = utime;
    status.step = step;
    status.state = run_status_t::RUNNING;
    status.num_robots = kRobots;
    status.detail = "running";
    write(lcm::kStatusChannel, utime, Encoded(status));
    for (int id = 0; id < kRobots; ++id) {
      radio_message_t radio{};
      radio.step = step;
      radio.sender_id = id;
      radio.agent_id = 100 + id;
      radio.payload = {1, 2, 3, 4, 5, 6, 7, 8};
      radio.payload_size = 8;
      write(lcm::RadioChannel(id), utime, Encoded(radio));
      velocity_command_t command{};
      command.step = step;
      command.robot_id = id;
      command.agent_id = 100 + id;
      command.v = 0.1;
      write(lcm::CommandChannel(id), utime, Encoded(command));
    }
  }
  robot_fault_t fault{};
  fault.step = 11;
  fault.robot_id = 2;
  fault.agent_id = 102;
  fault.detail = "controller failed";
  write(std::string(lcm::kFaultChannelPrefix) + "2", 11 * 33000, Encoded(fault));
  run_status_t finished{};
  finished.step = 11;
  finished.state = run_status_t::FINISHED;
  finished.num_robots = kRobots;
  finished.num_lost = 1;
  finished.lost_robot_ids = {2};
  finished.detail = "finished";
  write(lcm::kStatusChannel, 11 * 33000, Encoded(finished));
  recorder.Close();
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs `read`; true when it returned, false when it failed with a clean
/// error. Out-of-memory style failures are test failures: they mean a size
/// was trusted.
template <typename Read>
bool ReadsCleanly(Read read, const std::string& what) {
  try {
    read();
    return true;
  } catch (const std::bad_alloc& e) {
    ADD_FAILURE() << what << ": bad_alloc: " << e.what();
  } catch (const std::length_error& e) {
    ADD_FAILURE() << what << ": length_error: " << e.what();
  } catch (const std::exception& e) {
    return false;
  }
  return false;
}

class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "dream_mutation_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

TEST(MutationDriver, MutatedMessagesAreDecodedOrRefusedByEveryDecoder) {
  Mutator mutator(kSeed);
  long decoded = 0;
  long refused = 0;
  const long mutations_per_message = kMutationsPerMessage * FuzzScale();
  for (const EncodedMessage& sample : SampleMessages()) {
    for (long i = 0; i < mutations_per_message; ++i) {
      const std::vector<uint8_t> mutated = mutator.Mutate(sample.bytes);
      for (const auto& [type, decode] : Decoders()) {
        const AllocationWatch watch;
        (decode(mutated.data(), static_cast<int>(mutated.size())) ? decoded : refused) += 1;
        ASSERT_LE(watch.largest(), mutated.size() + kAllocationSlackBytes)
            << sample.type << " mutation " << i << " as " << type;
      }
    }
  }
  // Most mutations break a message; some (a flipped coordinate bit) do not.
  EXPECT_GT(refused, decoded);
  EXPECT_GT(decoded, 0);
  RecordProperty("decodes", std::to_string(decoded + refused));
}

TEST(MutationDriver, MutatedRunLogsAreReadOrRefusedWithFileAndByte) {
  const TempFolder folder;
  const std::vector<uint8_t> original = SmallRunLog(folder.file("run.lcmlog"));
  // The unmutated log reads everywhere, so the mutations below reach deep.
  const run_log::RunLog whole = run_log::RunLog::Read(folder.file("run.lcmlog"));
  ASSERT_EQ(whole.Flaw(true), std::nullopt);
  bridge::RunEnd end;
  ASSERT_EQ(bridge::RunTrackOf(whole, &end).last_step(), 11);
  ASSERT_EQ(end.robot_faults.count(2), 1U);

  Mutator mutator(kSeed + 1);
  const std::string path = folder.file("mutated.lcmlog");
  long refused_by_reader = 0;
  const long log_mutations = kLogMutations * FuzzScale();
  for (long i = 0; i < log_mutations; ++i) {
    const std::vector<uint8_t> mutated = mutator.Mutate(original);
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char*>(mutated.data()), static_cast<std::streamsize>(mutated.size()));
    }
    const std::string what = "log mutation " + std::to_string(i);
    const AllocationWatch watch;
    std::string reader_error;
    const bool read = ReadsCleanly(
        [&] {
          try {
            for (const lcm::LogRecord& record : lcm::LogReader::ReadAll(path)) {
              for (const auto& [type, decode] : Decoders())
                decode(record.data.data(), static_cast<int>(record.data.size()));
            }
          } catch (const std::runtime_error& e) {
            reader_error = e.what();
            throw;
          }
        },
        what + " (LogReader)");
    if (!read) {
      ++refused_by_reader;
      // A damaged log is named with the byte where it goes wrong.
      EXPECT_NE(reader_error.find(path), std::string::npos) << what << ": " << reader_error;
      EXPECT_TRUE(reader_error.find("at byte") != std::string::npos ||
                  reader_error.find("not an LCM log") != std::string::npos)
          << what << ": " << reader_error;
    }
    std::optional<run_log::RunLog> run;
    if (ReadsCleanly([&] { run = run_log::RunLog::Read(path); }, what + " (RunLog)")) {
      ReadsCleanly(
          [&] {
            render::MinimumDistanceSeries(*run);
            render::MovingObstaclePaths(*run);
          },
          what + " (drawing)");
      ReadsCleanly([&] { bridge::RunTrackOf(*run, &end); }, what + " (the bridge's RunTrackOf)");
    }
    ASSERT_LE(watch.largest(), mutated.size() + kAllocationSlackBytes) << what;
  }
  EXPECT_GT(refused_by_reader, 0);
  EXPECT_LT(refused_by_reader, log_mutations);
  RecordProperty("logs", std::to_string(log_mutations));
}

}  // namespace
}  // namespace dream::testing
