// files::ReadFileText, which reads configs' copies, summary.json, manifests
// and Python modules: a path naming something else (a FIFO, a folder, a huge
// file) is refused with its name, never waited on or read into memory.
#include "dream/files/file_text.h"

#include <sys/stat.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "../support/scratch_folder.h"

namespace dream::files {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class FileTextTest : public ::testing::Test {
 protected:
  std::string ErrorOf(const fs::path& path, std::uintmax_t max_bytes = kMaxTextFileBytes) {
    try {
      ReadFileText(path.string(), max_bytes);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "(no error)";
  }

  dream::testing::ScratchFolder folder_{"dream_file_text"};
  const fs::path dir_ = folder_.path();
};

TEST_F(FileTextTest, ARegularFileIsReadWhole) {
  const std::string text(200000, 'x');
  std::ofstream(dir_ / "big.txt", std::ios::binary) << text << "end";
  EXPECT_EQ(ReadFileText((dir_ / "big.txt").string()), text + "end");
  std::ofstream(dir_ / "empty.txt");
  EXPECT_EQ(ReadFileText((dir_ / "empty.txt").string()), "");
}

TEST_F(FileTextTest, AFileOverTheBoundIsRefusedWithItsSize) {
  std::ofstream(dir_ / "summary.json") << std::string(1001, ' ');
  EXPECT_EQ(ErrorOf(dir_ / "summary.json", 1000), (dir_ / "summary.json").string() +
                                                      ": 1001 bytes, more than the 1000 a file read here may hold; "
                                                      "is it the file you meant?");
  EXPECT_EQ(ReadFileText((dir_ / "summary.json").string(), 1001).size(), 1001u);
}

TEST_F(FileTextTest, AFifoAFolderAndAMissingFileAreRefusedByName) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(ErrorOf(fifo), fifo.string() + ": is a FIFO (named pipe), not a file to read");  // not waited on
  EXPECT_EQ(ErrorOf(dir_), dir_.string() + ": is a folder, not a file to read");
  EXPECT_THAT(ErrorOf(dir_ / "missing.yaml"), HasSubstr((dir_ / "missing.yaml").string() + ": cannot open the file"));
}

}  // namespace
}  // namespace dream::files
