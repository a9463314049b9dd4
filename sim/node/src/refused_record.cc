#include "dream/node/refused_record.h"

#include <spdlog/spdlog.h>

#include <stdexcept>
#include <utility>

#include "dream/node/run_recorder.h"

namespace dream::node {

RefusedRecord::RefusedRecord(std::string path) : path_(std::move(path)) {}

RefusedRecord::~RefusedRecord() { Close(); }

void RefusedRecord::Add(const std::string& channel, int64_t step, int64_t utime, const void* data, int size) {
  // Channel names come from the network: past the cap they share one entry.
  auto entry = per_channel_.find(channel);
  if (entry == per_channel_.end()) {
    const size_t named = per_channel_.size() - per_channel_.count(kOtherChannels);
    entry = per_channel_.emplace(named < kMaxChannels ? channel : kOtherChannels, Channel{0, step}).first;
  }
  ++entry->second.count;
  ++total_;
  if (!failure_.empty() || events_kept_ >= kMaxEvents || size < 0 || bytes_kept_ + size > kMaxBytes) return;
  try {
    if (log_ == nullptr) log_ = std::make_unique<RunRecorder>(path_);
    log_->Write(channel, utime, data, size);
    ++events_kept_;
    bytes_kept_ += size;
  } catch (const std::exception& e) {
    failure_ = e.what();
    spdlog::warn("the record of refused messages stops: {}", failure_);
  }
}

void RefusedRecord::Close() {
  if (log_ == nullptr) return;
  try {
    log_->Close();
  } catch (const std::exception& e) {
    if (failure_.empty()) failure_ = e.what();
  }
  events_kept_ = log_->events_written();
  log_.reset();
}

}  // namespace dream::node
