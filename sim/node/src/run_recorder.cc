#include "dream/node/run_recorder.h"

#include <fcntl.h>
#include <stdio_ext.h>  // __fpurge (glibc)
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>
#include <utility>

namespace dream::node {
namespace {

// An LCM log event is a fixed header (magic, event number, timestamp, channel
// length, data length: 4 + 8 + 8 + 4 + 4 bytes) followed by channel and data.
constexpr int64_t kEventHeaderBytes = 28;

std::string ErrorText(int error_number) { return error_number != 0 ? std::strerror(error_number) : "unknown error"; }

}  // namespace

RunRecorder::RunRecorder(std::string path, int flush_interval_events)
    : path_(std::move(path)), part_path_(path_ + ".part"), flush_interval_events_(flush_interval_events) {
  // The part file is made new and exclusively (O_EXCL | O_NOFOLLOW), then
  // opened by LogFile for appending and checked to be that very file: a link
  // planted at the .part name in a shared folder is removed, never written
  // through (LogFile's fopen would follow it and truncate what it names).
  ::unlink(part_path_.c_str());  // a killed run's part, or something planted there
  const int created = ::open(part_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (created < 0) {
    throw std::runtime_error("cannot create the run log " + part_path_ + ": " + ErrorText(errno) +
                             " (does the folder exist and is it writable?)");
  }
  struct stat made {};
  const bool made_known = ::fstat(created, &made) == 0;
  log_ = std::make_unique<::lcm::LogFile>(part_path_, "a");
  ::close(created);
  if (!log_->good()) {
    throw std::runtime_error("cannot create the run log " + part_path_ + ": does the folder exist and is it writable?");
  }
  struct stat file_status {};
  if (!made_known || ::fstat(fileno(log_->getFilePtr()), &file_status) != 0 || file_status.st_dev != made.st_dev ||
      file_status.st_ino != made.st_ino) {
    log_.reset();
    throw std::runtime_error("cannot create the run log " + part_path_ +
                             ": the file was replaced while it was opened (by another process in a shared folder?)");
  }
  part_device_ = file_status.st_dev;
  part_inode_ = file_status.st_ino;
}

bool RunRecorder::PartPathHoldsThisLog() const {
  struct stat at_path {};
  return ::stat(part_path_.c_str(), &at_path) == 0 && at_path.st_dev == part_device_ && at_path.st_ino == part_inode_;
}

RunRecorder::~RunRecorder() {
  try {
    Close();
  } catch (...) {
    // Destructors must not throw; failure() still tells what went wrong.
  }
}

void RunRecorder::RewriteChannel(std::string channel, Rewrite rewrite) {
  rewritten_channel_ = std::move(channel);
  rewrite_ = std::move(rewrite);
}

void RunRecorder::Write(const std::string& channel, int64_t utime, const void* data, int size) {
  if (rewrite_ && !rewriting_ && channel == rewritten_channel_) {
    rewriting_ = true;
    try {
      rewrite_(utime, data, size);
    } catch (...) {
      rewriting_ = false;
      throw;
    }
    rewriting_ = false;
    return;
  }
  if (!log_) throw std::logic_error("RunRecorder::Write after Close on " + path_);
  if (failed()) throw std::runtime_error(failure_);
  ::lcm::LogEvent event;
  event.eventnum = events_written_;
  event.timestamp = utime;
  event.channel = channel;
  event.datalen = size;
  event.data = const_cast<void*>(data);  // LogFile only reads it.
  errno = 0;
  if (log_->writeEvent(&event) != 0) Fail("writing", errno);
  ++events_written_;
  bytes_written_ += kEventHeaderBytes + static_cast<int64_t>(channel.size()) + size;
  unflushed_event_ends_.push_back(bytes_written_);
  if (events_written_ % flush_interval_events_ == 0) {
    if (std::fflush(log_->getFilePtr()) != 0) Fail("writing", errno);
    events_flushed_ = events_written_;
    bytes_flushed_ = bytes_written_;
    unflushed_event_ends_.clear();
  }
}

void RunRecorder::Flush() {
  if (!log_) return;
  if (failed()) throw std::runtime_error(failure_);
  FILE* file = log_->getFilePtr();
  if (std::fflush(file) != 0) Fail("writing", errno);
  events_flushed_ = events_written_;
  bytes_flushed_ = bytes_written_;
  unflushed_event_ends_.clear();
  if (::fsync(fileno(file)) != 0) Fail("syncing", errno);
}

void RunRecorder::Fail(const std::string& action, int error_number) {
  FILE* file = log_->getFilePtr();
  const int fd = fileno(file);
  // What stdio still buffers would land after the cut (or in the middle of a
  // half-written event) when the file is closed: drop it.
  __fpurge(file);
  // The disk holds whatever prefix of the buffered events write() got
  // through; keep every event that is wholly in it.
  int64_t keep_bytes = bytes_flushed_;
  int64_t keep_events = events_flushed_;
  struct stat file_status {};
  if (::fstat(fd, &file_status) == 0) {
    for (int64_t end : unflushed_event_ends_) {
      if (end > file_status.st_size) break;
      keep_bytes = end;
      ++keep_events;
    }
  }
  failure_ = action + " " + part_path_ + " failed: " + ErrorText(error_number);
  if (::ftruncate(fd, static_cast<off_t>(keep_bytes)) == 0) {
    failure_ += " (the log keeps the " + std::to_string(keep_events) + " whole events before it)";
  } else {
    cut_back_failed_ = true;
    failure_ += "; cutting it back to its last whole event failed too: " + ErrorText(errno);
  }
  events_written_ = keep_events;
  bytes_written_ = keep_bytes;
  unflushed_event_ends_.clear();
  throw std::runtime_error(failure_);
}

void RunRecorder::Close() {
  if (!log_) return;
  std::string flush_error;
  if (!failed()) {
    try {
      Flush();
    } catch (const std::runtime_error& e) {
      flush_error = e.what();
    }
  }
  log_.reset();  // fclose writes nothing more: stdio's buffer is flushed or purged
  if (cut_back_failed_) throw std::runtime_error(failure_ + "; the log stays at " + part_path_);
  // Renamed by the file it is, not by its name: when the folder was removed
  // and made again while the run went on, the path may hold another run's log.
  if (!PartPathHoldsThisLog()) {
    part_replaced_ = true;
    throw std::runtime_error("the run log " + part_path_ +
                             " is no longer the file this run wrote (its folder was removed, or the file moved or "
                             "replaced, while the run went on): not renamed to " +
                             path_ + ", so whatever is there now is left alone");
  }
  if (std::rename(part_path_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot rename " + part_path_ + " to " + path_ + ": " + ErrorText(errno));
  }
  if (!flush_error.empty()) throw std::runtime_error(flush_error);
}

}  // namespace dream::node
