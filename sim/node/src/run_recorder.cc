#include "dream/sim/run_recorder.h"

#include <unistd.h>

#include <cstdio>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>

namespace dream::sim {

RunRecorder::RunRecorder(std::string path, int flush_interval_events)
    : path_(std::move(path)), part_path_(path_ + ".part"), flush_interval_events_(flush_interval_events) {
  log_ = std::make_unique<::lcm::LogFile>(part_path_, "w");
  if (!log_->good()) {
    throw std::runtime_error("cannot create the run log " + part_path_ +
                             ": does the folder exist and is it writable?");
  }
}

RunRecorder::~RunRecorder() {
  try {
    Close();
  } catch (...) {
    // Destructors must not throw; Close() already reported nothing usable.
  }
}

void RunRecorder::Write(const std::string& channel, int64_t utime, const void* data, int size) {
  if (!log_) throw std::logic_error("RunRecorder::Write after Close on " + path_);
  ::lcm::LogEvent event;
  event.eventnum = events_written_;
  event.timestamp = utime;
  event.channel = channel;
  event.datalen = size;
  event.data = const_cast<void*>(data);  // LogFile only reads it.
  if (log_->writeEvent(&event) != 0) {
    throw std::runtime_error("cannot write to the run log " + part_path_ + " (disk full?)");
  }
  ++events_written_;
  if (events_written_ % flush_interval_events_ == 0) std::fflush(log_->getFilePtr());
}

void RunRecorder::Close() {
  if (!log_) return;
  FILE* file = log_->getFilePtr();
  const bool flushed = std::fflush(file) == 0 && ::fsync(fileno(file)) == 0;
  log_.reset();
  if (!flushed) throw std::runtime_error("cannot flush the run log " + part_path_);
  if (std::rename(part_path_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot rename " + part_path_ + " to " + path_);
  }
}

}  // namespace dream::sim
