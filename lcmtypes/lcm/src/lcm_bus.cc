#include "dream/lcm/lcm_bus.h"

#include <spdlog/spdlog.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <lcm/lcm-cpp.hpp>
#include <regex>
#include <stdexcept>

#include "dream/lcm/channel_prefix_filter.h"

namespace dream::lcm {

LcmBus::LcmBus(std::string url)
    : url_(std::move(url)), lcm_(std::make_unique<::lcm::LCM>(url_)), own_queue_(url_.rfind("memq://", 0) == 0) {
  if (!lcm_->good()) {
    throw std::runtime_error("cannot open LCM on '" + url_ +
                             "': check the URL (memq://, udpm://239.255.76.67:7667?ttl=0) and, for "
                             "udpm, that multicast is routed (ip route add 224.0.0.0/4 dev lo)");
  }
  // Subscribing starts udpm's receive thread and its self test: do it now, on
  // a channel nobody publishes, so what other processes' self tests left
  // queued is gone before any handler subscribes.
  subscription_ = lcm_->subscribeFunction(kStartUpChannel, &LcmBus::Dispatch, this);
  if (subscription_ == nullptr) throw std::runtime_error("cannot subscribe to LCM on " + url_);
  receive_fd_ = receive_socket_.Find();
  DiscardStartUpLeftovers();
}

void LcmBus::DiscardStartUpLeftovers() {
  // Packets queued during the self test were counted for no live subscription;
  // taking them off the queue now, while no subscription matches them, keeps
  // LCM's count in line with its queue. Bounded, in case the bus is busy.
  for (int i = 0; i < kQueueCapacity && lcm_->handleTimeout(0) > 0; ++i) {
  }
}

void LcmBus::ResubscribeForAllHandlers() {
  // One LCM subscription whose regex is the union of the handlers' ones, so
  // LCM drops traffic nobody here wants in its receive thread (an agent would
  // otherwise wake up for every other robot's command).
  std::string alternatives;
  for (const Subscriber& subscriber : subscribers_) {
    if (!subscriber.active) continue;
    alternatives += (alternatives.empty() ? "" : "|") + ("(?:" + subscriber.channel_regex_text + ")");
  }
  if (alternatives.empty()) alternatives = kStartUpChannel;  // nobody listens: LCM drops everything
  ::lcm::Subscription* replacement = lcm_->subscribeFunction("(?:" + alternatives + ")", &LcmBus::Dispatch, this);
  if (replacement == nullptr) throw std::runtime_error("cannot subscribe to '" + alternatives + "' on " + url_);
  replacement->setQueueCapacity(kQueueCapacity);
  lcm_->unsubscribe(subscription_);
  subscription_ = replacement;
  UpdateKernelFilter();
}

void LcmBus::UpdateKernelFilter() {
  if (receive_fd_ < 0) return;
  std::vector<std::string> prefixes;
  for (const Subscriber& subscriber : subscribers_) {
    if (subscriber.active) prefixes.push_back(ChannelPrefixFilter::LiteralPrefix(subscriber.channel_regex_text));
  }
  // Nobody listens: LCM drops everything anyway; the start-up channel's prefix lets nothing real through.
  if (prefixes.empty()) prefixes.push_back(kStartUpChannel);
  const ChannelPrefixFilter filter(prefixes);
  kernel_filter_prefixes_.clear();
  if (!kernel_filter_allowed_) {
    ChannelPrefixFilter::RemoveFrom(receive_fd_);
    return;
  }
  if (!filter.ApplyTo(receive_fd_)) {
    // Only a cost: LCM's receive thread drops what the kernel did not.
    spdlog::debug("{}: the kernel refused the channel filter ({}); every datagram goes to LCM", url_,
                  std::strerror(errno));
    ChannelPrefixFilter::RemoveFrom(receive_fd_);
    return;
  }
  if (!filter.passes_everything()) kernel_filter_prefixes_ = prefixes;
}

_lcm_t* LcmBus::c_handle() {
  const std::lock_guard<std::mutex> lock(queue_mutex_);
  if (own_queue_) PassOwnQueueToLcm();
  // The other host's subscriptions are not the bus's: the kernel must not drop their channels.
  kernel_filter_allowed_ = false;
  UpdateKernelFilter();
  return lcm_->getUnderlyingLCM();
}

void LcmBus::PassOwnQueueToLcm() {
  // Called with queue_mutex_ held. LCM's memq publish only queues (it never
  // calls a handler), so holding the lock here cannot deadlock.
  own_queue_ = false;
  for (const Queued& message : queue_) {
    lcm_->publish(message.channel, message.bytes.data(), static_cast<unsigned int>(message.bytes.size()));
  }
  queue_.clear();
}

long LcmBus::queue_overflows() const {
  const std::lock_guard<std::mutex> lock(queue_mutex_);
  return queue_overflows_;
}

LcmBus::~LcmBus() = default;

void LcmBus::Publish(const std::string& channel, const void* data, int size) {
  {
    std::unique_lock<std::mutex> lock(queue_mutex_);
    if (own_queue_) {
      // As LCM's memq: a message no handler wants now is dropped, a full queue drops new ones.
      std::vector<size_t> uncached;
      if (RouteOf(channel, &uncached).empty()) return;
      if (queue_.size() >= static_cast<size_t>(kQueueCapacity)) {
        if (queue_overflows_++ % 1000 == 0) {
          spdlog::warn("{}: queue full ({} messages): dropped a message on {} (#{})", url_, kQueueCapacity, channel,
                       queue_overflows_);
        }
        return;
      }
      const auto* bytes = static_cast<const uint8_t*>(data);
      queue_.push_back(Queued{channel, std::vector<uint8_t>(bytes, bytes + size)});
      lock.unlock();
      queue_filled_.notify_one();
      return;
    }
  }
  if (lcm_->publish(channel, data, static_cast<unsigned int>(size)) != 0) {
    throw std::runtime_error("LCM refused to publish " + std::to_string(size) + " bytes on " + channel + " (url " +
                             url_ + ")");
  }
}

Subscription LcmBus::Subscribe(const std::string& channel_regex, RawHandler handler) {
  std::regex regex;
  try {
    regex = std::regex(channel_regex, std::regex::ECMAScript | std::regex::optimize);
  } catch (const std::regex_error& e) {
    throw std::invalid_argument("cannot subscribe to '" + channel_regex + "': not a valid regex (" + e.what() + ")");
  }
  const std::lock_guard<std::mutex> lock(queue_mutex_);
  subscribers_.push_back(Subscriber{std::move(regex), channel_regex, std::move(handler)});
  try {
    ResubscribeForAllHandlers();
  } catch (...) {
    subscribers_.pop_back();  // the bus stays as it was
    throw;
  }
  // Extend the known routes in place (never rebuild them): a handler may be
  // subscribing from inside Deliver, which holds a reference to one of them.
  const size_t added = subscribers_.size() - 1;
  for (auto& [channel, targets] : routes_) {
    if (std::regex_match(channel, subscribers_[added].channel_regex)) targets.push_back(added);
  }
  return Subscription([bus = std::weak_ptr<LcmBus*>(self_), added] {
    if (const std::shared_ptr<LcmBus*> alive = bus.lock()) (*alive)->Unsubscribe(added);
  });
}

void LcmBus::Unsubscribe(size_t index) {
  const std::lock_guard<std::mutex> lock(queue_mutex_);
  subscribers_[index].active = false;
  // Its captures die now, unless a handler is running (it may be this one).
  if (delivering_ == 0) {
    subscribers_[index].handler = nullptr;
  } else {
    unsubscribed_while_delivering_.push_back(index);
  }
  ResubscribeForAllHandlers();
}

int LcmBus::HandleSubscriptions(int timeout_ms) {
  bool own_queue = false;
  {
    const std::lock_guard<std::mutex> lock(queue_mutex_);
    own_queue = own_queue_;
  }
  if (own_queue) return HandleOwnQueue(timeout_ms);
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

void LcmBus::Dispatch(const ::lcm::ReceiveBuffer* buffer, const std::string& channel, LcmBus* bus) {
  bus->Deliver(channel, buffer->data, static_cast<int>(buffer->data_size));
}

std::vector<size_t> LcmBus::MatchSubscribers(const std::string& channel) const {
  std::vector<size_t> matching;
  for (size_t i = 0; i < subscribers_.size(); ++i) {
    if (subscribers_[i].active && std::regex_match(channel, subscribers_[i].channel_regex)) matching.push_back(i);
  }
  return matching;
}

int LcmBus::HandleOwnQueue(int timeout_ms) {
  Queued message;
  {
    std::unique_lock<std::mutex> lock(queue_mutex_);
    if (queue_.empty() && timeout_ms > 0) {
      queue_filled_.wait_for(lock, std::chrono::milliseconds(timeout_ms), [this] { return !queue_.empty(); });
    }
    if (queue_.empty()) return 0;
    message = std::move(queue_.front());
    queue_.pop_front();
  }
  Deliver(message.channel, message.bytes.data(), static_cast<int>(message.bytes.size()));
  return 1;
}

const std::vector<size_t>& LcmBus::RouteOf(const std::string& channel, std::vector<size_t>* uncached) {
  // Called with queue_mutex_ held.
  auto found = routes_.find(channel);
  if (found == routes_.end() && routes_.size() < kMaxRoutedChannels) {
    found = routes_.emplace(channel, MatchSubscribers(channel)).first;
  }
  if (found != routes_.end()) return found->second;
  // Past the cap (made-up channel names) the route is matched per message and not kept.
  *uncached = MatchSubscribers(channel);
  return *uncached;
}

void LcmBus::Deliver(const std::string& channel, const void* data, int size) {
  // By index up to the count at arrival, as LCM does: a handler that
  // subscribes appends to this route, and the newcomer starts with the next
  // message. (unordered_map keeps references to its values valid.) The lock
  // covers finding the route, not the handlers, which may publish or subscribe.
  std::vector<size_t> uncached;
  const std::vector<size_t>* targets = nullptr;
  size_t count = 0;
  {
    const std::lock_guard<std::mutex> lock(queue_mutex_);
    targets = &RouteOf(channel, &uncached);
    count = targets->size();
    if (targets == &uncached) ++uncached_deliveries_;
    ++delivering_;
  }
  for (size_t k = 0; k < count; ++k) {
    const size_t index = (*targets)[k];
    {
      const std::lock_guard<std::mutex> lock(queue_mutex_);
      if (!subscribers_[index].active) continue;  // unsubscribed, perhaps by an earlier handler of this message
    }
    // Nothing may propagate into LCM's C code: log, count, carry on.
    try {
      subscribers_[index].handler(channel, data, size);
    } catch (const std::exception& e) {
      ++handler_failures_;
      spdlog::error("handler for channel {} failed: {}", channel, e.what());
    } catch (...) {
      ++handler_failures_;
      spdlog::error("handler for channel {} failed with an unknown exception", channel);
    }
  }
  const std::lock_guard<std::mutex> lock(queue_mutex_);
  if (--delivering_ == 0) {
    for (const size_t index : unsubscribed_while_delivering_) subscribers_[index].handler = nullptr;
    unsubscribed_while_delivering_.clear();
  }
}

}  // namespace dream::lcm
