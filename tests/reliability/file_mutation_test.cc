// A seeded mutation driver over the files of the lab loop, through the real
// readers: result files (.npy and every .mat flavour) through the import's
// ReadResultFile + ParseLabResult, the export's dream_params.npy through
// ExportedSubmission::Read, and a real run.lcmlog through LogReader and the
// run's one reader, RunLog, then what uses it (the bridge's RunTrackOf, the
// experiment metrics). Each must read the file or refuse it with a runtime_error naming
// it; nothing may crash, throw bad_alloc / length_error, or make one
// allocation far beyond the file. DREAM_FUZZ_SCALE=N multiplies the counts.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <new>
#include <optional>

#include "allocation_watch.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/bridge/lab_import.h"
#include "dream/bridge/metrics_json.h"
#include "dream/bridge/run_track.h"
#include "dream/bridge/submission_format.h"
#include "dream/lcm/log_reader.h"
#include "dream/run_log/run_log.h"
#include "file_mutator.h"
#include "fuzz_scale.h"
#include "lab_file_samples.h"

namespace dream::testing {
namespace {

namespace fs = std::filesystem;

constexpr uint32_t kSeed = 20261124;
// Counts for CI (each test a few seconds on 2 cores; not asserted, tests are not timed);
// DREAM_FUZZ_SCALE multiplies them.
constexpr long kResultMutations = 1500;  // per result format (npy, mat v4, v5, v5 compressed)
constexpr long kHdf5Mutations = 300;     // mat v7.3: HDF5 opens are slower
constexpr long kParamsMutations = 1500;
constexpr long kLogMutations = 300;  // the run log is 100 KB, read by LogReader and RunLog
// Readers may hold the file and a decoded copy; libraries keep some buffers.
constexpr size_t kAllocationSlackBytes = 4 << 20;

enum class Outcome { kRead, kRefused };

/// Runs `read` on `path`: kRead, or kRefused for a runtime_error that names
/// the file. Anything else fails the test.
template <typename Read>
Outcome ReadOrRefuse(Read read, const std::string& path, const std::string& what) {
  try {
    read();
    return Outcome::kRead;
  } catch (const std::bad_alloc& e) {
    ADD_FAILURE() << what << ": bad_alloc: " << e.what();
  } catch (const std::length_error& e) {
    ADD_FAILURE() << what << ": length_error: " << e.what();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << what << ": does not name the file: " << e.what();
    return Outcome::kRefused;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": " << e.what();
  }
  return Outcome::kRefused;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(FileMutationDriver, MutatedResultFilesAreImportedOrRefusedByName) {
  const LabFileSamples& samples = SharedLabFileSamples();
  const auto start = std::chrono::steady_clock::now();
  FileMutator mutator(kSeed);
  for (const LabFileSamples::Sample& sample : samples.results()) {
    const long count = (sample.name == "mat_v73" ? kHdf5Mutations : kResultMutations) * FuzzScale();
    const std::string path = samples.Scratch("mutated_" + sample.name + (sample.name == "npy" ? ".npy" : ".mat"));
    long read = 0;
    const auto format_start = std::chrono::steady_clock::now();
    for (long i = 0; i < count; ++i) {
      const std::string mutated = mutator.Mutate(sample.bytes);
      WriteBytes(path, mutated);
      const AllocationWatch watch;
      const Outcome outcome = ReadOrRefuse(
          [&] {
            const bridge::ExportedSubmission& exported = samples.exported();
            bridge::ParseLabResult(bridge::ReadResultFile(path, exported.MaxResultValues()), path, exported);
          },
          path, sample.name + " mutation " + std::to_string(i));
      if (outcome == Outcome::kRead) ++read;
      ASSERT_LE(watch.largest(), 4 * mutated.size() + kAllocationSlackBytes) << sample.name << " mutation " << i;
    }
    // Most damage is refused; a flipped bit in a pose value is not damage a reader can see.
    EXPECT_LT(read, count) << sample.name;
    std::printf("%s: %ld mutations, %ld imported, %ld refused (%.1f s)\n", sample.name.c_str(), count, read,
                count - read, SecondsSince(format_start));
    RecordProperty(sample.name, std::to_string(count));
  }
  RecordProperty("seconds", std::to_string(SecondsSince(start)));
}

TEST(FileMutationDriver, MutatedParamsFilesAreReadOrRefusedByName) {
  const LabFileSamples& samples = SharedLabFileSamples();
  const auto start = std::chrono::steady_clock::now();
  const std::string copy = samples.Scratch("mutated_export");
  fs::copy(samples.export_dir(), copy, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  // Without the export's digests, so each damaged file reaches the .npy
  // reader (the digest check alone refuses every one).
  WriteBytes(copy + "/export.json", "{}");
  const std::string params = copy + "/upload/" + bridge::SubmissionFiles::kParams;
  FileMutator mutator(kSeed + 1);
  const long count = kParamsMutations * FuzzScale();
  long read = 0;
  for (long i = 0; i < count; ++i) {
    const std::string mutated = mutator.Mutate(samples.params().bytes);
    WriteBytes(params, mutated);
    const AllocationWatch watch;
    if (ReadOrRefuse([&] { bridge::ExportedSubmission::Read(copy); }, params, "params mutation " + std::to_string(i)) ==
        Outcome::kRead) {
      ++read;
    }
    ASSERT_LE(watch.largest(), 4 * mutated.size() + kAllocationSlackBytes) << "params mutation " << i;
  }
  EXPECT_LT(read, count);
  std::printf("dream_params.npy: %ld mutations, %ld read, %ld refused\n", count, read, count - read);
  RecordProperty("seconds", std::to_string(SecondsSince(start)));
}

TEST(FileMutationDriver, MutatedRunLogsAreReadOrRefusedByEveryLogReader) {
  const LabFileSamples& samples = SharedLabFileSamples();
  const auto start = std::chrono::steady_clock::now();
  const std::string original = ReadBytes(samples.run_log());
  const run_config::RunConfig& config = samples.exported().config;
  const agent_host::ControllerFactory factory(config);
  ASSERT_FALSE(bridge::MetricsJson(factory, run_log::RunLog::Read(samples.run_log())).contains("error"));
  const std::string path = samples.Scratch("mutated.lcmlog");
  FileMutator mutator(kSeed + 2);
  const long count = kLogMutations * FuzzScale();
  long refused_by_reader = 0;
  for (long i = 0; i < count; ++i) {
    const std::string mutated = mutator.Mutate(original);
    WriteBytes(path, mutated);
    const std::string what = "log mutation " + std::to_string(i);
    const AllocationWatch watch;
    std::string reader_error;
    const Outcome by_reader = ReadOrRefuse(
        [&] {
          try {
            lcm::LogReader reader(path);
            lcm::LogRecord record;
            while (reader.Next(&record)) {
            }
          } catch (const std::runtime_error& e) {
            reader_error = e.what();
            throw;
          }
        },
        path, what + " (LogReader)");
    if (by_reader == Outcome::kRefused) {
      ++refused_by_reader;
      EXPECT_TRUE(reader_error.find("at byte ") != std::string::npos ||
                  reader_error.find("not an LCM log") != std::string::npos)
          << what << ": " << reader_error;
    }
    std::optional<run_log::RunLog> run;
    if (ReadOrRefuse([&] { run = run_log::RunLog::Read(path); }, path, what + " (RunLog)") == Outcome::kRead) {
      ReadOrRefuse([&] { bridge::RunTrackOf(*run); }, path, what + " (the bridge's RunTrackOf)");
      ReadOrRefuse([&] { bridge::MetricsJson(factory, *run); }, path, what + " (metrics)");
    }
    ASSERT_LE(watch.largest(), 4 * mutated.size() + kAllocationSlackBytes) << what;
  }
  EXPECT_GT(refused_by_reader, 0);
  std::printf("run.lcmlog: %ld mutations, %ld refused by LogReader\n", count, refused_by_reader);
  RecordProperty("seconds", std::to_string(SecondsSince(start)));
}

}  // namespace
}  // namespace dream::testing
