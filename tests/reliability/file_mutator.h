#pragma once

#include <cstdint>
#include <random>
#include <string>

namespace dream::testing {

/// Byte-level damage to a whole file, from a seed: bit flips, random bytes,
/// sizes an attacker picks (2^28, -1, INT_MAX, ... in both byte orders, as
/// .npy/.mat are little-endian and LCM logs big-endian), digits in text
/// headers, truncation, insertion, deletion and duplication; one to three
/// per file. The same seed gives the same files on every machine.
class FileMutator {
 public:
  explicit FileMutator(uint32_t seed) : random_(seed) {}

  std::string Mutate(std::string bytes);

 private:
  size_t Below(size_t n) { return n == 0 ? 0 : static_cast<size_t>(random_() % n); }
  void MutateOnce(std::string* bytes);

  std::mt19937 random_;
};

}  // namespace dream::testing
