// Every lab-loop file cut short at many lengths: the import refuses each one
// with an error naming the file, or (a cut the format cannot show, in
// padding) reads exactly the original. Before the .mat reader checked the
// declared sizes, 148 of 253 truncated .mat files imported as clean runs
// made of uninitialised memory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>

#include "dream/bridge/lab_import.h"
#include "dream/bridge/submission_format.h"
#include "lab_file_samples.h"

namespace dream::testing {
namespace {

namespace fs = std::filesystem;

/// Every length within 300 bytes of either end (headers, tags, the last
/// values and any padding), and about 400 between.
std::vector<size_t> CutLengths(size_t size) {
  std::set<size_t> lengths;
  for (size_t n = 0; n < size && n < 300; ++n) lengths.insert(n);
  for (size_t n = size > 300 ? size - 300 : 0; n < size; ++n) lengths.insert(n);
  const size_t stride = std::max<size_t>(1, size / 400);
  for (size_t n = 0; n < size; n += stride) lengths.insert(n);
  return {lengths.begin(), lengths.end()};
}

/// Leaves a freed block of `bytes` filled with a pattern, so a reader that
/// hands back memory it never filled (malloc reusing the last result's
/// block) shows other values instead of the original's.
void PoisonFreedHeap(size_t bytes) {
  void* block = std::malloc(bytes);
  ASSERT_NE(block, nullptr);
  std::memset(block, 0x5a, bytes);
  volatile char sink = static_cast<char*>(block)[bytes / 2];
  (void)sink;
  std::free(block);
}

std::string Extension(const std::string& sample_name) { return sample_name == "npy" ? ".npy" : ".mat"; }

TEST(TruncatedFiles, EveryCutResultFileIsRefusedByNameOrReadsAsTheOriginal) {
  const LabFileSamples& samples = SharedLabFileSamples();
  for (const LabFileSamples::Sample& sample : samples.results()) {
    const std::string path = samples.Scratch("cut_" + sample.name + Extension(sample.name));
    // The whole file imports: the cuts below start from a good file.
    WriteBytes(path, sample.bytes);
    ASSERT_EQ(bridge::ReadResultFile(path).values, samples.result().values) << sample.name;
    long refused = 0;
    long identical = 0;
    for (const size_t length : CutLengths(sample.bytes.size())) {
      WriteBytes(path, sample.bytes.substr(0, length));
      const std::string what =
          sample.name + " cut to " + std::to_string(length) + " of " + std::to_string(sample.bytes.size()) + " bytes";
      PoisonFreedHeap(samples.result().values.size() * sizeof(double));
      try {
        const formats::NpyArray rows = bridge::ReadResultFile(path, samples.exported().MaxResultValues());
        bridge::ParseLabResult(rows, path, samples.exported());
        EXPECT_EQ(rows.shape, samples.result().shape) << what << " was read as another array";
        EXPECT_EQ(rows.values, samples.result().values) << what << " was read with other values";
        ++identical;
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << what << ": " << e.what();
        ++refused;
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": not a clean refusal: " << e.what();
      }
    }
    EXPECT_GT(refused, 0) << sample.name;
    RecordProperty(sample.name + "_refused", std::to_string(refused));
    RecordProperty(sample.name + "_identical", std::to_string(identical));
    std::printf("%s (%zu bytes): %ld cuts refused, %ld read as the original\n", sample.name.c_str(),
                sample.bytes.size(), refused, identical);
  }
}

TEST(TruncatedFiles, EveryCutParamsFileIsRefusedByName) {
  const LabFileSamples& samples = SharedLabFileSamples();
  const std::string copy = samples.Scratch("export_copy");
  fs::copy(samples.export_dir(), copy, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  // Without the export's digests, so each damaged file reaches the .npy
  // reader (the digest check alone refuses every one).
  WriteBytes(copy + "/export.json", "{}");
  const std::string params = copy + "/upload/" + bridge::SubmissionFiles::kParams;
  long refused = 0;
  for (const size_t length : CutLengths(samples.params().bytes.size())) {
    WriteBytes(params, samples.params().bytes.substr(0, length));
    try {
      bridge::ExportedSubmission::Read(copy);
      ADD_FAILURE() << "dream_params.npy cut to " << length << " bytes was read";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(params + ": ", 0), 0u) << length << ": " << e.what();
      ++refused;
    }
  }
  RecordProperty("params_refused", std::to_string(refused));
}

TEST(TruncatedFiles, ImportOfACutMatFileNamesTheVariableAndWritesNothing) {
  const LabFileSamples& samples = SharedLabFileSamples();
  const std::string& v5 = samples.results()[1].bytes;
  ASSERT_EQ(samples.results()[1].name, "mat_v5");
  const std::string path = samples.Scratch("half.mat");
  WriteBytes(path, v5.substr(0, v5.size() / 2));
  const std::string out = samples.Scratch("half_out");
  try {
    bridge::ImportLabRun(path, samples.export_dir(), out);
    ADD_FAILURE() << "imported half a .mat file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": top-level element 0 at byte 128 declares "), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(TruncatedFiles, MatDimensionsThatDisagreeWithTheDataAreRefusedByVariable) {
  const LabFileSamples& samples = SharedLabFileSamples();
  std::string v5 = samples.results()[1].bytes;
  // The v5 matrix: tag (8), array flags (16), dims tag (8) + rows, columns (int32 each).
  const size_t rows_at = 128 + 8 + 16 + 8;
  int32_t rows = 0;
  std::memcpy(&rows, v5.data() + rows_at, 4);
  ASSERT_EQ(rows, samples.result().shape[0]);
  const int32_t fewer = rows - 1;
  std::memcpy(v5.data() + rows_at, &fewer, 4);
  const std::string path = samples.Scratch("dims.mat");
  WriteBytes(path, v5);
  try {
    bridge::ReadResultFile(path);
    ADD_FAILURE() << "read a .mat whose dims disagree with its data";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(
        std::string(e.what()).find(path + ": variable 'dream_result': dimensions " + std::to_string(fewer) + " x "),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace dream::testing
