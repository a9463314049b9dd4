#pragma once

#include <chrono>
#include <functional>
#include <utility>

namespace dream::node {

/// Where SimNode reads the time: the steady clock in every run. A test gives
/// a clock of its own (for example one that moves only while the bus is
/// quiet), so that a loaded machine cannot make an answering agent late and
/// a test never depends on how fast its machine is.
class NodeClock {
 public:
  using TimePoint = std::chrono::steady_clock::time_point;
  using Now = std::function<TimePoint()>;

  NodeClock() : now_([] { return std::chrono::steady_clock::now(); }) {}
  explicit NodeClock(Now now) : now_(std::move(now)) {}

  TimePoint now() const { return now_(); }

 private:
  Now now_;
};

}  // namespace dream::node
