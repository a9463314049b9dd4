#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <lcm/lcm-cpp.hpp>

#include "dream/lcm/log_reader.h"

namespace dream::lcm {
namespace {

namespace fs = std::filesystem;

std::string TempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("dream_log_reader_" + std::to_string(::getpid()) + "_" + name)).string();
}

void WriteLog(const std::string& path, int events) {
  ::lcm::LogFile log(path, "w");
  for (int i = 0; i < events; ++i) {
    std::string payload = "payload " + std::to_string(i);
    ::lcm::LogEvent event{i, 1000 * i, "CHANNEL_" + std::to_string(i % 2), static_cast<int32_t>(payload.size()),
                          payload.data()};
    log.writeEvent(&event);
  }
}

TEST(LogReaderTest, ReadsEveryEventInOrder) {
  const std::string path = TempPath("ok.lcmlog");
  WriteLog(path, 5);
  const std::vector<LogRecord> records = LogReader::ReadAll(path);
  ASSERT_EQ(records.size(), 5u);
  EXPECT_EQ(records[3].utime, 3000);
  EXPECT_EQ(records[3].channel, "CHANNEL_1");
  EXPECT_EQ(std::string(records[3].data.begin(), records[3].data.end()), "payload 3");
  fs::remove(path);
}

TEST(LogReaderTest, CutShortLogIsAnErrorNamingTheFile) {
  const std::string path = TempPath("cut.lcmlog");
  WriteLog(path, 5);
  fs::resize_file(path, fs::file_size(path) - 4);
  try {
    LogReader::ReadAll(path);
    FAIL() << "a truncated log must not read as complete";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cut short"), std::string::npos) << e.what();
  }
  fs::remove(path);
}

TEST(LogReaderTest, ForeignFileIsRejected) {
  const std::string path = TempPath("foreign.txt");
  std::ofstream(path) << "name: not a log\n";
  try {
    LogReader reader(path);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not an LCM log"), std::string::npos) << e.what();
  }
  fs::remove(path);
  EXPECT_THROW(LogReader(TempPath("missing.lcmlog")), std::runtime_error);
}

}  // namespace
}  // namespace dream::lcm
