#include <cstdint>
#include <exception>
#include <string>

#include "dream/bridge/lab_import.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/pre_validation.h"
#include "fuzz_targets.h"
#include "../support/source_tree.h"

namespace dream::fuzz {

void LabRowsTarget(const uint8_t* data, size_t size) {
  // An 8-robot, 20-step go_to_goal export (tests/fuzz/lab_export), read once.
  static const bridge::ExportedSubmission exported =
      bridge::ExportedSubmission::Read(dream::testing::SourceDir() + "/tests/fuzz/lab_export");
  const std::string name = "fuzz_result.npy";
  try {
    const formats::NpyArray rows = formats::DecodeNpy(std::string(reinterpret_cast<const char*>(data), size), name);
    const bridge::LabResult lab = bridge::ParseLabResult(rows, name, exported);
    (void)bridge::LabVerifierReasons(lab, exported.config.world, exported.UploadDeclaration());
    (void)bridge::VerifierCounts(lab.track, exported.config.world);
  } catch (const std::exception& e) {
    if (std::string(e.what()).find(name) == std::string::npos)
      Finding("a lab result error without its file: " + std::string(e.what()));
  }
}

}  // namespace dream::fuzz
