#pragma once

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace dream::testing {

/// How many times the CI counts the fuzz tests run: DREAM_FUZZ_SCALE from the
/// environment (a whole number >= 1), 1 when unset. CI keeps 1, so every fuzz
/// test stays a few seconds; a longer run is e.g.
///   DREAM_FUZZ_SCALE=100 ctest --test-dir build -R 'MutationDriver|ConfigMutation'
/// A scale multiplies the count of each test, never changes its seed, so the
/// first N cases of a long run are the CI run's.
inline long FuzzScale() {
  const char* text = std::getenv("DREAM_FUZZ_SCALE");
  if (text == nullptr || *text == '\0') return 1;
  char* end = nullptr;
  const long scale = std::strtol(text, &end, 10);
  if (*end != '\0' || scale < 1 || scale > 1000000) {
    throw std::invalid_argument("DREAM_FUZZ_SCALE must be a whole number from 1 to 1000000, got '" + std::string(text) +
                                "'");
  }
  return scale;
}

}  // namespace dream::testing
