#pragma once
// Real files of the lab loop, made once per test binary: a simulated run of
// config/go_to_goal.yaml (run.lcmlog), its export (upload/dream_params.npy)
// and the result a perfect lab would save for it, as dream_result.npy and in
// every MATLAB .mat flavour libmatio reads (v4, v5, v5 compressed, v7.3).

#include <string>
#include <vector>

#include "dream/bridge/lab_import.h"
#include "dream/formats/npy_file.h"

namespace dream::testing {

class LabFileSamples {
 public:
  struct Sample {
    std::string name;   ///< e.g. "mat_v5_compressed"
    std::string bytes;  ///< the whole file
  };

  /// Runs, exports and writes the samples under a fresh temporary folder.
  LabFileSamples();

  const bridge::ExportedSubmission& exported() const { return exported_; }
  const std::string& export_dir() const { return export_dir_; }
  const std::string& run_log() const { return run_log_; }
  const formats::NpyArray& result() const { return result_; }
  /// The result file in each format (npy, mat_v4, mat_v5, mat_v5_compressed, mat_v73).
  const std::vector<Sample>& results() const { return results_; }
  /// The export's upload/dream_params.npy.
  const Sample& params() const { return params_; }
  /// A scratch path in the samples' folder.
  std::string Scratch(const std::string& name) const { return dir_ + "/" + name; }

 private:
  std::string dir_;
  std::string export_dir_;
  std::string run_log_;
  bridge::ExportedSubmission exported_;
  formats::NpyArray result_;
  std::vector<Sample> results_;
  Sample params_;
};

/// The samples of this test binary, made on first use.
const LabFileSamples& SharedLabFileSamples();

std::string ReadBytes(const std::string& path);
void WriteBytes(const std::string& path, const std::string& bytes);

}  // namespace dream::testing
