#include "dream/files/output_folder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include "../support/scratch_folder.h"

namespace dream::node {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class OutputFolderTest : public ::testing::Test {
 protected:
  dream::testing::ScratchFolder folder_{"dream_output_folder"};
  const fs::path base_ = folder_.path();

  std::string Path(const std::string& name) const { return (base_ / name).string(); }
};

std::string MessageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST_F(OutputFolderTest, NamesThatWouldLeaveTheFolderAreRefused) {
  const files::OutputFolder folder(Path("plain"));
  EXPECT_THAT(MessageOf([&] { folder.PathOf("../x"); }), HasSubstr("'..' would escape"));
  EXPECT_THAT(MessageOf([&] { folder.PathOf("a/../../x"); }), HasSubstr("'..' would escape"));
  EXPECT_THAT(MessageOf([&] { folder.PathOf("/etc/passwd"); }), HasSubstr("absolute path"));
  EXPECT_THAT(MessageOf([&] { folder.PathOf(""); }), HasSubstr("empty"));
  EXPECT_EQ(folder.PathOf("a/b.npy"), Path("plain") + "/a/b.npy");
}

TEST_F(OutputFolderTest, SymbolicLinkLeadingOutsideIsRefused) {
  fs::create_directories(base_ / "outside");
  const files::OutputFolder folder(Path("out"));
  fs::create_directory_symlink(base_ / "outside", base_ / "out" / "upload");
  EXPECT_THAT(MessageOf([&] { folder.WriteFile("upload/x.txt", "x"); }), HasSubstr("outside the output folder"));
  EXPECT_TRUE(fs::is_empty(base_ / "outside"));
}

TEST_F(OutputFolderTest, NamedFolderNeedsItsParentDefaultFolderIsMadeWithParents) {
  EXPECT_THAT(MessageOf([&] { files::OutputFolder(Path("missing/run")); }),
              HasSubstr("its parent folder " + Path("missing") + " does not exist"));
  EXPECT_FALSE(fs::exists(base_ / "missing"));
  const files::OutputFolder made(Path("runs/go_to_goal/"), files::OutputFolder::Parents::kCreate);
  EXPECT_TRUE(fs::is_directory(base_ / "runs" / "go_to_goal"));
  EXPECT_EQ(made.dir(), Path("runs/go_to_goal")) << "a trailing slash names the same folder";
}

TEST_F(OutputFolderTest, NamedFolderUnderAMissingToolFolderMakesIt) {
  // runs/, sweeps/ and exports/ of the working folder are dream's own, made
  // when missing (`--out exports/x` in a fresh checkout); any other missing
  // parent is still refused.
  const fs::path before = fs::current_path();
  fs::current_path(base_);
  const files::OutputFolder exported("exports/go_to_goal");
  const files::OutputFolder swept("./sweeps/seeds");
  EXPECT_THAT(MessageOf([&] { files::OutputFolder("exprots/go_to_goal"); }), HasSubstr("does not exist"));
  EXPECT_THAT(MessageOf([&] { files::OutputFolder("runs/a/b"); }),
              HasSubstr("its parent folder runs/a does not exist"));
  fs::current_path(before);
  EXPECT_TRUE(fs::is_directory(base_ / "exports" / "go_to_goal"));
  EXPECT_TRUE(fs::is_directory(base_ / "sweeps" / "seeds"));
  EXPECT_FALSE(fs::exists(base_ / "exprots"));
}

TEST_F(OutputFolderTest, FileWrittenWholeWithNoTemporaryLeftBehind) {
  const files::OutputFolder folder(Path("out"));
  folder.WriteFile("a.txt", "first");
  folder.WriteFile("a.txt", "second");
  std::ifstream in(folder.PathOf("a.txt"));
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "second");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(base_ / "out")) ++files;
  EXPECT_EQ(files, 1);
}

TEST_F(OutputFolderTest, AFileWhereTheFolderShouldBeIsReported) {
  std::ofstream(Path("taken")) << "x";
  EXPECT_THAT(MessageOf([&] { files::OutputFolder(Path("taken")); }),
              HasSubstr(Path("taken") + ": is a file, not a folder"));
  EXPECT_THAT(MessageOf([&] { files::OutputFolder(Path("taken/run")); }),
              HasSubstr("its parent " + Path("taken") + " is a file, not a folder"));
}

TEST_F(OutputFolderTest, AFileInSubfoldersGetsItsFoldersMadeAndStaysInside) {
  const files::OutputFolder out(Path("run"));
  out.WriteFileInSubfolders("controllers/python/orbit.py", "print('orbit')\n");
  std::ifstream in(out.PathOf("controllers/python/orbit.py"));
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "print('orbit')\n");
  out.WriteFileInSubfolders("controllers/python/orbit.py", "print('again')\n");  // the folders exist: fine
  EXPECT_THAT(MessageOf([&] { out.WriteFileInSubfolders("../outside/orbit.py", "x"); }), HasSubstr("would escape"));
  EXPECT_FALSE(fs::exists(base_ / "outside"));
}

// dream export into a folder whose `upload` is a file said only "File exists".
TEST_F(OutputFolderTest, AFileWhereASubfolderShouldBeIsNamedAsInTheWay) {
  const files::OutputFolder out(Path("export"));
  std::ofstream(out.PathOf("upload")) << "x";
  EXPECT_THAT(MessageOf([&] { out.MakeSubfolder("upload"); }),
              HasSubstr("cannot create the folder " + out.PathOf("upload") + ": a file of that name is in the way"));
  EXPECT_EQ(out.MakeSubfolder("lab_files"), out.PathOf("lab_files"));
  EXPECT_EQ(out.MakeSubfolder("lab_files"), out.PathOf("lab_files"));  // an existing folder is fine
}

}  // namespace
}  // namespace dream::node
