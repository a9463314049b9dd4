// Issue 34, files: a FIFO, device or folder given where dream reads a file is
// refused by name before anything can wait on it (each test here would hang
// in open() without that, and end at ctest's timeout); a link planted at a
// temporary name in a shared folder is never written through; the stop token
// long computations poll.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "../support/scratch_folder.h"
#include "dream/calibration/calibration_run.h"
#include "dream/bridge/lab_import.h"
#include "dream/formats/mat_file.h"
#include "dream/formats/npy_file.h"
#include "dream/formats/npz_file.h"
#include "dream/formats/sha256.h"
#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/files/regular_file.h"
#include "dream/files/stop_token.h"
#include "dream/files/stopped.h"
#include "dream/files/temporary_file.h"
#include "dream/lcm/log_reader.h"
#include "dream/node/run_recorder.h"
#include "dream/run_log/run_log.h"

namespace dream {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string ErrorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

std::string Contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class HostileFilesTest : public ::testing::Test {
 protected:
  // A FIFO named `name` in the scratch folder (no writer: opening it for
  // reading would block).
  std::string Fifo(const std::string& name) {
    const std::string path = (dir_ / name).string();
    if (::mkfifo(path.c_str(), 0600) != 0) throw std::runtime_error("mkfifo " + path);
    return path;
  }

  dream::testing::ScratchFolder folder_{"dream_hostile_files"};
  const fs::path dir_ = folder_.path();
};

TEST_F(HostileFilesTest, RegularFileRefusesAFifoADeviceAndAFolderByName) {
  const std::string fifo = Fifo("pipe");
  EXPECT_EQ(ErrorOf([&] { files::RegularFile{fifo}; }), fifo + ": is a FIFO (named pipe), not a file to read");
  EXPECT_EQ(ErrorOf([&] { files::RegularFile{"/dev/null"}; }), "/dev/null: is a device, not a file to read");
  EXPECT_EQ(ErrorOf([&] { files::RegularFile{dir_.string()}; }), dir_.string() + ": is a folder, not a file to read");
  EXPECT_EQ(ErrorOf([&] { files::ReadFileText(fifo); }), fifo + ": is a FIFO (named pipe), not a file to read");
}

// What a library reopens by OpenedName() is the file that was checked, even
// when the path names a FIFO by then.
TEST_F(HostileFilesTest, TheOpenedNameIsTheCheckedFileWhateverThePathNamesLater) {
  const fs::path path = dir_ / "result.mat";
  std::ofstream(path) << "checked";
  const files::RegularFile file(path.string());
  fs::remove(path);
  Fifo("result.mat");
  EXPECT_EQ(file.size(), 7U);
  EXPECT_EQ(Contents(file.OpenedName()), "checked");
}

// Every reader of a lab file (issue 34: dream calibrate f.npy / f.mat / f.npz,
// dream import dream_result.npy / .mat, logs, hashes of uploads).
TEST_F(HostileFilesTest, EveryLabFileReaderRefusesAFifoInsteadOfWaitingOnIt) {
  const calibration::CalibrationInputOptions options;
  for (const char* name : {"f.npy", "f.mat", "f.npz", "run.lcmlog"}) {
    const std::string fifo = Fifo(name);
    EXPECT_THAT(ErrorOf([&] { calibration::ReadCalibrationRun(fifo, options); }), HasSubstr(fifo + ": ")) << name;
    EXPECT_THAT(ErrorOf([&] { calibration::ReadCalibrationRun(fifo, options); }), HasSubstr("FIFO")) << name;
  }
  for (const char* name : {"dream_result.npy", "dream_result.mat"}) {
    const std::string fifo = Fifo(name);
    EXPECT_EQ(ErrorOf([&] { bridge::ReadResultFile(fifo); }), fifo + ": is a FIFO (named pipe), not a file to read");
  }
  const std::string fifo = (dir_ / "f.npy").string();
  EXPECT_THAT(ErrorOf([&] { formats::ReadNpyFile(fifo); }), HasSubstr("is a FIFO"));
  EXPECT_THAT(ErrorOf([&] { formats::ReadMatArray((dir_ / "f.mat").string(), "poses", 1000, 3); }),
              HasSubstr("is a FIFO"));
  EXPECT_THAT(ErrorOf([&] { formats::NpzFile{(dir_ / "f.npz").string()}; }), HasSubstr("is a FIFO"));
  EXPECT_THAT(ErrorOf([&] { formats::Sha256::HexOfFile(fifo); }), HasSubstr("is a FIFO"));
  const std::string log = (dir_ / "run.lcmlog").string();
  EXPECT_EQ(ErrorOf([&] { lcm::LogReader{log}; }),
            log + ": not a regular file (a folder, FIFO or device), so no log file");
  EXPECT_THAT(ErrorOf([&] { run_log::RunLog::Read(log); }), HasSubstr(log + ": not a regular file"));
  EXPECT_THAT(ErrorOf([&] { lcm::LogReader{"/dev/zero"}; }), HasSubstr("not a regular file"));
}

// The attack of issue 34: links planted at PATH.tmp.<pid> (the name the
// writer used to open with O_CREAT | O_TRUNC) in a shared folder; the victim
// behind them must stay as it was.
TEST_F(HostileFilesTest, LinksPlantedAtTemporaryNamesAreNeverWrittenThrough) {
  const fs::path victim = dir_ / "victim.txt";
  std::ofstream(victim) << "the victim's own text";
  const fs::path target = dir_ / "lab.yaml";
  for (pid_t pid = ::getpid() - 5; pid <= ::getpid() + 5; ++pid) {
    fs::create_symlink(victim, target.string() + ".tmp." + std::to_string(pid));
  }
  files::WriteFileAtomically(target.string(), "realism: fitted\n");
  EXPECT_EQ(Contents(victim), "the victim's own text");
  EXPECT_EQ(Contents(target), "realism: fitted\n");
  EXPECT_FALSE(fs::is_symlink(target));
  // A link at the target itself is replaced by the rename, not followed.
  fs::remove(target);
  fs::create_symlink(victim, target);
  files::WriteFileAtomically(target.string(), "second\n", files::Durability::kRenamedOnly);
  EXPECT_EQ(Contents(victim), "the victim's own text");
  EXPECT_FALSE(fs::is_symlink(target));
  EXPECT_EQ(Contents(target), "second\n");
}

TEST_F(HostileFilesTest, TemporaryFilesHaveUnguessableNamesAndVanishUncommitted) {
  const std::string target = (dir_ / "picture.png").string();
  std::string first_name;
  {
    files::TemporaryFile first(target, ".png");
    const files::TemporaryFile second(target, ".png");
    first_name = first.path();
    EXPECT_NE(first.path(), second.path());
    EXPECT_THAT(first.path(), ::testing::StartsWith(target + ".tmp."));
    EXPECT_THAT(first.path(), ::testing::EndsWith(".png"));
    EXPECT_THAT(first.path(), ::testing::Not(HasSubstr(".tmp." + std::to_string(::getpid()))));
    first.Write("half");
  }
  EXPECT_FALSE(fs::exists(first_name));
  EXPECT_FALSE(fs::exists(target));
  EXPECT_THAT(ErrorOf([&] { files::TemporaryFile{(dir_ / "missing" / "x").string()}; }),
              HasSubstr("cannot write " + (dir_ / "missing" / "x").string()));
}

// The run log's .part file: fopen("w") on a planted link would truncate the
// victim; it is made new and exclusively instead.
TEST_F(HostileFilesTest, ALinkPlantedAtTheRunLogsPartFileIsNotWrittenThrough) {
  const fs::path victim = dir_ / "victim.lcmlog";
  std::ofstream(victim) << "someone else's log";
  const fs::path log = dir_ / "run.lcmlog";
  fs::create_symlink(victim, log.string() + ".part");
  {
    node::RunRecorder recorder(log.string());
    const std::string payload = "x";
    recorder.Write("CHANNEL", 1, payload.data(), static_cast<int>(payload.size()));
    recorder.Close();
  }
  EXPECT_EQ(Contents(victim), "someone else's log");
  EXPECT_FALSE(fs::is_symlink(log));
  EXPECT_EQ(lcm::LogReader::ReadAll(log.string()).size(), 1U);
}

TEST(StopTokenTest, FollowsItsFlagOrFunctionAndThrowsStoppedWhenAsked) {
  EXPECT_FALSE(files::StopToken().Requested());
  EXPECT_NO_THROW(files::StopToken().ThrowIfRequested());
  std::atomic<bool> flag{false};
  const files::StopToken token(flag);
  EXPECT_FALSE(token.Requested());
  flag = true;
  EXPECT_TRUE(token.Requested());
  EXPECT_THROW(token.ThrowIfRequested(), files::Stopped);
  int polls = 0;
  const files::StopToken third([&polls] { return ++polls >= 3; });
  EXPECT_FALSE(third.Requested());
  EXPECT_FALSE(third.Requested());
  EXPECT_TRUE(third.Requested());
}

}  // namespace
}  // namespace dream
