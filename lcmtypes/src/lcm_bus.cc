#include "dream/lcm/lcm_bus.h"

#include <spdlog/spdlog.h>

#include <cerrno>
#include <exception>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>

namespace dream::lcm {

LcmBus::LcmBus(std::string url) : url_(std::move(url)), lcm_(std::make_unique<::lcm::LCM>(url_)) {
  if (!lcm_->good()) {
    throw std::runtime_error("cannot open LCM on '" + url_ +
                             "': check the URL (memq://, udpm://239.255.76.67:7667?ttl=0) and, for "
                             "udpm, that multicast is routed (ip route add 224.0.0.0/4 dev lo)");
  }
}

LcmBus::~LcmBus() = default;

void LcmBus::Publish(const std::string& channel, const void* data, int size) {
  if (lcm_->publish(channel, data, static_cast<unsigned int>(size)) != 0) {
    throw std::runtime_error("LCM refused to publish " + std::to_string(size) + " bytes on " +
                             channel + " (url " + url_ + ")");
  }
}

void LcmBus::Subscribe(const std::string& channel_regex, RawHandler handler) {
  subscribers_.push_back(Subscriber{this, std::move(handler)});
  ::lcm::Subscription* subscription =
      lcm_->subscribeFunction(channel_regex, &LcmBus::Dispatch, &subscribers_.back());
  if (subscription == nullptr) {
    subscribers_.pop_back();
    throw std::runtime_error("cannot subscribe to '" + channel_regex + "' on " + url_);
  }
  subscription->setQueueCapacity(kQueueCapacity);
}

int LcmBus::HandleSubscriptions(int timeout_ms) {
  errno = 0;
  const int handled = lcm_->handleTimeout(timeout_ms);
  // A signal (Ctrl-C) interrupting the wait is not a failure: the caller
  // checks its stop flag and ends cleanly.
  if (handled < 0 && errno == EINTR) return 0;
  if (handled < 0) {
    throw std::runtime_error("LCM failed while receiving on " + url_);
  }
  return handled;
}

void LcmBus::Dispatch(const ::lcm::ReceiveBuffer* buffer, const std::string& channel,
                      Subscriber* subscriber) {
  // Nothing may propagate into LCM's C code: log, count, carry on.
  try {
    subscriber->handler(channel, buffer->data, static_cast<int>(buffer->data_size));
  } catch (const std::exception& e) {
    ++subscriber->owner->handler_failures_;
    spdlog::error("handler for channel {} failed: {}", channel, e.what());
  } catch (...) {
    ++subscriber->owner->handler_failures_;
    spdlog::error("handler for channel {} failed with an unknown exception", channel);
  }
}

}  // namespace dream::lcm
