#include "file_mutator.h"

#include <iterator>

namespace dream::testing {

std::string FileMutator::Mutate(std::string bytes) {
  const size_t rounds = Below(3) + 1;
  for (size_t i = 0; i < rounds; ++i) MutateOnce(&bytes);
  return bytes;
}

void FileMutator::MutateOnce(std::string* bytes) {
  static const uint32_t kInteresting[] = {0x10000000, 0xFFFFFFFF, 0x7FFFFFFF, 0x80000000,
                                          0x06666667, 0x00000000, 0x00000033, 0x00010001};
  static const char* const kDigits[] = {"0", "1", "-1", "99999999999999999999", "4294967296", "268435456", ", 0"};
  const size_t size = bytes->size();
  const size_t at = Below(size);
  switch (Below(9)) {
    case 0:
      if (size > 0) (*bytes)[at] = static_cast<char>((*bytes)[at] ^ (1 << Below(8)));
      break;
    case 1:
      if (size > 0) (*bytes)[at] = static_cast<char>(random_());
      break;
    case 2:
    case 3:
      if (size >= 4) {  // an attacker's 32-bit value, little-endian (case 2) or big-endian (case 3)
        const bool big_endian = Below(2) == 1;
        const size_t word = Below(size - 3);
        const uint32_t value = kInteresting[Below(std::size(kInteresting))];
        for (size_t i = 0; i < 4; ++i) {
          const size_t shift = big_endian ? 24 - 8 * i : 8 * i;
          (*bytes)[word + i] = static_cast<char>((value >> shift) & 0xff);
        }
      }
      break;
    case 4:
      bytes->resize(at);
      break;
    case 5: {
      std::string inserted(Below(16) + 1, '\0');
      for (char& byte : inserted) byte = static_cast<char>(random_());
      bytes->insert(at, inserted);
      break;
    }
    case 6:
      bytes->erase(at, Below(32) + 1);
      break;
    case 7:
      if (size > 0) bytes->insert(at, bytes->substr(Below(size), Below(64) + 1));
      break;
    default:  // a number where a text header (the .npy dict) has one, or anywhere
      bytes->replace(at, Below(3), kDigits[Below(std::size(kDigits))]);
      break;
  }
}

}  // namespace dream::testing
