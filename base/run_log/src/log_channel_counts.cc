#include "dream/run_log/log_channel_counts.h"

#include <stdexcept>

#include "dream/lcm/log_reader.h"

namespace dream::run_log {

LogChannelCounts LogChannelCounts::Read(const std::string& path) {
  LogChannelCounts counts;
  counts.path_ = path;
  lcm::LogReader reader(counts.path_);
  lcm::LogRecord record;
  while (reader.Next(&record)) {
    if (counts.events_ == 0) counts.first_utime_ = record.utime;
    counts.last_utime_ = record.utime;
    ++counts.events_;
    Channel& channel = counts.channels_[record.channel];
    ++channel.events;
    channel.bytes += static_cast<long>(record.data.size());
  }
  if (counts.events_ == 0) {
    throw std::runtime_error(counts.path_ + ": an empty log (no events): nothing was recorded");
  }
  return counts;
}

}  // namespace dream::run_log
