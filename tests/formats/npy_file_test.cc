// The hand-written .npy reader and writer: round trips, numpy's own byte
// layouts, and strict refusal of everything else, naming the file.
#include "dream/formats/npy_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include "../support/scratch_folder.h"

namespace dream::formats {
namespace {

using ::testing::HasSubstr;

/// A .npy file with the given header dict (padded like numpy) and data bytes.
std::string NpyBytes(const std::string& dict, const std::string& data, char major = 1) {
  std::string header = dict;
  const size_t prefix = major == 1 ? 10 : 12;
  header.append((64 - (prefix + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string bytes("\x93NUMPY", 6);
  bytes += major;
  bytes += '\0';
  const size_t length = header.size();
  bytes += static_cast<char>(length & 0xff);
  bytes += static_cast<char>((length >> 8) & 0xff);
  if (major != 1) bytes += std::string(2, '\0');
  return bytes + header + data;
}

std::string Doubles(const std::vector<double>& values) {
  std::string data(values.size() * 8, '\0');
  if (!values.empty()) std::memcpy(data.data(), values.data(), data.size());
  return data;
}

TEST(NpyFileTest, RoundTripKeepsShapeAndEveryBit) {
  NpyArray array;
  array.shape = {2, 3};
  array.values = {1.0, -0.0, 1e-310, std::nextafter(1.0, 2.0), -3.25, 1e300};
  const std::string bytes = EncodeNpy(array);
  EXPECT_EQ((bytes.size() - 6 * 8) % 64, 0u) << "data must start 64-byte aligned, like numpy";
  const NpyArray back = DecodeNpy(bytes, "a.npy");
  EXPECT_EQ(back.shape, array.shape);
  ASSERT_EQ(back.values.size(), array.values.size());
  EXPECT_EQ(std::memcmp(back.values.data(), array.values.data(), 6 * 8), 0);
}

TEST(NpyFileTest, WritesTheHeaderNumpyWrites) {
  NpyArray vector;
  vector.shape = {3};
  vector.values = {1, 2, 3};
  EXPECT_THAT(EncodeNpy(vector), HasSubstr("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }"));
  NpyArray matrix;
  matrix.shape = {2, 0, 4};
  EXPECT_THAT(EncodeNpy(matrix), HasSubstr("'shape': (2, 0, 4), }"));
  NpyArray wrong;
  wrong.shape = {2};
  EXPECT_THROW(EncodeNpy(wrong), std::invalid_argument);
}

TEST(NpyFileTest, ReadsNumpyLayoutsVersionTwoAndAnyKeyOrder) {
  const NpyArray a =
      DecodeNpy(NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", Doubles({1.5, 2.5})), "a");
  EXPECT_EQ(a.shape, (std::vector<int64_t>{2}));
  EXPECT_EQ(a.values, (std::vector<double>{1.5, 2.5}));
  const NpyArray b =
      DecodeNpy(NpyBytes("{'shape': (1, 1), 'fortran_order': False, 'descr': '<f8'}", Doubles({7}), 2), "b");
  EXPECT_EQ(b.shape, (std::vector<int64_t>{1, 1}));
  const NpyArray scalar =
      DecodeNpy(NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (), }", Doubles({4})), "c");
  EXPECT_TRUE(scalar.shape.empty());
  EXPECT_EQ(scalar.values, (std::vector<double>{4}));
}

struct BadNpy {
  const char* what;
  std::string bytes;
  const char* message;
};

TEST(NpyFileTest, RefusesEverythingButFloat64NamingTheFile) {
  const std::string ok_dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }";
  const std::vector<BadNpy> cases = {
      {"text file", "x,y\n1,2\n", "not a .npy file"},
      {"empty", "", "not a .npy file"},
      {"cut in the header", NpyBytes(ok_dict, "").substr(0, 20), "cut short inside the .npy header"},
      {"cut in the data", NpyBytes(ok_dict, Doubles({1.0, 2.0})).substr(0, 64 + 12), "cut short"},
      {"trailing bytes", NpyBytes(ok_dict, Doubles({1.0, 2.0, 3.0})), "bytes after the data"},
      {"float32", NpyBytes("{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }", std::string(8, '\0')), "'<f4'"},
      {"big endian", NpyBytes("{'descr': '>f8', 'fortran_order': False, 'shape': (2,), }", Doubles({1, 2})), "'>f8'"},
      {"int64", NpyBytes("{'descr': '<i8', 'fortran_order': False, 'shape': (2,), }", Doubles({1, 2})), "'<i8'"},
      {"pickled objects", NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (2,), }", Doubles({1, 2})),
       "'|O'"},
      {"extra key", NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), 'x': 1}", Doubles({1, 2})),
       "unexpected key"},
      {"missing shape", NpyBytes("{'descr': '<f8', 'fortran_order': False}", Doubles({1, 2})), "lacks"},
      {"code in the header",
       NpyBytes("{'descr': '<f8', 'fortran_order': __import__('os'), 'shape': (2,)}", Doubles({1, 2})),
       "True or False"},
      {"negative shape", NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (-2,), }", Doubles({1, 2})),
       "tuple of whole numbers"},
      {"absurd shape", NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999, 99999999999), }", ""),
       "absurd"},
      {"version 9", std::string("\x93NUMPY\x09\x00", 8) + std::string(100, ' '), "version 9.0"},
  };
  for (const BadNpy& bad : cases) {
    try {
      DecodeNpy(bad.bytes, "results/dream_result.npy");
      ADD_FAILURE() << bad.what << ": accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("results/dream_result.npy: ")) << bad.what;
      EXPECT_THAT(e.what(), HasSubstr(bad.message)) << bad.what;
    }
  }
}

