#pragma once

#include <functional>
#include <utility>

namespace dream::lcm {

/// What LcmInterface::Subscribe returns: the handler stays subscribed while
/// this lives and is unsubscribed when it is destroyed (or Cancel()led), as
/// with Drake's DrakeSubscriptionInterface. So a host that subscribes its own
/// member functions keeps the handles as members and can never be called
/// after it is gone, whatever the bus's life. Outliving the bus is harmless.
class Subscription {
 public:
  Subscription() = default;
  /// `cancel` unsubscribes; it is called once at most.
  explicit Subscription(std::function<void()> cancel) : cancel_(std::move(cancel)) {}
  ~Subscription() { Cancel(); }

  Subscription(Subscription&& other) noexcept : cancel_(std::exchange(other.cancel_, nullptr)) {}
  Subscription& operator=(Subscription&& other) noexcept {
    if (this != &other) {
      Cancel();
      cancel_ = std::exchange(other.cancel_, nullptr);
    }
    return *this;
  }
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;

  /// Unsubscribes now; the handler is not called again.
  void Cancel() {
    if (cancel_) std::exchange(cancel_, nullptr)();
  }
  /// Still subscribed.
  bool active() const { return static_cast<bool>(cancel_); }

 private:
  std::function<void()> cancel_;
};

}  // namespace dream::lcm
