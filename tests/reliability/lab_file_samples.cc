#include "lab_file_samples.h"

#include <matio.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "bridge_test_support.h"
#include "dream/formats/mat_file.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/bridge/submission_format.h"

namespace dream::testing {
namespace {

/// A .mat file of a flavour WriteMatMatrix does not write (v4, compressed v5).
std::string MatioFile(const std::string& path, const formats::NpyArray& array, mat_ft version,
                      matio_compression compression) {
  const auto rows = static_cast<size_t>(array.shape[0]);
  const auto columns = static_cast<size_t>(array.shape[1]);
  std::vector<double> column_major(rows * columns);
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < columns; ++c) column_major[c * rows + r] = array.values[r * columns + c];
  }
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, version);
  if (mat == nullptr) throw std::runtime_error(path + ": cannot create");
  size_t dims[2] = {rows, columns};
  matvar_t* var = Mat_VarCreate(bridge::SubmissionFiles::kResultMatVariable, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                                column_major.data(), MAT_F_DONT_COPY_DATA);
  const bool written = var != nullptr && Mat_VarWrite(mat, var, compression) == 0;
  Mat_VarFree(var);
  Mat_Close(mat);
  if (!written) throw std::runtime_error(path + ": cannot write");
  return ReadBytes(path);
}

}  // namespace

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void WriteBytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error(path + ": cannot write");
}

LabFileSamples::LabFileSamples() {
  const std::string run_dir =
      bridge::testing::MakeRunFolder("samples_run", bridge::testing::ShippedConfig("go_to_goal"));
  run_log_ = run_dir + "/run.lcmlog";
  export_dir_ = bridge::testing::NewFolder("samples_export");
  bridge::ExportSubmission(run_dir, export_dir_, bridge::ExportOptions{});
  exported_ = bridge::ExportedSubmission::Read(export_dir_);
  dir_ = bridge::testing::NewFolder("samples_files");
  result_ = bridge::testing::PerfectLabResult(export_dir_);
  results_.push_back({"npy", formats::EncodeNpy(result_)});
  const std::string mat = dir_ + "/sample.mat";
  formats::WriteMatMatrix(mat, bridge::SubmissionFiles::kResultMatVariable, result_);
  results_.push_back({"mat_v5", ReadBytes(mat)});
  results_.push_back({"mat_v5_compressed", MatioFile(mat, result_, MAT_FT_MAT5, MAT_COMPRESSION_ZLIB)});
  results_.push_back({"mat_v4", MatioFile(mat, result_, MAT_FT_MAT4, MAT_COMPRESSION_NONE)});
  std::filesystem::remove(mat);
  formats::WriteMatMatrix(mat, bridge::SubmissionFiles::kResultMatVariable, result_, true);
  results_.push_back({"mat_v73", ReadBytes(mat)});
  params_ = {"params_npy", ReadBytes(export_dir_ + "/upload/" + bridge::SubmissionFiles::kParams)};
}

const LabFileSamples& SharedLabFileSamples() {
  static const LabFileSamples* samples = new LabFileSamples();
  return *samples;
}

}  // namespace dream::testing
