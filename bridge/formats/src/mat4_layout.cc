#include "mat4_layout.h"

#include <cstring>
#include <stdexcept>

namespace dream::formats {

void Mat4Layout::Check() const {
  uint64_t offset = 0;
  for (int index = 0; offset < bytes_.size(); ++index) offset = CheckVariable(index, offset);
}

bool Mat4Layout::ReadableAsV4(const std::string& bytes) {
  if (bytes.size() < 4) return false;
  uint32_t word = 0;
  std::memcpy(&word, bytes.data(), 4);
  return word <= 4052 || __builtin_bswap32(word) <= 4052;
}

void Mat4Layout::Fail(const std::string& problem) const {
  throw std::runtime_error(path_ + ": " + problem +
                           " (not a MATLAB .mat file, or damaged or cut short? MATLAB's save writes v5/v7/v7.3 " +
                           "files with a 'MATLAB 5.0 MAT-file' header; a header-less file is read as v4)");
}

int32_t Mat4Layout::Word(uint64_t offset, bool swap) const {
  uint32_t value = 0;
  std::memcpy(&value, bytes_.data() + offset, 4);
  return static_cast<int32_t>(swap ? __builtin_bswap32(value) : value);
}

uint64_t Mat4Layout::CheckVariable(int index, uint64_t offset) const {
  const std::string what = "v4 variable " + std::to_string(index) + " at byte " + std::to_string(offset);
  if (bytes_.size() - offset < kHeaderBytes) Fail(what + " is cut short inside its 20-byte header");
  // The type MOPT is small in the file's byte order; libmatio tries both orders the same way.
  int32_t type = Word(offset, false);
  if (type < 0 || type > 4052) type = Word(offset, true);
  const int32_t machine = type / 1000;
  const int32_t zero = type / 100 % 10;
  const int32_t precision = type / 10 % 10;
  const int32_t matrix_type = type % 10;
  if (type < 0 || machine > 1 || zero != 0 || precision > 5 || matrix_type > 2) {
    Fail(what + " has type " + std::to_string(Word(offset, false)) + ", not a v4 MOPT code (M 0-1, O 0, P 0-5, T 0-2)");
  }
  // libmatio then reads the rest in the order M names (0 little-, 1 big-endian),
  // whichever order the type was found in: so must we.
  const bool swap = (machine == 1) != (__BYTE_ORDER__ == __ORDER_BIG_ENDIAN__);
  const int32_t rows = Word(offset + 4, swap);
  const int32_t columns = Word(offset + 8, swap);
  const int32_t imaginary = Word(offset + 12, swap);
  const int32_t name_bytes = Word(offset + 16, swap);
  if (rows < 0 || columns < 0) {
    Fail(what + " has " + std::to_string(rows) + " x " + std::to_string(columns) + " values");
  }
  if (imaginary != 0 && imaginary != 1)
    Fail(what + " has imaginary flag " + std::to_string(imaginary) + ", not 0 or 1");
  const uint64_t after_header = offset + kHeaderBytes;
  if (name_bytes < 1 || name_bytes > kMaxNameBytes ||
      static_cast<uint64_t>(name_bytes) > bytes_.size() - after_header) {
    Fail(what + " has a name of " + std::to_string(name_bytes) + " bytes, but 1.." + std::to_string(kMaxNameBytes) +
         " that fit in the " + std::to_string(bytes_.size() - after_header) + " bytes left are allowed");
  }
  static constexpr uint64_t kPrecisionBytes[] = {8, 4, 4, 2, 2, 1};  // double, single, int32, int16, uint16, uint8
  const uint64_t data_start = after_header + static_cast<uint64_t>(name_bytes);
  const uint64_t left = bytes_.size() - data_start;
  // rows and columns are below 2^31, so their product fits; compare before scaling it.
  const uint64_t values = static_cast<uint64_t>(rows) * static_cast<uint64_t>(columns);
  const uint64_t per_value = kPrecisionBytes[precision] * (imaginary == 1 ? 2 : 1);
  if (values > left / per_value) {
    Fail(what + " declares " + std::to_string(rows) + " x " + std::to_string(columns) + " values of " +
         std::to_string(per_value) + " bytes, but only " + std::to_string(left) + " bytes follow its name");
  }
  return data_start + values * per_value;
}

}  // namespace dream::formats
