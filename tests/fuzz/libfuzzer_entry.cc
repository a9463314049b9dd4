// One libFuzzer program per target: compiled with
// -DDREAM_FUZZ_TARGET=dream::fuzz::<Name>Target (tests/fuzz/CMakeLists.txt).
#include <cstddef>
#include <cstdint>

#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  DREAM_FUZZ_TARGET(data, size);
  return 0;
}
