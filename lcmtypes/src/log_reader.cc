#include "dream/lcm/log_reader.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>

namespace dream::lcm {
namespace {

// Every LCM log event starts with this sync word (big-endian on disk).
constexpr unsigned char kSyncWord[4] = {0xED, 0xA1, 0xDA, 0x01};
// sync word, event number, timestamp, channel length, data length.
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;

}  // namespace

LogReader::LogReader(std::string path) : path_(std::move(path)) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path_, error)) {
    throw std::runtime_error(path_ + ": no such log file");
  }
  file_size_ = static_cast<int64_t>(std::filesystem::file_size(path_, error));
  if (file_size_ > 0) {
    std::ifstream in(path_, std::ios::binary);
    unsigned char head[4] = {0, 0, 0, 0};
    in.read(reinterpret_cast<char*>(head), 4);
    if (!in || !std::equal(head, head + 4, kSyncWord)) {
      throw std::runtime_error(path_ + ": not an LCM log (it does not start with the LCM event sync word)");
    }
  }
  log_ = std::make_unique<::lcm::LogFile>(path_, "r");
  if (!log_->good()) throw std::runtime_error(path_ + ": cannot open the log");
}

LogReader::~LogReader() = default;

bool LogReader::Next(LogRecord* record) {
  const ::lcm::LogEvent* event = log_->readNextEvent();
  if (event == nullptr) {
    if (bytes_read_ != file_size_) {
      throw std::runtime_error(path_ + ": the log is cut short or damaged after event " + std::to_string(events_) +
                               " (" + std::to_string(file_size_ - bytes_read_) + " bytes at byte " +
                               std::to_string(bytes_read_) + " are not a complete event)");
    }
    return false;
  }
  record->utime = event->timestamp;
  record->channel = event->channel;
  const auto* bytes = static_cast<const uint8_t*>(event->data);
  record->data.assign(bytes, bytes + event->datalen);
  ++events_;
  bytes_read_ += kEventHeaderBytes + static_cast<int64_t>(event->channel.size()) + event->datalen;
  return true;
}

std::vector<LogRecord> LogReader::ReadAll(const std::string& path) {
  LogReader reader(path);
  std::vector<LogRecord> records;
  LogRecord record;
  while (reader.Next(&record)) records.push_back(record);
  return records;
}

}  // namespace dream::lcm
