#include <cstdint>
#include <exception>
#include <filesystem>

#include "dream/formats/mat_file.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/submission_params.h"
#include "fuzz_targets.h"

namespace dream::fuzz {

void LabResultTarget(const uint8_t* data, size_t size) {
  if (size < 1) return;
  const bool mat = (data[0] & 1) != 0;
  const std::string path = ScratchFile(data + 1, size - 1, mat ? ".mat" : ".npy");
  try {
    if (mat) {
      const formats::NpyArray array = formats::ReadMatMatrix(path, "dream_result");
      if (static_cast<int64_t>(array.values.size()) != array.size())
        Finding("a .mat array whose values are not its shape");
    } else {
      const formats::NpyArray array = formats::ReadNpyFile(path, int64_t{1} << 20);
      if (static_cast<int64_t>(array.values.size()) != array.size())
        Finding("an .npy array whose values are not its shape");
      if (formats::DecodeNpy(formats::EncodeNpy(array), "again.npy").shape != array.shape)
        Finding("an .npy round trip changed the shape");
      if (array.shape.size() == 1) (void)bridge::SubmissionParams::FromNpy(array, path);
    }
  } catch (const std::exception& e) {
    if (std::string(e.what()).find(path) == std::string::npos)
      Finding("a lab result error without its file: " + std::string(e.what()));
  }
  std::filesystem::remove(path);
}

}  // namespace dream::fuzz