// scipy.io.loadmat and MATLAB give arrays in Fortran order, and np.save keeps
// it: the first index runs fastest in the file. Read as numpy reads it.
TEST(NpyFileTest, ReadsFortranOrderAsNumpyDoes) {
  // a[i][j][k] = 100 i + 10 j + k, shape (2, 3, 4), written first index fastest.
  std::vector<double> fortran;
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 2; ++i) fortran.push_back(100 * i + 10 * j + k);
    }
  }
  const NpyArray array =
      DecodeNpy(NpyBytes("{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3, 4), }", Doubles(fortran)), "f.npy");
  ASSERT_EQ(array.shape, (std::vector<int64_t>{2, 3, 4}));
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(array.values[static_cast<size_t>((i * 3 + j) * 4 + k)], 100 * i + 10 * j + k);
    }
  }
  // One dimension: the same either way.
  EXPECT_EQ(
      DecodeNpy(NpyBytes("{'descr': '<f8', 'fortran_order': True, 'shape': (2,), }", Doubles({1, 2})), "f.npy").values,
      (std::vector<double>{1, 2}));
}

TEST(NpyFileTest, ReadFileNamesMissingAndOversizedFiles) {
  const dream::testing::ScratchFolder scratch("npy_files");
  const std::string dir = scratch.path().string();
  EXPECT_THROW(
      {
        try {
          ReadNpyFile(dir + "/missing.npy");
        } catch (const std::runtime_error& e) {
          EXPECT_THAT(e.what(), HasSubstr(dir + "/missing.npy: cannot open"));
          throw;
        }
      },
      std::runtime_error);
  NpyArray array;
  array.shape = {100};
  array.values.assign(100, 1.0);
  std::ofstream(dir + "/big.npy", std::ios::binary) << EncodeNpy(array);
  EXPECT_EQ(ReadNpyFile(dir + "/big.npy").values.size(), 100u);
  EXPECT_THROW(ReadNpyFile(dir + "/big.npy", 500), std::runtime_error);
}

}  // namespace
}  // namespace dream::formats
