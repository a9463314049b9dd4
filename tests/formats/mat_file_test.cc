// The .mat reader's own checks, made before libmatio reads a byte: forged v4
// headers, compressed v5 headers and a v7.3 header with no HDF5 behind it, each
// refused naming the file, the element and its byte offset.
#include "dream/formats/mat_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../support/scratch_folder.h"

namespace dream::formats {
namespace {

using ::testing::HasSubstr;

void WriteFile(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

class MatFileTest : public ::testing::Test {
 protected:
  /// A fresh folder `name` in this test's scratch folder.
  std::string NewFolder(const std::string& name) const {
    const std::filesystem::path dir = scratch_.path() / name;
    std::filesystem::create_directories(dir);
    return dir.string();
  }

 private:
  const dream::testing::ScratchFolder scratch_{"mat_file"};
};

/// The error of reading `bytes` as `path`'s .mat file, "" when it was read.
std::string MatReadError(const std::string& path, const std::string& bytes) {
  WriteFile(path, bytes);
  try {
    ReadMatMatrix(path, "dream_result", 100);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

/// A MATLAB v4 variable: its 20-byte header (type, rows, columns, imaginary
/// flag, name length; little-endian), `name` and `data`.
std::string Mat4Variable(int32_t type, int32_t rows, int32_t columns, int32_t name_bytes, const std::string& name,
                         const std::vector<double>& data) {
  std::string bytes;
  for (const int32_t word : {type, rows, columns, int32_t{0}, name_bytes}) {
    bytes.append(reinterpret_cast<const char*>(&word), sizeof(word));
  }
  bytes += name;
  bytes.append(reinterpret_cast<const char*>(data.data()), data.size() * sizeof(double));
  return bytes;
}

// libmatio allocates what a v4 header declares before reading it (40 forged
// bytes made it ask for 1.8 GB): the reader walks v4 headers against the
// file first, names the flaw, and still reads a sound v4 file.
TEST_F(MatFileTest, ForgedV4HeadersAreRefusedBeforeLibmatioReadsThem) {
  const std::string dir = NewFolder("mat_v4");
  const std::string name("dream_result\0", 13);
  const std::string sound = dir + "/sound.mat";
  WriteFile(sound, Mat4Variable(0, 2, 3, 13, name, {1, 2, 3, 4, 5, 6}));
  const NpyArray read = ReadMatMatrix(sound, "dream_result", 100);
  EXPECT_EQ(read.shape, (std::vector<int64_t>{2, 3}));
  EXPECT_EQ(read.values, (std::vector<double>{1, 3, 5, 2, 4, 6}));  // the file is column-major

  const std::vector<std::pair<std::string, std::string>> cases = {
      {Mat4Variable(0, 2, 3, 1819636581, name, {1, 2, 3, 4, 5, 6}),
       "v4 variable 0 at byte 0 has a name of 1819636581 bytes"},
      {Mat4Variable(0, 65536, 65536, 13, name, {1, 2}),
       "v4 variable 0 at byte 0 declares 65536 x 65536 values of 8 bytes, but only 16 bytes follow its name"},
      {Mat4Variable(0, -1, 3, 13, name, {}), "v4 variable 0 at byte 0 has -1 x 3 values"},
      {Mat4Variable(7777, 2, 3, 13, name, {}), "v4 variable 0 at byte 0 has type 7777, not a v4 MOPT code"},
      // A type found byte-swapped (bytes 00 00 00 01: 1) but whose M (0) says little-endian:
      // libmatio reads the rest little-endian, a 2013265920-byte name.
      {Mat4Variable(16777216, 0, 0, 0x78000000, name, {}), "v4 variable 0 at byte 0 has a name of 2013265920 bytes"},
      {Mat4Variable(0, 1, 1, 13, name, {1}) + "short",
       "v4 variable 1 at byte 41 is cut short inside its 20-byte header"},
      {"not a MATLAB file at all, just text that goes on", "v4 variable 0 at byte 0 has type 544501614, not a v4"},
  };
  for (const auto& [bytes, problem] : cases) {
    SCOPED_TRACE(problem);
    const std::string path = dir + "/forged.mat";
    EXPECT_THAT(MatReadError(path, bytes), HasSubstr(path + ": " + problem));
  }
}

/// `words` as little-endian int32s.
std::string Int32s(std::initializer_list<int32_t> words) {
  std::string bytes;
  for (const int32_t word : words) bytes.append(reinterpret_cast<const char*>(&word), sizeof(word));
  return bytes;
}

/// A little-endian MAT-file v5 of one compressed element holding `inside`.
std::string CompressedMat5(const std::string& inside) {
  std::string header = "MATLAB 5.0 MAT-file, made by a test";
  header.resize(124, ' ');
  header += std::string("\x00\x01IM", 4);
  std::string packed(compressBound(static_cast<uLong>(inside.size())), '\0');
  uLongf packed_size = packed.size();
  EXPECT_EQ(compress(reinterpret_cast<Bytef*>(packed.data()), &packed_size,
                     reinterpret_cast<const Bytef*>(inside.data()), static_cast<uLong>(inside.size())),
            Z_OK);
  packed.resize(packed_size);
  return header + Int32s({15, static_cast<int32_t>(packed.size())}) + packed;
}

// libmatio inflates a compressed matrix's header and allocates the name and
// dimensions it declares (296 forged bytes made it ask for 1 GB): the reader
// inflates the first 4 KiB itself and refuses a header that does not fit.
TEST_F(MatFileTest, ForgedCompressedHeadersAreRefusedBeforeLibmatioReadsThem) {
  const std::string dir = NewFolder("mat_v5_compressed");
  const std::string flags = Int32s({6, 8, 6, 0});                    // miUINT32 x 2: class double
  const std::string dims = Int32s({5, 8, 2, 3});                     // miINT32 x 2: 2 x 3
  const std::string data = Int32s({9, 48}) + std::string(48, '\0');  // miDOUBLE x 6
  auto matrix = [](const std::string& body) { return Int32s({14, static_cast<int32_t>(body.size())}) + body; };
  const std::string name = Int32s({1, 12}) + "dream_result" + std::string(4, '\0');  // padded to 8 bytes
  const std::string sound = dir + "/sound.mat";
  WriteFile(sound, CompressedMat5(matrix(flags + dims + name + data)));
  EXPECT_EQ(ReadMatMatrix(sound, "dream_result", 100).shape, (std::vector<int64_t>{2, 3}));

  const std::vector<std::pair<std::string, std::string>> cases = {
      {CompressedMat5(matrix(flags + dims + Int32s({1, 1000000000}) + "dream_result")),
       "(inflated, first 60 bytes): its name at byte 40 declares 1000000000 bytes of data, but only 12 follow"},
      {CompressedMat5(matrix(flags + Int32s({5, 400000000}) + name)),
       "(inflated, first 56 bytes): its dimensions at byte 24 declares 400000000 bytes"},
      {CompressedMat5(Int32s({9, 8}) + std::string(8, '\0')), "holds data type 9, not a matrix (14)"},
      {CompressedMat5("abc"), "inflates to 3 bytes, not a matrix"},
      {CompressedMat5(Int32s({14, 2000000000}) + flags + dims + name), "says it inflates to 2000000000 bytes"},
  };
  for (const auto& [bytes, problem] : cases) {
    SCOPED_TRACE(problem);
    const std::string path = dir + "/forged.mat";
    const std::string error = MatReadError(path, bytes);
    EXPECT_THAT(error, HasSubstr(path + ": compressed element 0 at byte 128"));  // what and where
    EXPECT_THAT(error, HasSubstr(problem));
  }
  // The same parts uncompressed: 616 forged bytes whose array flags claimed
  // 242 bytes made libmatio ask for 3.4 GB.
  const std::string header = CompressedMat5("").substr(0, 128);
  const std::vector<std::pair<std::string, std::string>> uncompressed = {
      {matrix(Int32s({6, 16}) + std::string(16, '\0') + dims + name + data),
       "matrix 0 at byte 128: its array flags are 16 bytes of type 6, not 8 bytes of miUINT32 (6)"},
      {matrix(flags + Int32s({5, 4, 2, 0}) + name + data),
       "matrix 0 at byte 128: its dimensions are 4 bytes of type 5, not miINT32 (5), 4 bytes for each of two or more"},
      {matrix(flags + dims + Int32s({2, 12}) + "dream_result" + std::string(4, '\0') + data),
       "matrix 0 at byte 128: its name has type 2, not miINT8 (1)"},
      // A cell array of 654311940 x 13 cells: libmatio asked for 68 GB of cell pointers.
      {matrix(Int32s({6, 8, 1, 0}) + Int32s({5, 8, 654311940, 13}) + name),
       "matrix 0 at byte 128: dimensions 654311940 x 13 (class 1) need 8 byte(s) per value, but the matrix has 56"},
  };
  for (const auto& [element, problem] : uncompressed) {
    SCOPED_TRACE(problem);
    const std::string path = dir + "/forged_plain.mat";
    EXPECT_THAT(MatReadError(path, header + element), HasSubstr(path + ": " + problem));
  }
  std::string not_zlib = CompressedMat5(matrix(flags));
  not_zlib[136] = 'X';  // the zlib header's first byte
  const std::string path = dir + "/not_zlib.mat";
  EXPECT_THAT(MatReadError(path, not_zlib), HasSubstr("compressed element 0 at byte 128 is not zlib data"));
}

// A v7.3 header must have HDF5 behind it: when the HDF5 part does not open,
// libmatio reads the file as v4 from byte 0 (a fuzzed file whose first bytes
// were zeros made it allocate 1.8 GB).
TEST_F(MatFileTest, V73HeaderWithoutHdf5IsRefused) {
  const std::string dir = NewFolder("mat_v73");
  std::string v73_header = "MATLAB 7.3 MAT-file, made by a test";
  v73_header.resize(124, ' ');
  v73_header += std::string("\x00\x02IM", 4);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {std::string(4, '\0') + v73_header.substr(4) + std::string(64, 'x'), "v4 variable 0 at byte 0 has "},
      {v73_header + std::string(600, '\0'), "a MATLAB 7.3 MAT-file header, but no HDF5 data at byte 512"},
      {v73_header, "a MATLAB 7.3 MAT-file header, but no HDF5 data at byte 512"},
  };
  for (const auto& [bytes, problem] : cases) {
    SCOPED_TRACE(problem);
    const std::string path = dir + "/forged.mat";
    EXPECT_THAT(MatReadError(path, bytes), HasSubstr(path + ": " + problem));
  }
}

}  // namespace
}  // namespace dream::formats
