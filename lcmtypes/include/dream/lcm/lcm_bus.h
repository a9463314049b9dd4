#pragma once

#include <deque>
#include <memory>
#include <string>

#include "dream/lcm/lcm_interface.h"

namespace lcm {
class LCM;
class ReceiveBuffer;
}  // namespace lcm

namespace dream::lcm {

/// The real transport: an lcm::LCM opened on a URL chosen by the user.
///
/// Queue capacity is set on every subscription (LCM's default of 30 silently
/// drops messages when a lockstep step delivers one command per robot), and
/// udpm URLs get a 4 MB kernel receive buffer unless the URL sets one
/// (see ResolveLcmUrl()).
class LcmBus final : public LcmInterface {
 public:
  /// Messages queued per subscription before LCM drops the oldest; enough for
  /// several steps of 50 robots' commands and radio traffic.
  static constexpr int kQueueCapacity = 10000;

  /// Opens LCM on `url` as given (use ResolveLcmUrl() to apply defaults).
  /// @throws std::runtime_error naming the URL when LCM cannot open it.
  explicit LcmBus(std::string url);
  ~LcmBus() override;

  LcmBus(const LcmBus&) = delete;
  LcmBus& operator=(const LcmBus&) = delete;

  void Publish(const std::string& channel, const void* data, int size) override;
  void Subscribe(const std::string& channel_regex, RawHandler handler) override;
  int HandleSubscriptions(int timeout_ms) override;
  const std::string& url() const override { return url_; }
  long handler_failures() const override { return handler_failures_; }

 private:
  struct Subscriber {
    LcmBus* owner;
    RawHandler handler;
  };
  static void Dispatch(const ::lcm::ReceiveBuffer* buffer, const std::string& channel,
                       Subscriber* subscriber);

  std::string url_;
  std::unique_ptr<::lcm::LCM> lcm_;
  // deque: subscriber addresses are handed to LCM and must stay stable.
  std::deque<Subscriber> subscribers_;
  long handler_failures_ = 0;
};

}  // namespace dream::lcm
