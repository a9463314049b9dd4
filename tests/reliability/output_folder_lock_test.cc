// OutputFolderLock: a folder written by one process is refused to every
// other, naming the holder; one process may hold it again; a child given
// the holder's descriptor (dream launch's simulator) adopts the lock. The
// other process is util-linux's flock(1), which holds the lock file as
// dream would and writes a holder note into it.
#include "dream/files/output_folder_lock.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "dream/bridge/lab_import.h"
#include "lab_file_samples.h"

namespace dream::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string NewDir(const std::string& name) {
  const std::string dir = SharedLabFileSamples().Scratch(name);
  fs::create_directories(dir);
  return dir;
}

/// flock(1) holding <dir>/.dream.lock with the note "<its command's pid>\nfake holder" until killed.
class OtherHolder {
 public:
  explicit OtherHolder(const std::string& dir) : lock_path_(dir + "/" + files::OutputFolderLock::kFileName) {
    pid_ = ::fork();
    if (pid_ == 0) {
      // -o: only flock itself holds the lock, so killing it releases the lock.
      ::execl("/usr/bin/flock", "flock", "-o", lock_path_.c_str(), "sh", "-c",
              "printf '%s\\nfake holder\\n' $$ > \"$0\"; exec sleep 60", lock_path_.c_str(), nullptr);
      ::_exit(127);
    }
    // Ready once the note is written (the lock is taken before it).
    for (int i = 0;
         i < 1000 && (!fs::exists(lock_path_) || ReadBytes(lock_path_).find("fake holder") == std::string::npos); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  ~OtherHolder() {
    // The command first, so flock reaps it and exits; flock itself if there is no note.
    const std::string sleeper = note_pid();
    ::kill(sleeper.empty() ? pid_ : static_cast<pid_t>(std::stol(sleeper)), SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  /// The pid in the note: the shell's, which flock ran (and which sleep replaced).
  /// (Read before the note is overwritten by a later holder.)
  std::string note_pid() const {
    const std::string note = ReadBytes(lock_path_);
    return note.substr(0, note.find('\n'));
  }

 private:
  std::string lock_path_;
  pid_t pid_ = -1;
};

TEST(OutputFolderLock, OneProcessMayHoldAFolderTwiceAndNamesItselfInTheLockFile) {
  const std::string dir = NewDir("lock_twice");
  files::OutputFolderLock::HoldUntilExit(dir);
  EXPECT_NO_THROW(files::OutputFolderLock::HoldUntilExit(dir + "/"));
  EXPECT_TRUE(files::OutputFolderLock::TryHoldUntilExit(dir));
  const std::string note = ReadBytes(dir + "/" + files::OutputFolderLock::kFileName);
  EXPECT_EQ(note.substr(0, note.find('\n')), std::to_string(::getpid()));
  EXPECT_THAT(note, HasSubstr("file_damage_test"));
  EXPECT_GE(files::OutputFolderLock::DescriptorOf(dir), 0);
}

TEST(OutputFolderLock, AFolderHeldByAnotherProcessIsRefusedNamingItsPidAndCommand) {
  if (!fs::exists("/usr/bin/flock")) GTEST_SKIP() << "needs util-linux's flock";
  const std::string dir = NewDir("lock_other");
  {
    const OtherHolder other(dir);
    ASSERT_FALSE(other.note_pid().empty());
    try {
      files::OutputFolderLock::HoldUntilExit(dir);
      ADD_FAILURE() << "locked a folder another process holds";
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("output folder " + dir + " is being written by pid " + other.note_pid() +
                                      " (fake holder); wait for it to end, or choose another --out"));
    }
    EXPECT_FALSE(files::OutputFolderLock::TryHoldUntilExit(dir));
    EXPECT_EQ(files::OutputFolderLock::DescriptorOf(dir), -1);
    // dream import into it is refused too, before anything is written.
    const LabFileSamples& samples = SharedLabFileSamples();
    const std::string result = samples.Scratch("lock_result.npy");
    WriteBytes(result, samples.results()[0].bytes);
    try {
      bridge::ImportLabRun(result, samples.export_dir(), dir);
      ADD_FAILURE() << "imported into a folder another process holds";
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("is being written by pid " + other.note_pid()));
    }
    EXPECT_FALSE(fs::exists(dir + "/run.lcmlog"));
  }
  // The holder is gone (killed): the kernel released its lock.
  EXPECT_NO_THROW(files::OutputFolderLock::HoldUntilExit(dir));
}

TEST(OutputFolderLock, AnInheritedDescriptorOfTheSameLockFileIsAdopted) {
  const std::string dir = NewDir("lock_inherited");
  const std::string lock_path = dir + "/" + files::OutputFolderLock::kFileName;
  // What dream launch holds (another open file: flock locks belong to it, not to the process).
  const int parent_fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(parent_fd, 0);
  ASSERT_EQ(::flock(parent_fd, LOCK_EX | LOCK_NB), 0);
  // A descriptor of another file is not taken for the lock.
  const std::string other = dir + "/other";
  const int other_fd = ::open(other.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ::setenv(files::OutputFolderLock::kInheritedVariable, std::to_string(other_fd).c_str(), 1);
  EXPECT_FALSE(files::OutputFolderLock::TryHoldUntilExit(dir));
  ::setenv(files::OutputFolderLock::kInheritedVariable, std::to_string(parent_fd).c_str(), 1);
  EXPECT_NO_THROW(files::OutputFolderLock::HoldUntilExit(dir));
  EXPECT_EQ(files::OutputFolderLock::DescriptorOf(dir), parent_fd);
  ::unsetenv(files::OutputFolderLock::kInheritedVariable);
  ::close(other_fd);
}

}  // namespace
}  // namespace dream::testing
