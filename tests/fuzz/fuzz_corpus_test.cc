// Replays tests/fuzz/corpus through the fuzz targets in every build: the
// inputs coverage-guided fuzzing found (each once crashed a reader or made
// libmatio ask for gigabytes) and a sound sample of each kind, plus the
// shipped configs. A target aborts on a finding, failing this test; under
// the sanitizer build (CI) an allocation over 512 MB is a finding too.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_targets.h"
#include "../support/source_tree.h"

// Read by AddressSanitizer when it is linked in (the asan preset): libmatio's
// mallocs go through it, so a forged header asking for gigabytes stops the test.
extern "C" const char* __asan_default_options() { return "max_allocation_size_mb=512"; }

namespace dream::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The files of `folder`, in name order.
std::vector<fs::path> FilesOf(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Runs `target` on every file of corpus/<name>; returns how many.
size_t Replay(const std::string& name, void (*target)(const uint8_t*, size_t)) {
  const std::vector<fs::path> files = FilesOf(fs::path(dream::testing::SourceDir()) / "tests/fuzz/corpus" / name);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::vector<uint8_t> bytes = ReadBytes(file);
    target(bytes.data(), bytes.size());
  }
  return files.size();
}

TEST(FuzzCorpusTest, RunLogs) { EXPECT_GE(Replay("run_log", RunLogTarget), 3u); }

TEST(FuzzCorpusTest, LabResults) { EXPECT_GE(Replay("lab_result", LabResultTarget), 5u); }

TEST(FuzzCorpusTest, LabRows) { EXPECT_GE(Replay("lab_rows", LabRowsTarget), 2u); }

TEST(FuzzCorpusTest, LcmMessages) { EXPECT_GE(Replay("lcm_message", LcmMessageTarget), 4u); }

TEST(FuzzCorpusTest, RunConfigsAndTheShippedOnes) {
  EXPECT_GE(Replay("run_config", RunConfigTarget), 1u);
  size_t shipped = 0;
  for (const fs::path& file : FilesOf(fs::path(dream::testing::SourceDir()) / "config")) {
    if (file.extension() != ".yaml") continue;
    const std::vector<uint8_t> bytes = ReadBytes(file);
    RunConfigTarget(bytes.data(), bytes.size());
    ++shipped;
  }
  EXPECT_GE(shipped, 6u);
}

TEST(FuzzCorpusTest, SetOverrides) { EXPECT_GE(Replay("set_override", SetOverrideTarget), 4u); }

}  // namespace
}  // namespace dream::fuzz
