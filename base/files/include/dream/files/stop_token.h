#pragma once

#include <atomic>
#include <functional>
#include <utility>

namespace dream::files {

/// Whether the user asked the command to stop (Ctrl-C, SIGTERM), for the
/// long computations that write outputs at their end (calibrate's fit, a
/// render, a sweep's table): they poll it often enough to stop within a
/// fraction of a second and then throw Stopped, so nothing half-computed is
/// written. The command line's signal handler sets the flag behind it; a test
/// gives a function (stop at the Nth poll). The default token never stops.
class StopToken {
 public:
  StopToken() = default;
  /// Follows `flag`, which must outlive the token (a signal handler's flag).
  explicit StopToken(const std::atomic<bool>& flag) : asked_([&flag] { return flag.load(); }) {}
  explicit StopToken(std::function<bool()> asked) : asked_(std::move(asked)) {}

  bool Requested() const { return asked_ && asked_(); }
  /// @throws Stopped when Requested().
  void ThrowIfRequested() const;

 private:
  std::function<bool()> asked_;
};

}  // namespace dream::files
